#!/usr/bin/python3
"""Table and plots of the tethered-buoy study (cases/tethered_buoy/run_study.sh).

Usage: plot_study.py RUNS_DIR DOCS_DIR
Reads RUNS_DIR/summary.txt (one line per run) and RUNS_DIR/<run>.csv; writes
DOCS_DIR/tethered-buoy-vertical.png, DOCS_DIR/tethered-buoy-horizontal.png and prints a
markdown table (run, dx, particles, steps, wall time, period, decay, first extremum,
tension range, final offset from the nominal rest pose).
"""
import csv
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

D = 0.203  # buoy diameter [m]


def read_summary(path):
    runs = {}
    for line in open(path):
        name, rest = line.split(" ", 1)
        fields = dict(re.findall(r"(\w+)=(\[[^\]]*\]|\S+)", rest))
        runs[name] = fields
    return runs


def read_series(path):
    cols = {}
    with open(path) as f:
        for row in csv.DictReader(f):
            for k, v in row.items():
                cols.setdefault(k, []).append(float(v))
    return cols


def describe(name):
    kind = "vertical" if name.startswith("v_") else "horizontal"
    m = re.search(r"_d(\d+)", name)
    tank = {"t06": "0.6 x 0.6 m", "t10": "1.0 x 1.0 m", "t2": "2.0 x 0.6 m"}
    t = next((v for k, v in tank.items() if f"_{k}" in name), "?")
    depth = "0.8 m" if name.endswith("_d08") else ("0.4 m" if kind == "horizontal" else "0.5 m")
    return kind, int(m.group(1)), t, depth


def main():
    runs_dir, docs_dir = sys.argv[1], sys.argv[2]
    runs = read_summary(f"{runs_dir}/summary.txt")
    print("| run | release | dx | tank | depth | particles | steps | wall s | period s | decay/cycle "
          "| first extremum mm | tension N | final offset mm |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for kind, column in (("vertical", "heave_m"), ("horizontal", "surge_m")):
        if not any(describe(name)[0] == kind for name in runs):
            continue
        fig, (ax, ax_t) = plt.subplots(2, 1, figsize=(8, 6), sharex=True)
        for name, f in runs.items():
            k, res, tank, depth = describe(name)
            if k != kind:
                continue
            s = read_series(f"{runs_dir}/{name}.csv")
            t = s["t_s"]
            tail = [v for tt, v in zip(t, s[column]) if tt > t[-1] - 0.5]
            final = 1e3 * sum(tail) / len(tail)
            print(f"| {name} | {kind} | D/{res} | {tank} | {depth} | {f['particles']} | {f['steps']} | "
                  f"{float(f['wall_s']):.0f} | {f['period_s']} | {f['decay_per_cycle']} | "
                  f"{1e3 * float(f['first_extremum']):+.1f} | {f['tension_N']} | {final:+.1f} |")
            label = f"D/{res}, {tank}, depth {depth}"
            ax.plot(t, [1e3 * v for v in s[column]], label=label, lw=1)
            ax_t.plot(t, s["tension_N"], lw=1)
        ax.axvline(0, color="k", lw=0.5)
        ax.set_ylabel(f"{column.split('_')[0]} from rest [mm]")
        ax.legend(fontsize=8)
        ax.set_title(f"Tethered lab buoy, {kind} release (METHOD 6.2)")
        ax_t.set_ylabel("tether tension [N]")
        ax_t.set_xlabel("time after release [s]")
        fig.tight_layout()
        fig.savefig(f"{docs_dir}/tethered-buoy-{kind}.png", dpi=90)


if __name__ == "__main__":
    main()
