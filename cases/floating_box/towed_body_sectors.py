#!/usr/bin/env python3
"""Where a towed cylinder's resistance comes from, from two `moorsph_towed_body ... sectors=N`
outputs: the same tow moving up (+U) and moving down (-U).

The part that reverses with the motion, (F(-U) - F(+U))/2, cancels the held load and its
swing (docs/accuracy-cost.md, "Light cylinder released under water"). Here it is split over
the N sectors of the surface, counted from the direction of motion (0 = front), with each
run's held mean (before the start) subtracted:
  - the wall law's force from each sector (the program's reactions), as a resistance;
  - the odd part of the mean pressure of the water within 1.5 dx of the surface in each
    sector (up and down averaged: the hydrostatic change with depth cancels);
  - that pressure integrated round the body, sum over sectors of p R (sin b - sin a), the
    resistance the water's own pressure would give.
Means over the windows given (ms after the start of the motion).

  towed_body_sectors.py UP DOWN [--radius 0.05] [--windows 30,80,130,180,250]
"""
import argparse

import numpy as np

FIXED_COLUMNS = 6  # s, travel, speed, F, F_pf, R


def read(path):
    data = np.loadtxt(path, comments="#")
    sectors = (data.shape[1] - FIXED_COLUMNS) // 2
    if sectors < 2 or data.shape[1] != FIXED_COLUMNS + 2 * sectors:
        raise SystemExit(f"{path}: no sector columns (run moorsph_towed_body with sectors=N)")
    return data, sectors


def odd_parts(up, down, n):
    """Per sector, counted from the motion: the resistance from the wall law and the odd pressure."""
    held = up[:, 0] < 0.0
    force_up, force_down = up[:, FIXED_COLUMNS:FIXED_COLUMNS + n], down[:, FIXED_COLUMNS:FIXED_COLUMNS + n]
    p_up, p_down = up[:, FIXED_COLUMNS + n:], down[:, FIXED_COLUMNS + n:]
    # Sector j of the down run (counted from +y) is sector j - n/2 counted from its motion.
    resistance = (-(force_up - force_up[held].mean(axis=0))
                  + np.roll(force_down - force_down[held].mean(axis=0), -n // 2, axis=1)) / 2.0
    pressure = ((p_up - p_up[held].mean(axis=0)) + np.roll(p_down - p_down[held].mean(axis=0), -n // 2, axis=1)) / 2.0
    return resistance, pressure


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("up")
    ap.add_argument("down")
    ap.add_argument("--radius", type=float, default=0.05)
    ap.add_argument("--windows", default="30,80,130,180,250")
    a = ap.parse_args()
    up, n = read(a.up)
    down, n_down = read(a.down)
    if n_down != n or n % 2:
        raise SystemExit("both runs need the same, even, number of sectors")
    rows = min(len(up), len(down))
    up, down = up[:rows], down[:rows]
    resistance, pressure = odd_parts(up, down, n)
    edges = np.deg2rad(np.arange(n + 1) * 360.0 / n - 180.0 / n)
    width = a.radius * (np.sin(edges[1:]) - np.sin(edges[:-1]))  # across the motion, signed
    s = up[:, 0]
    bounds = [float(x) for x in a.windows.split(",")]
    names = ["front" if j == 0 else "back" if j == n // 2 else f"{360 * j // n}" for j in range(n)]
    print("window [ms]   what            " + " ".join(f"{x:>8s}" for x in names) + "      sum")
    spans = list(zip(bounds[:-1], bounds[1:])) + [(bounds[0], bounds[-1])]
    for lo, hi in spans:
        chosen = (s >= lo) & (s < hi)
        if not chosen.any():
            continue
        f = resistance[chosen].mean(axis=0)
        p = pressure[chosen].mean(axis=0)
        print(f"{lo:4.0f}-{hi:4.0f}    wall law [N/m] " + " ".join(f"{x:8.2f}" for x in f) + f" {f.sum():8.2f}")
        print(f"{'':10s}    water p [Pa]   " + " ".join(f"{x:8.0f}" for x in p)
              + f" {(p * width).sum():8.2f}  (integrated, N/m)")


if __name__ == "__main__":
    main()
