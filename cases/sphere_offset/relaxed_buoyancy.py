#!/usr/bin/env python3
"""A held sphere's buoyancy while the water next to it re-packs (docs/validation/sphere-offset.md).

For each run directory: the mean of wrench_<body>/Fy over consecutive windows against
Archimedes, and the plateau of an exponential relaxation v_inf + A exp(-(t - from)/tau)
fitted from --from to the end: the same fit as `moorsph study --metric relaxed_level`
(app/study/metrics.cpp), so a run restarted to a later end time can be read without
re-running the study. Needs numpy and h5py.

  relaxed_buoyancy.py [--body sphere] [--archimedes 42.970] [--from 1.0] [--window 0.5] RUN_DIR...
"""
import argparse
import math

import h5py
import numpy as np


def trapezoid_weights(t):
    w = np.zeros_like(t)
    w[1:] += 0.5 * np.diff(t)
    w[:-1] += 0.5 * np.diff(t)
    return w


def fit_for_tau(t, v, w, tau):
    e = np.exp(-(t - t[0]) / tau)
    sw, se, see = w.sum(), (w * e).sum(), (w * e * e).sum()
    sv, sev = (w * v).sum(), (w * e * v).sum()
    det = sw * see - se * se
    amplitude = (sw * sev - se * sv) / det if det > 0 else 0.0
    level = (sv - amplitude * se) / sw
    return level, amplitude, float((w * (v - level - amplitude * e) ** 2).sum())


def relaxed_level(t, v):
    """(level, tau, note): the plateau, its time constant, and why it is not trusted."""
    w = trapezoid_weights(t)
    span = t[-1] - t[0]
    grid = np.exp(np.linspace(math.log(span / 200), math.log(20 * span), 121))
    errors = [fit_for_tau(t, v, w, tau)[2] for tau in grid]
    k = int(np.argmin(errors))
    a, b = math.log(grid[max(k - 1, 0)]), math.log(grid[min(k + 1, len(grid) - 1)])
    g = 0.5 * (math.sqrt(5) - 1)
    for _ in range(60):
        x1, x2 = b - g * (b - a), a + g * (b - a)
        if fit_for_tau(t, v, w, math.exp(x1))[2] < fit_for_tau(t, v, w, math.exp(x2))[2]:
            b = x2
        else:
            a = x1
    tau = math.exp(0.5 * (a + b))
    level, _, err = fit_for_tau(t, v, w, tau)
    mean = (w * v).sum() / w.sum()
    if err >= 0.99 * (w * (v - mean) ** 2).sum():
        return mean, float("inf"), "steady"
    if tau > span / math.log(2):
        return level, tau, "not half-way: run longer"
    return level, tau, ""


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("runs", nargs="+")
    ap.add_argument("--body", default="sphere")
    ap.add_argument("--archimedes", type=float, default=42.970, help="[N]")
    ap.add_argument("--from", dest="start", type=float, default=1.0, help="fit from [s]")
    ap.add_argument("--window", type=float, default=0.5, help="window of the means [s]")
    args = ap.parse_args()
    for run in args.runs:
        with h5py.File(f"{run}/series.h5", "r") as f:
            t = f[f"wrench_{args.body}/time"][:]
            fy = f[f"wrench_{args.body}/Fy"][:]
        err = fy / args.archimedes - 1
        means = []
        a = args.window
        while a + args.window <= t[-1] + 1e-9:
            m = (t >= a) & (t < a + args.window)
            means.append(f"{a:.1f}-{a + args.window:.1f} s {100 * err[m].mean():+.2f}%")
            a += args.window
        keep = t >= args.start
        level, tau, note = relaxed_level(t[keep], err[keep])
        print(f"{run}: to {t[-1]:.2f} s")
        print("  window means: " + ", ".join(means))
        print(f"  relaxed level from {args.start} s: {100 * level:+.2f}% (tau {tau:.2f} s) {note}")


if __name__ == "__main__":
    main()
