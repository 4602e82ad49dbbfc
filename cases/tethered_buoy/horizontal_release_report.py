#!/usr/bin/python3
"""The tethered buoy's horizontal release (METHOD.md 6.2b) from a run of
horizontal_release_3d.yaml: turning points, crossings of the rest, period, decay, plot.

    horizontal_release_report.py RUN_DIR [PNG] [--rest 0.746] [--release 0.3]

Reads RUN_DIR/series.h5 (body_buoy x, y; velocity_buoy vx; line_tether fairlead_tension;
a restarted run's series carry the history from t = 0). Prints the surge turning points
after the release (where vx changes sign) with their distance past the rest x = 0.746 m,
the times the buoy passes the rest (linear interpolation), the half periods between
successive turns and successive crossings, the decay per half cycle (|next| / |previous|
turning distance, the first from the release offset) and the tether's and height's ranges;
writes a plot of surge, height and tension against time when PNG is given. Tested by
tests/cases/tethered_buoy/test_horizontal_release_report.py.
"""
import os
import sys

import numpy as np


def turning_points(t, x, v, after):
    """[(t, x)] where the velocity changes sign after `after` (the output with the new sign)."""
    s = np.sign(v)
    return [(t[i], x[i]) for i in range(1, len(t)) if t[i] > after and s[i] != 0 and s[i - 1] != 0 and s[i] != s[i - 1]]


def crossings(t, x, level):
    """Times x passes `level`, linearly interpolated between outputs."""
    out = []
    for i in range(1, len(t)):
        a, b = x[i - 1] - level, x[i] - level
        if a * b < 0:
            out.append(t[i - 1] + a / (a - b) * (t[i] - t[i - 1]))
    return out


def analyse(t, x, v, rest, release):
    """Turns (after the first output past the release at which the buoy moves), crossings,
    half periods and decay ratios per half cycle."""
    start = x[np.searchsorted(t, release)] - rest
    turns = [(tt, xx - rest) for tt, xx in turning_points(t, x, v, release + 0.1)]
    cross = crossings(t, x, rest)
    amplitudes = [start] + [d for _, d in turns]
    decay = [abs(b) / abs(a) for a, b in zip(amplitudes, amplitudes[1:])]
    return {
        "start": start,
        "turns": turns,
        "crossings": cross,
        "half_periods_turns": list(np.diff([tt for tt, _ in turns])),
        "half_periods_crossings": list(np.diff(cross)),
        "decay": decay,
    }


def main():
    args = list(sys.argv[1:])
    rest, release = 0.746, 0.3
    for flag in ("--rest", "--release"):
        if flag in args:
            k = args.index(flag)
            value = float(args[k + 1])
            del args[k:k + 2]
            rest, release = (value, release) if flag == "--rest" else (rest, value)
    if not args:
        sys.exit(__doc__)
    import h5py
    with h5py.File(args[0] + "/series.h5", "r") as f:
        t = f["body_buoy/time"][:]
        x, y = f["body_buoy/x"][:], f["body_buoy/y"][:]
        v = f["velocity_buoy/vx"][:]
        tension = f["line_tether/fairlead_tension"][:]
    r = analyse(t, x, v, rest, release)
    print(f"series 0-{t[-1]:.3f} s; released at {release} s from {1e3 * r['start']:+.1f} mm past the rest x = {rest} m")
    for (tt, d), ratio in zip(r["turns"], r["decay"]):
        print(f"turn at {tt:.3f} s: {1e3 * d:+.1f} mm past the rest (|this| / |previous| {ratio:.3f})")
    for c in r["crossings"]:
        print(f"through the rest at {c:.3f} s")
    print("half periods between turns [s]: " + ", ".join(f"{h:.3f}" for h in r["half_periods_turns"]))
    print("half periods between crossings [s]: " + ", ".join(f"{h:.3f}" for h in r["half_periods_crossings"]))
    after = t > release
    print(f"after the release: height y {y[after].min():.4f}-{y[after].max():.4f} m, tether "
          f"{tension[after].min():.2f}-{tension[after].max():.2f} N; at {t[-1]:.2f} s x - rest = "
          f"{1e3 * (x[-1] - rest):+.1f} mm, vx {v[-1]:+.4f} m/s")
    if len(args) > 1:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(3, 1, figsize=(8, 8), sharex=True)
        ax[0].plot(t, 1e3 * (x - rest))
        ax[0].axhline(0.0, color="grey", lw=0.5)
        for tt, d in r["turns"]:
            ax[0].annotate(f"{1e3 * d:+.1f} mm\n{tt:.2f} s", (tt, 1e3 * d), fontsize=8)
        ax[0].set_ylabel("surge past the rest [mm]")
        ax[1].plot(t, 1e3 * (y - y[0]))
        ax[1].set_ylabel("height from the start [mm]")
        ax[2].plot(t, tension)
        ax[2].set_ylabel("tether tension [N]")
        ax[2].set_xlabel("t [s]")
        fig.suptitle(f"tethered buoy, horizontal release ({os.path.basename(os.path.normpath(args[0]))})", fontsize=9)
        fig.tight_layout()
        fig.savefig(args[1], dpi=110)
        print(f"wrote {args[1]}")


if __name__ == "__main__":
    main()
