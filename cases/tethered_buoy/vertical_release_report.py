#!/usr/bin/env python3
"""Heave of the vertical release (cases/tethered_buoy/vertical_release_3d.yaml) about the
run's own still level.

The scene fills the water to 0.5 m around the buoy pulled fully under, so once the buoy
floats half submerged the level is lower by (water kept out of the sphere and its dx/2
margin at the start - the half sphere at rest) / tank area: 11 mm at dx = 25 mm. Mass is
conserved, so the still level follows from the particle count alone:

    L = (N dx^3 + (2/3) pi R^3) / (tank length x width)

(what the tethered-buoy program does before it places the buoy). Heights here are the
centroid's above L. Prints per run: L, the first overshoot (largest y - L in the first
second after release) and its time, the first trough after it, the time between the
first two maxima, and the mean over the last 0.3 s.

    vertical_release_report.py RUN [RUN ...] [--release 0.3]
"""
import argparse
import re

import h5py
import numpy as np
import yaml

RADIUS = 0.1015


def still_level(run):
    """The still level with the buoy half submerged, from the run's particle count."""
    with open(run + "/scene.resolved.yaml") as f:
        scene = yaml.safe_load(f)
    dx = scene["resolution"]["dx"]
    tank = next(g["tank"] for g in scene["geometry"] if "tank" in g)
    area = (tank["upper"][0] - tank["lower"][0]) * (tank["upper"][2] - tank["lower"][2])
    with open(run + "/log.txt") as f:
        count = int(re.search(r"(\d+) fluid,", f.read()).group(1))
    return dx, count, (count * dx ** 3 + 2.0 / 3.0 * np.pi * RADIUS ** 3) / area


def maxima(y):
    """Indices of the local maxima of y (a plateau counts once)."""
    dy = np.sign(np.diff(y))
    turns = np.flatnonzero(dy[1:] != dy[:-1]) + 1
    return [i for i in turns if dy[i - 1] > 0]


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("runs", nargs="+")
    p.add_argument("--release", type=float, default=0.3, help="release time [s]")
    a = p.parse_args()
    print("run  dx [m]  fluid  L [m]  overshoot [mm] (t after release [s])  trough [mm] (t)  "
          "peak-to-peak [s]  last 0.3 s mean [mm]")
    for run in a.runs:
        dx, count, level = still_level(run)
        with h5py.File(run + "/series.h5", "r") as f:
            t, y = f["body_buoy/time"][:], f["body_buoy/y"][:] - level
        free = t >= a.release
        t, y = t[free] - a.release, y[free]
        first = np.argmax(np.where(t <= 1.0, y, -np.inf))
        after = (t > t[first]) & (t <= t[first] + 0.5)
        trough = np.flatnonzero(after)[np.argmin(y[after])] if after.any() else None
        later = [i for i in maxima(y) if t[i] > t[first] + 0.2]
        period = "%.3f" % (t[later[0]] - t[first]) if later else "-"
        text = "%+.1f (%.3f)" % (1000 * y[trough], t[trough]) if trough is not None else "-"
        print("%s  %.5f  %d  %.4f  %+.1f (%.3f)  %s  %s  %+.1f" % (
            run, dx, count, level, 1000 * y[first], t[first], text, period, 1000 * y[t >= t[-1] - 0.3].mean()))


if __name__ == "__main__":
    main()
