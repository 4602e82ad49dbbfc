#!/usr/bin/env python3
"""Mean water levels, ship CoM height and cable tensions over time windows, per ship run.

    python3 mean_levels.py --windows 20-30,60-100,230-265 NAME=RUN_DIR[,RUN_DIR...] [NAME=...]

How docs/validation/ship.md measures the gauges' mean fall as the sea builds: the mean of
each gauge (150 m, the focus at 200 m, 470 m), of the CoM height and of each fairlead
tension over each window. The water's volume does not change (sum m/rho is constant to
1e-4); a fall of the gauges is the particles packing closer than their densities say
(ship.md finding 6, session 37), which the bulk packing probes' mean xi (bulk_fore,
bulk_aft; runs from session 38 on, "-" for older ones) shows directly. RUN_DIRs are the
segments of one run, stitched as plot_ship_run.py does. Tested by
tests/cases/ship/test_compare_variants.py.
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from compare_variants import LINES  # noqa: E402
from plot_ship_run import stitch  # noqa: E402

GAUGES = ["G150", "G200_side", "G470"]
PACKING = ["bulk_fore", "bulk_aft"]


def fmt(value, digits):
    return "-" if np.isnan(value) else f"{value:.{digits}f}"


def window_mean(cols, column, t0, t1):
    """The mean of `column` over t0 <= t < t1 (samples of NaN skipped); NaN when none."""
    t = cols["time"]
    v = cols[column][(t >= t0) & (t < t1)]
    v = v[np.isfinite(v)]
    return float(v.mean()) if v.size else float("nan")


def levels(s, t0, t1):
    """{label: mean} over one window of a stitched run."""
    out = {g: window_mean(s["gauges"], g, t0, t1) for g in GAUGES}
    out["CoM"] = window_mean(s["points_ship"], "com_y", t0, t1)
    for line in LINES:
        out[line[5:]] = window_mean(s[line], "fairlead_tension", t0, t1) / 1e6
    for box in PACKING:
        out[box] = window_mean(s["packing_probes"], box + "_xi_mean", t0, t1)
    return out


def parse_windows(text):
    """'20-30,60-100' -> [(20.0, 30.0), (60.0, 100.0)]"""
    out = []
    for w in text.split(","):
        a, b = w.split("-")
        out.append((float(a), float(b)))
    return out


def main():
    args = sys.argv[1:]
    if "--windows" not in args or args.index("--windows") + 1 >= len(args):
        sys.exit(__doc__)
    k = args.index("--windows")
    windows = parse_windows(args[k + 1])
    runs = args[:k] + args[k + 2:]
    if not runs:
        sys.exit(__doc__)
    print("| run | window [s] | " + " | ".join(GAUGES) + " | CoM [m] | fore / aft port / aft stbd [MN] | xi bulk fore / aft |")
    print("|---" * (len(GAUGES) + 5) + "|")
    for arg in runs:
        if "=" not in arg:
            sys.exit(f"mean_levels.py: '{arg}' is not NAME=RUN_DIR[,RUN_DIR...]")
        name, dirs = arg.split("=", 1)
        s = stitch(dirs.split(","))
        for t0, t1 in windows:
            m = levels(s, t0, t1)
            tensions = " / ".join(f"{m[line[5:]]:.2f}" for line in LINES)
            print(f"| {name} | {t0:g}-{t1:g} | " + " | ".join(f"{m[g]:.3f}" for g in GAUGES) +
                  f" | {m['CoM']:.3f} | {tensions} | " + " / ".join(fmt(m[b], 4) for b in PACKING) + " |")


if __name__ == "__main__":
    main()
