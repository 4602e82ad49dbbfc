#!/usr/bin/env python3
"""Compare ship runs (the base and its design variants) over one time window.

    python3 compare_variants.py T0 T1 OUT.png NAME=RUN_DIR[,RUN_DIR...] [NAME=...]

Each NAME names one variant; its RUN_DIRs are the segments of that run in order (a run
continued from a checkpoint), stitched as plot_ship_run.py does. Prints a Markdown table
of what issue 7 asks to compare (cable peaks, slack spells and the fastest rise of tension
between samples, a snap's signature; heave, pitch, deck-end
heights, fluid force, green water, hull-pressure peaks) over T0 <= t <= T1, one column
per variant, and writes one PNG overlaying the variants' time series. The table's logic
and plot_ship_run.stitch are tested by tests/cases/ship/test_compare_variants.py.
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plot_ship_run import stitch  # noqa: E402

LINES = ["line_fore", "line_aft_port", "line_aft_starboard"]
HANGING = 0.5e6  # [N]: a fairlead tension below this counts as a hanging (slack) line
DESIGN_COM_Y = 132.48  # [m]: the CoM height at the design pose (ship_base.yaml, docs/validation/ship.md)


def past_first_second(time):
    """The samples after a window's first second: a restart variant's changed line steps
    in that second, so the fastest rise is looked for after it."""
    return time >= time[0] + 1.0


def window(series, t0, t1, name="run"):
    """The stitched series cut to t0 <= t <= t1. A run whose cable series do not cover the
    window past its first second (a segment missing, or a run that stopped early) has no
    fastest rise or peak to report: SystemExit naming the run and where its series end."""
    out = {}
    for g, cols in series.items():
        t = cols["time"]
        keep = (t >= t0) & (t <= t1)
        out[g] = {c: v[keep] for c, v in cols.items()}
    for line in LINES:
        t = out[line]["time"]
        if t.size == 0 or past_first_second(t).sum() < 2:  # rows() needs two of them for a rise
            full = series[line]["time"]
            span = f"{full[0]:.2f}-{full[-1]:.2f} s" if full.size else "no rows"
            sys.exit(f"compare_variants.py: {name}: its {line} series cover {span}, "
                     f"not the window {t0:g}-{t1:g} s past its first second; give all of the run's segments")
    return out


def spells(time, flag):
    """[(start, end)] of the intervals where the boolean array `flag` holds: from the first
    sample that has it to the first that has not."""
    out, start = [], None
    for t, f in zip(time, flag):
        if f and start is None:
            start = t
        if not f and start is not None:
            out.append((start, t))
            start = None
    if start is not None:
        out.append((start, time[-1]))
    return out


def rows(s):
    """{row label: text} for one variant's windowed series."""
    r = {}
    for line in LINES:
        L = s[line]
        k = np.argmax(L["fairlead_tension"])
        slack = spells(L["time"], L["slack"] > 0.5)
        r[f"{line[5:]}: tension range [MN]"] = (f"{L['fairlead_tension'].min() / 1e6:.1f}-"
                                                f"{L['fairlead_tension'][k] / 1e6:.1f} (peak {L['time'][k]:.1f} s)")
        r[f"{line[5:]}: slack [s]"] = ", ".join(f"{a:.1f}-{b:.1f}" for a, b in slack) or "never"
        # The catenary and lumped-mass lines hang on their weight where a spring goes slack
        # and rarely raise the flag: the time below HANGING reads alike for every model.
        hanging = spells(L["time"], L["fairlead_tension"] < HANGING)
        r[f"{line[5:]}: below {HANGING / 1e6:g} MN [s]"] = ", ".join(f"{a:.1f}-{b:.1f}" for a, b in hanging) or "never"
        late = past_first_second(L["time"])
        rise = np.diff(L["fairlead_tension"][late]) / np.diff(L["time"][late])
        k = np.argmax(rise)
        r[f"{line[5:]}: fastest rise [MN/s]"] = f"{rise[k] / 1e6:.1f} ({L['time'][late][k]:.1f} s)"
    p, b = s["points_ship"], s["body_ship"]
    r["CoM height [m] (design 132.48)"] = f"{p['com_y'].min():.1f} / {p['com_y'].max():.1f}"
    r["CoM surge [m]"] = f"{p['com_x'].min():.1f} / {p['com_x'].max():.1f}"
    r["pitch [deg]"] = f"{np.degrees(b['pitch']).min():+.1f} / {np.degrees(b['pitch']).max():+.1f}"
    r["bow / stern deck end lowest [m]"] = f"{p['bow_y'].min():.1f} / {p['stern_y'].min():.1f}"
    F = s["wrench_ship"]["Fy"]
    r["fluid Fy [MN]"] = f"{F.min() / 1e6:.0f}-{F.max() / 1e6:.0f}"
    w = s["green_water_ship"]
    k = np.argmax(w["volume"])
    r["green water, most [m^3]"] = f"{w['volume'][k]:.0f}" + (f" ({w['time'][k]:.1f} s)" if w["volume"][k] > 0 else "")
    pr = s["probes"]
    r["sensors 1-4, 0.3 s mean peak [kPa]"] = " / ".join(
        f"{pr[f'sensor{k}_interpolated_mean'].max() / 1e3:.0f}" for k in range(1, 5))
    g = s["gauges"]
    r["gauge 150 m [m]"] = f"{g['G150'].min():.1f}-{g['G150'].max():.1f}"
    if not np.isnan(g["G200_side"]).all():
        k = np.nanargmax(g["G200_side"])
        r["gauge at the focus, 200 m [m]"] = (f"{np.nanmin(g['G200_side']):.1f}-{g['G200_side'][k]:.1f} "
                                              f"(crest {g['time'][k]:.1f} s)")
    return r


def table(names, all_rows):
    print("| " + " | ".join(["quantity"] + names) + " |")
    print("|---" * (len(names) + 1) + "|")
    for label in all_rows[0]:
        print("| " + " | ".join([label] + [r[label] for r in all_rows]) + " |")


def plot(names, windows, png):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(6, 1, figsize=(9, 14), sharex=True)
    for name, s in zip(names, windows):
        p, b = s["points_ship"], s["body_ship"]
        ax[0].plot(p["time"], p["com_y"], lw=0.8, label=name)
        ax[1].plot(b["time"], np.degrees(b["pitch"]), lw=0.8, label=name)
        for a, line in zip(ax[2:4], ["line_fore", "line_aft_port"]):
            a.plot(s[line]["time"], s[line]["fairlead_tension"] / 1e6, lw=0.8, label=name)
        ax[4].plot(s["wrench_ship"]["time"], s["wrench_ship"]["Fy"] / 1e6, lw=0.8, label=name)
        ax[5].plot(s["green_water_ship"]["time"], s["green_water_ship"]["volume"], lw=0.8, label=name)
    labels = ["CoM height [m]", "pitch [deg]", "fore tension [MN]", "aft port tension [MN]", "fluid Fy [MN]",
              "green water [m^3]"]
    for a, lab in zip(ax, labels):
        a.set_ylabel(lab)
        a.legend(fontsize=7)
    ax[-1].set_xlabel("t [s]")
    fig.tight_layout()
    fig.savefig(png, dpi=90)


def main():
    if len(sys.argv) < 5:
        sys.exit(__doc__)
    t0, t1, png = float(sys.argv[1]), float(sys.argv[2]), sys.argv[3]
    names, windows = [], []
    for arg in sys.argv[4:]:
        if "=" not in arg:
            sys.exit(f"compare_variants.py: '{arg}' is not NAME=RUN_DIR[,RUN_DIR...]")
        name, dirs = arg.split("=", 1)
        names.append(name)
        windows.append(window(stitch(dirs.split(",")), t0, t1, name))
    table(names, [rows(s) for s in windows])
    plot(names, windows, png)


if __name__ == "__main__":
    main()
