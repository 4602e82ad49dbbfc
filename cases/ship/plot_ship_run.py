#!/usr/bin/env python3
"""Stitch a ship run continued over several restarts and plot what issue 7 asks for.

    python3 plot_ship_run.py OUT.png RUN_DIR [RUN_DIR ...]

Each RUN_DIR holds a series.h5 written by `moorsph run` (the first from t = 0, the
others restarted from a checkpoint of the one before). Where two runs overlap in time
the later one wins (it restarted from an earlier checkpoint). Prints a summary (the
figures docs/validation/ship.md quotes) and writes one PNG with seven panels: the wave
150 m from the piston, the CoM heave and the bow/stern heights, roll and pitch, the
fairlead tensions (slack marked), the vertical fluid force, green water on deck and the
four hull pressures (0.3 s moving mean).
"""
import os
import sys

os.environ.setdefault("HDF5_USE_FILE_LOCKING", "FALSE")
import h5py  # noqa: E402
import numpy as np  # noqa: E402

GROUPS = {
    "gauges": ["G150", "G200_side", "G470"],  # G200_side: at the focus; G470: 470 m (not in the tiny scenes)
    "points_ship": ["com_y", "bow_y", "stern_y", "com_x", "com_z"],
    "body_ship": ["roll", "pitch", "yaw"],
    "line_fore": ["fairlead_tension", "slack"],
    "line_aft_port": ["fairlead_tension", "slack"],
    "line_aft_starboard": ["fairlead_tension", "slack"],
    "wrench_ship": ["Fy"],
    "green_water_ship": ["volume"],
    "probes": [f"sensor{k}_interpolated_mean" for k in range(1, 5)],
    "energy": ["wall_time"],
    # Bulk packing (mean kernel sum xi): recorded from session 38 on; empty for older runs.
    "packing_probes": ["bulk_fore_xi_mean", "bulk_aft_xi_mean"],
}


def stitch(runs):
    """{group: {column: array}} over all runs, later runs replacing overlapped times."""
    out = {g: {c: [] for c in ["time"] + cols} for g, cols in GROUPS.items()}
    for k, run in enumerate(runs):
        with h5py.File(os.path.join(run, "series.h5"), "r") as f:
            next_start = None
            if k + 1 < len(runs):
                with h5py.File(os.path.join(runs[k + 1], "series.h5"), "r") as nf:
                    next_start = nf["body_ship/time"][0]
            for g, cols in GROUPS.items():
                if g not in f:
                    continue
                t = f[g]["time"][:]
                keep = t < next_start if next_start is not None else np.ones_like(t, bool)
                out[g]["time"].append(t[keep])
                for c in cols:
                    out[g][c].append(f[g][c][:][keep] if c in f[g] else np.full(keep.sum(), np.nan))
    return {g: {c: np.concatenate(v) if v else np.array([]) for c, v in cols.items()} for g, cols in out.items()}


def summary(s):
    p = s["points_ship"]
    b = s["body_ship"]
    t0 = p["time"][0]
    still = (p["time"] > 10.0) & (p["time"] < 30.0)  # released at 2 s, the piston starts at 30 s
    y0 = np.mean(p["com_y"][still]) if still.any() else p["com_y"][0]
    print(f"series {t0:.1f}-{p['time'][-1]:.1f} s")
    g = s["gauges"]
    level = np.mean(g["G150"][g["time"] < 30.0])
    i = np.argmax(g["G150"])
    print(f"gauge 150 m (still level {level:.2f} m): crest {g['G150'][i] - level:+.2f} m at {g['time'][i]:.1f} s, "
          f"trough {g['G150'].min() - level:+.2f} m")
    print(f"CoM heave about its still mean {y0:.2f} m: {p['com_y'].min() - y0:+.2f} / {p['com_y'].max() - y0:+.2f} m")
    print(f"CoM surge {p['com_x'].min():.1f}..{p['com_x'].max():.1f} m, sway {p['com_z'].min():.1f}..{p['com_z'].max():.1f} m")
    print(f"bow height {p['bow_y'].min():.2f}..{p['bow_y'].max():.2f} m, stern {p['stern_y'].min():.2f}..{p['stern_y'].max():.2f} m")
    for a in ["roll", "pitch", "yaw"]:
        print(f"{a}: {np.degrees(b[a]).min():+.2f}..{np.degrees(b[a]).max():+.2f} deg")
    for line in ["line_fore", "line_aft_port", "line_aft_starboard"]:
        L = s[line]
        j = np.argmax(L["fairlead_tension"])
        slack = L["time"][L["slack"] > 0.5]
        print(f"{line}: max {L['fairlead_tension'][j] / 1e6:.2f} MN at {L['time'][j]:.1f} s, min "
              f"{L['fairlead_tension'].min() / 1e6:.2f} MN, slack {len(slack)} samples"
              + (f" ({slack[0]:.1f}-{slack[-1]:.1f} s)" if len(slack) else ""))
    w = s["green_water_ship"]
    j = np.argmax(w["volume"])
    print(f"green water: max {w['volume'][j]:.0f} m^3 at {w['time'][j]:.1f} s")
    F = s["wrench_ship"]
    held = F["time"] > 5.0
    print(f"Fy {F['Fy'][held].min() / 1e6:.0f}..{F['Fy'][held].max() / 1e6:.0f} MN (after 5 s)")
    pr = s["probes"]
    waves = pr["time"] > 30.0
    for k in range(1, 5):
        c = f"sensor{k}_interpolated_mean"
        j = np.flatnonzero(waves)[np.argmax(pr[c][waves])]
        print(f"sensor {k} (0.3 s mean): max {pr[c][j] / 1e3:.0f} kPa at {pr['time'][j]:.1f} s (after 30 s), "
              f"still {np.mean(pr[c][(pr['time'] > 10) & (pr['time'] < 30)]) / 1e3:.0f} kPa")


def plot(s, png):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(7, 1, figsize=(9, 16), sharex=True)
    g = s["gauges"]
    ax[0].plot(g["time"], g["G150"], "k", lw=0.8)
    ax[0].set_ylabel("surface at 150 m [m]")
    p = s["points_ship"]
    for c, lab in [("com_y", "CoM"), ("bow_y", "bow deck end"), ("stern_y", "stern deck end")]:
        ax[1].plot(p["time"], p[c], lw=0.8, label=lab)
    ax[1].set_ylabel("height [m]")
    ax[1].legend(fontsize=7)
    b = s["body_ship"]
    for c in ["roll", "pitch"]:
        ax[2].plot(b["time"], np.degrees(b[c]), lw=0.8, label=c)
    ax[2].set_ylabel("angle [deg]")
    ax[2].legend(fontsize=7)
    for line in ["line_fore", "line_aft_port", "line_aft_starboard"]:
        L = s[line]
        ax[3].plot(L["time"], L["fairlead_tension"] / 1e6, lw=0.8, label=line[5:])
        sl = L["slack"] > 0.5
        ax[3].plot(L["time"][sl], L["fairlead_tension"][sl] / 1e6, "rx", ms=3)
    ax[3].set_ylabel("fairlead tension [MN]")
    ax[3].legend(fontsize=7)
    F = s["wrench_ship"]
    ax[4].plot(F["time"], F["Fy"] / 1e6, "k", lw=0.8)
    held = F["time"] > 5.0  # the release at 2 s rings for a few seconds
    if held.any():
        lo, hi = F["Fy"][held].min() / 1e6, F["Fy"][held].max() / 1e6
        ax[4].set_ylim(lo - 0.1 * (hi - lo), hi + 0.1 * (hi - lo))
    ax[4].set_ylabel("fluid Fy [MN]")
    w = s["green_water_ship"]
    ax[5].plot(w["time"], w["volume"], "b", lw=0.8)
    ax[5].set_ylabel("green water [m^3]")
    pr = s["probes"]
    for k in range(1, 5):
        ax[6].plot(pr["time"], pr[f"sensor{k}_interpolated_mean"] / 1e3, lw=0.8, label=f"sensor {k}")
    ax[6].set_ylabel("pressure, 0.3 s mean [kPa]")
    ax[6].legend(fontsize=7)
    ax[6].set_xlabel("t [s]")
    fig.tight_layout()
    fig.savefig(png, dpi=90)


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    s = stitch(sys.argv[2:])
    summary(s)
    plot(s, sys.argv[1])


if __name__ == "__main__":
    main()
