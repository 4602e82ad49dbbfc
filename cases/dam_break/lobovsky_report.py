#!/usr/bin/python3
"""Lobovsky et al. (2014) dam break, H = 300 mm: runs of cases/dam_break/lobovsky_h300_2d.yaml
against the measured pressure at sensor 2 (z = 15 mm on the far wall).

usage: lobovsky_report.py reference OUT_DIR [WIDTH]
         writes OUT_DIR/lobovsky_p2_{median,p2.5,p97.5}.csv: time [s], pressure [Pa]
         (t = (t/T) T with T = sqrt(H/g); p = (p/rho g H) rho g H, rho = 1000 kg/m^3 as
         in the scene), for `moorsph study --reference FILE`, and with WIDTH [s]
         OUT_DIR/lobovsky_p2_median_mean.csv, the median's trailing mean over WIDTH (the
         same as a probe's `moving_mean`, so the two compare like with like)
       lobovsky_report.py report --out PREFIX RUN_DIR [RUN_DIR ...]
         writes PREFIX.md (table) and PREFIX.png (P2 against the 2.5-97.5 % band), prints
         the table
       lobovsky_report.py ensemble --out PREFIX RUN_DIR [RUN_DIR ...]
         runs of one spacing that differ only in a detail (time step, integrator, thread
         count): after the impact the flow is chaotic and one run is one draw, as each of
         the experiment's repeats is. Writes PREFIX.md (per run, and the ensemble's mean,
         standard deviation and range of the peak and plateau, 34 ms means) and PREFIX.png
         (every member against the band)

The reference file (../shared/refdata/lobovsky2014/) holds, per t/T, the 2.5 %, 50 % and
97.5 % percentiles of p/(rho g H) over 100 repeats (the paper's figure 31). Per run, per
estimate of the probe (interpolated 1.5 dx in front of the wall; reaction of the wall
particles) and per processing (raw samples; centred moving mean over 4 H / c_s, the water
column's fundamental acoustic period in the SPH, which removes the artificial-compressibility
ringing: see the scene's comment; the median is then given the same mean), measured the
same way on the median:
- peak: the largest p/(rho g H) over the first impact, t/T in [1.8, 3.2]; the band for the
  peak is the largest 2.5 % and 97.5 % values over the same window;
- t_peak: its t/T;
- plateau: the mean over t/T in [3.5, 5.5] (the wall carries the run-up's weight);
- rms: RMS of run minus median over t/T in [1.8, 7.0], / (rho g H);
- in band: the fraction of the reference's samples in that window where the run lies
  between the 2.5 % and 97.5 % curves.
"""
import argparse
import math
import os
import sys

import numpy as np

H, G, RHO = 0.3, 9.81, 1000.0
T = math.sqrt(H / G)
PSCALE = RHO * G * H
HERE = os.path.dirname(os.path.abspath(__file__))
REFDATA = os.path.join(HERE, "..", "..", "..", "shared", "refdata", "lobovsky2014",
                       "lobovsky_H300_sensor2_percentiles.csv")
IMPACT = (1.8, 3.2)
PLATEAU = (3.5, 5.5)
COMPARE = (1.8, 7.0)
ESTIMATES = ("interpolated", "reaction")


def centred_mean(t, v, width):
    """Moving mean of v over [t - width/2, t + width/2] (uniform samples assumed)."""
    n = max(1, int(round(width / (t[1] - t[0]))))
    if n % 2 == 0:
        n += 1
    pad = n // 2
    padded = np.concatenate([np.full(pad, v[0]), v, np.full(pad, v[-1])])
    return np.convolve(padded, np.ones(n) / n, mode="valid")


def load_reference(path=REFDATA):
    data = np.loadtxt(path, delimiter=",", skiprows=1)
    return {"t": data[:, 0], "p2.5": data[:, 1], "median": data[:, 2], "p97.5": data[:, 3]}


def trailing_mean(t, v, width):
    """Mean of v over (t - width, t], as the probes' moving_mean (uniform samples)."""
    n = max(1, int(round(width / (t[1] - t[0]))))
    c = np.concatenate([[0.0], np.cumsum(v)])
    k = np.arange(1, len(v) + 1)
    lo = np.maximum(0, k - n)
    return (c[k] - c[lo]) / (k - lo)


def write_reference(out_dir, width=None):
    ref = load_reference()
    os.makedirs(out_dir, exist_ok=True)
    series = {key: ref[key] for key in ("median", "p2.5", "p97.5")}
    if width:
        series["median_mean"] = trailing_mean(ref["t"] * T, ref["median"], width)
    for key, values in series.items():
        path = os.path.join(out_dir, "lobovsky_p2_%s.csv" % key)
        np.savetxt(path, np.column_stack([ref["t"] * T, values * PSCALE]), delimiter=",",
                   header="time,value", comments="", fmt="%.6g")
        print(path)


def window(t, lo, hi):
    return (t >= lo) & (t <= hi)


def measures(t_over_T, p_over, ref):
    """The measures above for one series (t/T, p/(rho g H))."""
    w = window(t_over_T, *IMPACT)
    i = int(np.argmax(np.where(w, p_over, -np.inf)))
    wp = window(t_over_T, *PLATEAU)
    plateau = float(np.trapz(p_over[wp], t_over_T[wp]) / (t_over_T[wp][-1] - t_over_T[wp][0]))
    rc = window(ref["t"], *COMPARE) & (ref["t"] <= t_over_T[-1])
    on_ref = np.interp(ref["t"][rc], t_over_T, p_over)
    rms = float(np.sqrt(np.mean((on_ref - ref["median"][rc]) ** 2)))
    inside = float(np.mean((on_ref >= ref["p2.5"][rc]) & (on_ref <= ref["p97.5"][rc])))
    return {"peak": float(p_over[i]), "t_peak": float(t_over_T[i]), "plateau": plateau, "rms": rms, "in_band": inside}


def smoothed_reference(ref, width):
    """The reference with each percentile curve given the same centred mean."""
    out = {"t": ref["t"]}
    for key in ("p2.5", "median", "p97.5"):
        out[key] = centred_mean(ref["t"] * T, ref[key], width)
    return out


def read_run(run_dir):
    import h5py
    import yaml
    os.environ.setdefault("HDF5_USE_FILE_LOCKING", "FALSE")
    with open(os.path.join(run_dir, "scene.resolved.yaml")) as f:
        scene = yaml.safe_load(f)
    with h5py.File(os.path.join(run_dir, "series.h5"), "r") as f:
        g = f["probes"]
        probes = {k: g[k][:] for k in g.keys()}
        energy = f["energy"]
        wall = float(energy["wall_time"][-1]) if "wall_time" in energy else float("nan")
        steps = int(energy["steps"][-1]) if "steps" in energy else 0
    return scene, probes, wall, steps


def finished(run_dir):
    """A run that reached its end time logs 'simulated T s in N steps'."""
    try:
        with open(os.path.join(run_dir, "log.txt")) as f:
            return any(line.startswith("simulated ") for line in f)
    except OSError:
        return False


def scene_counts(run_dir):
    """(fluid particles, threads) from the run's log line
    "2D scene '..': N fluid, M boundary particles, K threads"; 0 where absent."""
    found = {}
    try:
        with open(os.path.join(run_dir, "log.txt")) as f:
            for line in f:
                words = line.replace(",", " ").split()
                for count, noun in zip(words, words[1:]):
                    if count.isdigit() and noun in ("fluid", "threads"):
                        found.setdefault(noun, int(count))
    except OSError:
        pass
    return found.get("fluid", 0), found.get("threads", 0)


def finished_runs(run_dirs):
    """(run, scene, probes, wall, steps) for each run that reached its end time."""
    for run in run_dirs:
        if not finished(run):
            print("skipped (the run did not finish: see its log.txt): %s" % run)
            continue
        yield (run,) + read_run(run)


def report(out, run_dirs):
    ref = load_reference()
    ref_m = measures(ref["t"], ref["median"], ref)
    wr = window(ref["t"], *IMPACT)
    band = (float(ref["p2.5"][wr].max()), float(ref["p97.5"][wr].max()))
    rows, curves = [], []
    for run, scene, probes, wall, steps in finished_runs(run_dirs):
        dx = scene["resolution"]["dx"]
        tag = " + shifting" if "particle_shifting" in scene.get("effects", []) else ""
        width = 4.0 * H / scene["fluid"]["sound_speed"]
        t = probes["time"] / T
        smooth = {}
        for est in ESTIMATES:
            raw = probes["P2_" + est] / PSCALE
            smooth[est] = centred_mean(probes["time"], raw, width)
            for label, series, against in (("raw", raw, ref), ("mean %.0f ms" % (1e3 * width), smooth[est],
                                                                     smoothed_reference(ref, width))):
                rows.append((dx, scene_counts(run)[0], steps, wall, est + ", " + label + tag, measures(t, series, against),
                             measures(against["t"], against["median"], against)))
        curves.append((dx, t, smooth["interpolated"], smooth["reaction"], width, tag))
    lines = [
        "Sensor 2 (z = 15 mm), p / (rho g H) against Lobovsky et al. (2014), H = 300 mm.",
        "Median of the experiment: peak %.2f (band of the peak %.2f-%.2f) at t/T = %.2f, plateau %.3f."
        % (ref_m["peak"], band[0], band[1], ref_m["t_peak"], ref_m["plateau"]),
        "In brackets: the median measured the same way (for the mean rows, the median given the same mean).",
        "",
        "| dx [m] | H/dx | fluid particles | steps | wall [s] | estimate | peak | peak vs median | t/T of peak | plateau "
        "(t/T 3.5-5.5) | RMS vs median (t/T 1.8-7) | time in 2.5-97.5 % band |",
        "|---:|---:|---:|---:|---:|---|---:|---:|---:|---:|---:|---:|",
    ]
    for dx, n, steps, wall, est, m, rm in rows:
        lines.append("| %g | %.0f | %s | %s | %.0f | %s | %.2f (%.2f) | %+.0f%% | %.3f (%.3f) | %.3f (%.3f) | %.3f | %.0f%% |" % (
            dx, H / dx, "{:,}".format(n) if n else "-", "{:,}".format(steps), wall, est, m["peak"], rm["peak"],
            100.0 * (m["peak"] / rm["peak"] - 1.0), m["t_peak"], rm["t_peak"], m["plateau"], rm["plateau"], m["rms"],
            100.0 * m["in_band"]))
    text = "\n".join(lines) + "\n"
    with open(out + ".md", "w") as f:
        f.write(text)
    print(text)
    plot(out + ".png", smoothed_reference(ref, curves[0][4]), curves)


def ensemble(out, run_dirs):
    """Peak and plateau (centred 4 H / c_s means) per member and over the members."""
    ref = load_reference()
    members, curves = [], []
    for run, scene, probes, wall, steps in finished_runs(run_dirs):
        width = 4.0 * H / scene["fluid"]["sound_speed"]
        t = probes["time"] / T
        smooth = {est: centred_mean(probes["time"], probes["P2_" + est] / PSCALE, width) for est in ESTIMATES}
        m = {est: measures(t, smooth[est], smoothed_reference(ref, width)) for est in ESTIMATES}
        method = scene.get("method", {})
        label = "%s, CFL %g, %d thread(s)" % (method.get("integrator", "predictor_corrector"), method.get("cfl", 0.5),
                                              scene_counts(run)[1])
        members.append((os.path.basename(os.path.normpath(run)), label, steps, wall, m))
        curves.append((scene["resolution"]["dx"], t, smooth["interpolated"], smooth["reaction"], width, " " + label))
    if not members:
        sys.exit("lobovsky_report.py ensemble: no finished run")
    sref = smoothed_reference(ref, curves[0][4])
    rm = measures(sref["t"], sref["median"], sref)
    cols = [(est, key) for est in ESTIMATES for key in ("peak", "plateau")]
    lines = ["Sensor 2, p / (rho g H), centred means over 4 H / c_s; dx = %g m. The median measured the same "
             "way: peak %.2f, plateau %.3f." % (curves[0][0], rm["peak"], rm["plateau"]), "",
             "| run | method | steps | wall [s] | " + " | ".join("%s %s" % c for c in cols) + " |",
             "|---|---|---:|---:|" + "---:|" * len(cols)]
    for name, label, steps, wall, m in members:
        lines.append("| %s | %s | %s | %.0f | " % (name, label, "{:,}".format(steps), wall) +
                     " | ".join("%.3f" % m[e][k] for e, k in cols) + " |")
    values = {c: np.array([m[c[0]][c[1]] for _, _, _, _, m in members]) for c in cols}
    for stat, f in (("mean", np.mean), ("standard deviation", np.std), ("lowest", np.min), ("highest", np.max)):
        lines.append("| %s of %d | | | | " % (stat, len(members)) + " | ".join("%.3f" % f(values[c]) for c in cols) + " |")
    text = "\n".join(lines) + "\n"
    with open(out + ".md", "w") as fh:
        fh.write(text)
    print(text)
    plot(out + ".png", sref, curves, colour="0.35")


def plot(path, ref, curves, colour=None):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(2, 1, figsize=(9, 7), sharex=True)
    for ax, col, title in ((axes[0], 2, "interpolated 1.5 dx in front of the wall, centred mean over 4H/c_s"),
                           (axes[1], 3, "wall-particle reactions, centred mean over 4H/c_s")):
        ax.fill_between(ref["t"], ref["p2.5"], ref["p97.5"], color="0.8", label="Lobovsky et al. 2014, 2.5-97.5 % (same mean)")
        ax.plot(ref["t"], ref["median"], "k", lw=1.0, label="median")
        for c in curves:
            if colour:  # an ensemble: one colour, no legend entry per member
                ax.plot(c[1], c[col], lw=0.6, color=colour, alpha=0.7,
                        label="SPH runs, dx = %g m (%d)" % (c[0], len(curves)) if c is curves[0] else None)
            else:
                ax.plot(c[1], c[col], lw=0.8, label="dx = %g m (H/%.0f)%s" % (c[0], H / c[0], c[5]))
        ax.set_ylabel("p / (rho g H)")
        ax.set_title("sensor 2, z = 15 mm: " + title, fontsize=10)
        ax.set_ylim(-0.3, 3.0)
        ax.grid(alpha=0.3)
    axes[0].legend(fontsize=8, loc="upper right")
    axes[1].set_xlabel("t sqrt(g / H)")
    axes[1].set_xlim(1.5, 7.15)
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def main():
    if len(sys.argv) >= 3 and sys.argv[1] == "reference":
        write_reference(sys.argv[2], float(sys.argv[3]) if len(sys.argv) > 3 else None)
        return
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("mode", choices=["report", "ensemble"])
    ap.add_argument("--out", required=True)
    ap.add_argument("runs", nargs="+")
    a = ap.parse_args()
    (report if a.mode == "report" else ensemble)(a.out, a.runs)


if __name__ == "__main__":
    main()
