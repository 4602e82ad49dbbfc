#!/usr/bin/python3
"""Compare moorsph SPHERIC Test 2 runs with the MARIN experiment (Kleefsman et al. 2005).

usage: compare.py --data test_case_2_exp_data.dat --plots DIR [--table FILE] RUN_DIR [RUN_DIR ...]

Each RUN_DIR holds series.h5 and run.txt written by moorsph_spheric_test2. The data
file's columns are Time, P1..P8 [Pa], H1..H4 [m]; its "H1" is the gauge at x = 1.488 m
(nearest the gate) and "H3" the one at x = 0.496 m (see the refdata README), and the
runs write their gauges in that same column meaning, so H_k is compared with H_k.

Metrics (window 0..6 s, or the run's end if earlier):
  heights   RMS of (simulated - measured) on the data's time base, for the METHOD.md
            gauge (xi_t = 0.8) and the xi_t = 0.5 level; the arrival time (first
            height > 2 cm) of H1..H3.
  P1        peak value and time, raw and after a 10 ms running mean of both signals
            (the SPH pressure carries acoustic noise sampled at the output interval);
            RMS difference of the 10 ms means over 0.3..6 s.
"""
import argparse
import os

# Read series.h5 of a run that is still writing it (HDF5 1.10 locks files by default).
os.environ.setdefault("HDF5_USE_FILE_LOCKING", "FALSE")
import h5py  # noqa: E402
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

GAUGES = ["H1", "H2", "H3", "H4"]
GAUGE_X = {"H1": 1.488, "H2": 0.992, "H3": 0.496, "H4": 2.638}
SENSORS = ["P1", "P2", "P3", "P4"]
WINDOW = 6.0


def load_data(path):
    d = np.loadtxt(path, skiprows=1)
    data = {"time": d[:, 0]}
    for k, name in enumerate(SENSORS + ["P5", "P6", "P7", "P8"]):
        data[name] = d[:, 1 + k]
    for k, name in enumerate(GAUGES):
        data[name] = d[:, 9 + k]
    return data


def load_run(run_dir):
    info = {}
    with open(os.path.join(run_dir, "run.txt")) as f:
        for line in f:
            key, _, value = line.strip().partition(" ")
            info[key] = value
    with h5py.File(os.path.join(run_dir, "series.h5"), "r") as f:
        series = {name: {c: f[name][c][:] for c in f[name].keys()} for name in f.keys()}
    if info.get("status", "finished") != "finished":
        # Stopped by hand (or still running): the last output row has the figures.
        e = series["energy"]
        info["simulated"] = str(e["time"][-1])
        info["steps"] = str(int(e["steps"][-1]))
        info["wall_seconds"] = str(e["wall_time"][-1])
    return info, series


def running_mean(t, y, width):
    """Centred running mean over `width` seconds of a uniformly sampled signal."""
    dt = np.median(np.diff(t))
    n = max(1, int(round(width / dt)))
    kernel = np.ones(n) / n
    return np.convolve(y, kernel, mode="same")


def first_crossing(t, y, level):
    idx = np.nonzero(y > level)[0]
    return float(t[idx[0]]) if idx.size else float("nan")


def metrics(data, info, series, window=WINDOW):
    out = {}
    t_end = min(window, float(series["gauges"]["time"][-1]))
    mask = data["time"] <= t_end
    te = data["time"][mask]
    for g in GAUGES:
        for key, name in (("gauges", g), ("gauges_half", g + "_half")):
            if key not in series:
                continue
            s = series[key]
            sim = np.interp(te, s["time"], s[g])
            out["rms_" + name] = float(np.sqrt(np.mean((sim - data[g][mask]) ** 2)))
        if g != "H4":
            out["arrive_" + g] = first_crossing(series["gauges"]["time"], series["gauges"][g], 0.02)
            out["arrive_exp_" + g] = first_crossing(data["time"], data[g], 0.02)
    p = series["pressure"]
    tp = p["time"]
    for name in ("P1", "P1i"):
        raw = p[name]
        k = int(np.argmax(raw))
        out["peak_" + name] = (float(raw[k]), float(tp[k]))
        smooth = running_mean(tp, raw, 0.010)
        k = int(np.argmax(smooth))
        out["peak10_" + name] = (float(smooth[k]), float(tp[k]))
        exp_smooth = running_mean(data["time"], data["P1"], 0.010)
        win = te >= 0.3
        sim_on_exp = np.interp(te[win], tp, smooth)
        out["rms10_" + name] = float(np.sqrt(np.mean((sim_on_exp - exp_smooth[mask][win]) ** 2)))
    k = int(np.argmax(data["P1"]))
    out["peak_exp_P1"] = (float(data["P1"][k]), float(data["time"][k]))
    exp_smooth = running_mean(data["time"], data["P1"], 0.010)
    k = int(np.argmax(exp_smooth))
    out["peak10_exp_P1"] = (float(exp_smooth[k]), float(data["time"][k]))
    out["t_end"] = t_end
    return out


def label(info):
    dd = " +dd" if info.get("density_diffusion", "0") == "1" else ""
    xs = " +Monaghan XSPH" if info.get("xsph_monaghan", "0") == "1" else ""
    return "moorsph dx = %.4g m%s%s" % (float(info["dx"]), dd, xs)


def plot_heights(data, runs, path):
    fig, axes = plt.subplots(4, 1, figsize=(8, 10), sharex=True)
    for ax, g in zip(axes, GAUGES):
        ax.plot(data["time"], data[g], "k-", lw=1.0, label="experiment (MARIN)")
        for info, series, _ in runs:
            s = series["gauges"]
            ax.plot(s["time"], s[g], lw=1.0, label=label(info))
        ax.set_ylabel("%s [m]\n(x = %.3f m)" % (g, GAUGE_X[g]))
        ax.set_xlim(0, 7.4)
        ax.grid(alpha=0.3)
    axes[0].legend(loc="upper right", fontsize=8)
    axes[-1].set_xlabel("t [s]")
    fig.suptitle("SPHERIC Test 2: water heights (gauge xi_t = 0.8, METHOD.md section 3)")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def finished(info):
    return info.get("error", "none") == "none" and info.get("status", "finished") == "finished"


def plot_pressure(data, runs, path):
    runs = [r for r in runs if finished(r[0])]  # runs that stopped early: heights plot and tables only
    fig, axes = plt.subplots(len(SENSORS), 1, figsize=(8, 10), sharex=True)
    for ax, name in zip(axes, SENSORS):
        ax.plot(data["time"], running_mean(data["time"], data[name], 0.010), "k-", lw=1.0,
                label="experiment, 10 ms mean")
        for info, series, _ in runs:
            p = series["pressure"]
            ax.plot(p["time"], running_mean(p["time"], p[name], 0.010), lw=0.9,
                    label=label(info) + ", reactions")
            ax.plot(p["time"], running_mean(p["time"], p[name + "i"], 0.010), lw=0.9, ls="--",
                    label=label(info) + ", interpolated")
        ax.set_ylabel("%s [Pa]" % name)
        ax.set_xlim(0, 7.4)
        ax.grid(alpha=0.3)
    axes[0].legend(loc="upper right", fontsize=7)
    axes[-1].set_xlabel("t [s]")
    fig.suptitle("SPHERIC Test 2: pressure on the box face x = 0.8245 m (10 ms running means)")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def plot_p1_zoom(data, runs, path):
    runs = [r for r in runs if finished(r[0])]
    fig, ax = plt.subplots(figsize=(8, 4))
    ax.plot(data["time"], data["P1"], color="0.6", lw=0.6, label="experiment, raw")
    ax.plot(data["time"], running_mean(data["time"], data["P1"], 0.010), "k-", lw=1.2,
            label="experiment, 10 ms mean")
    for info, series, _ in runs:
        p = series["pressure"]
        ax.plot(p["time"], running_mean(p["time"], p["P1"], 0.010), lw=1.0, label=label(info) + ", reactions")
        ax.plot(p["time"], running_mean(p["time"], p["P1i"], 0.010), lw=1.0, ls="--",
                label=label(info) + ", interpolated")
    ax.set_xlim(0.3, 1.2)
    ax.set_xlabel("t [s]")
    ax.set_ylabel("P1 [Pa]")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7)
    ax.set_title("P1 (box face, 0.021 m above the floor): the impact")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def table(runs, data, heading=""):
    rows = [heading] if heading else []
    rows.append("| run | dx [m] | fluid particles | boundary particles | simulated [s] | steps | wall [s] | threads "
                "| particle-steps/s |")
    rows.append("|---|---|---|---|---|---|---|---|---|")
    for info, series, m in runs:
        n = int(info["particles"])
        steps = int(info["steps"])
        wall = float(info["wall_seconds"])
        rows.append("| %s | %.4g | %d | %s | %.3f | %d | %.0f | %s | %.2e |" % (
            label(info), float(info["dx"]), n, info.get("boundary_particles", "?"), float(info["simulated"]),
            steps, wall, info["threads"], n * steps / wall))
    rows.append("")
    rows.append("| run | RMS H1 [mm] | RMS H2 [mm] | RMS H3 [mm] | RMS H4 [mm] | same, xi_t = 0.5 [mm] "
                "| arrival H1/H2/H3 [s] |")
    rows.append("|---|---|---|---|---|---|---|")
    first = runs[0][2]
    rows.append("| experiment | | | | | | %.3f / %.3f / %.3f |" % tuple(first["arrive_exp_" + g] for g in GAUGES[:3]))
    for info, series, m in runs:
        half = " / ".join("%.0f" % (1e3 * m["rms_%s_half" % g]) for g in GAUGES if "rms_%s_half" % g in m)
        rows.append("| %s (0..%.1f s) | %.0f | %.0f | %.0f | %.0f | %s | %.3f / %.3f / %.3f |" % (
            (label(info), m["t_end"]) + tuple(1e3 * m["rms_" + g] for g in GAUGES) + (half,)
            + tuple(m["arrive_" + g] for g in GAUGES[:3])))
    rows.append("")
    rows.append("| run | P1 peak raw [Pa] at [s] | P1 peak, 10 ms mean [Pa] at [s] | RMS of 10 ms means, 0.3 s..window end [Pa] |")
    rows.append("|---|---|---|---|")
    rows.append("| experiment | %.0f at %.3f | %.0f at %.3f | |" % (first["peak_exp_P1"] + first["peak10_exp_P1"]))
    for info, series, m in runs:
        for name, what in (("P1", "reactions"), ("P1i", "interpolated")):
            rows.append("| %s, %s | %.0f at %.3f | %.0f at %.3f | %.0f |" % (
                (label(info), what) + m["peak_" + name] + m["peak10_" + name] + (m["rms10_" + name],)))
    return "\n".join(rows) + "\n"


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--data", required=True)
    ap.add_argument("--plots", required=True, help="folder for the PNG plots")
    ap.add_argument("--table", help="write the markdown tables here too")
    ap.add_argument("--common-window", action="store_true",
                    help="also tabulate every run's errors over the shortest run's time window")
    ap.add_argument("runs", nargs="+")
    args = ap.parse_args()
    data = load_data(args.data)
    runs = []
    for r in args.runs:
        if not os.path.exists(os.path.join(r, "run.txt")):
            print("skipping %s (no run.txt: not run or not finished)" % r)
            continue
        info, series = load_run(r)
        runs.append((info, series, metrics(data, info, series)))
    if not runs:
        raise SystemExit("no finished runs")
    os.makedirs(args.plots, exist_ok=True)
    plot_heights(data, runs, os.path.join(args.plots, "spheric-test2-heights.png"))
    plot_pressure(data, runs, os.path.join(args.plots, "spheric-test2-pressure.png"))
    plot_p1_zoom(data, runs, os.path.join(args.plots, "spheric-test2-p1-impact.png"))
    text = table(runs, data, "Errors over 0..%.0f s (or up to where a run stopped):\n" % WINDOW)
    if args.common_window:
        common = min(float(series["gauges"]["time"][-1]) for _, series, _ in runs)
        again = [(info, series, metrics(data, info, series, common)) for info, series, _ in runs]
        text += "\n" + table(again, data, "Errors over the common window 0..%.2f s:\n" % common)
    print(text)
    if args.table:
        with open(args.table, "w") as f:
            f.write(text)


if __name__ == "__main__":
    main()
