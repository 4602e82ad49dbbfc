#!/usr/bin/python3
"""Peregrine breather runs (METHOD.md 6.4) against theory: a table and a plot.

usage: peregrine_report.py --out PREFIX --theory-stem STEM RUN_DIR [RUN_DIR ...]

Each RUN_DIR is a `moorsph run` directory of a cases/peregrine scene (its
scene.resolved.yaml gives the piston, the breather and the gauges). STEM_theory_x<d>.csv
is the breather's own surface d metres from the piston, written by
`moorsph_breather_signal ... --theory-at d1,d2,.. --theory-level DEPTH` (d as the gauge's x
minus the piston's rest x, formatted with %g; the level is the still depth over a floor at
y = 0, as in the cases/peregrine scenes, and is taken off again here). Writes PREFIX.md (the table) and PREFIX.png (gauge series with
the theory overlaid), and prints the table.

Per gauge and run, measured on the gauge minus the still level (its mean over the first
0.3 s), from focus_time - 6 s to the run's end (the event), the same way on the theory:
- crest: the largest elevation, / a0 (theory: 3 at the focus for order 1, 5 for order 2);
- arrival: the time of the envelope's peak, the largest moving mean of eta^2 over one
  carrier period, so the envelope's passage, not a single crest, is timed; the group
  speed is the slope of a straight line fitted to the distances of the gauges from the
  focus on against their arrivals (deep-water theory: omega0/2k0);
- rms: the RMS of run minus theory over the event window, / a0.
The theory is deep-water NLS; on the scenes' finite depth linear waves carry the envelope
at the finite-depth group speed, faster: "linear on depth d" is the envelope-peak time
of the theory at the gauge nearest the piston carried to each gauge by linear waves with
omega^2 = g k tanh(k d), frequency by frequency (deep-water transport reproduces the
NLS theory's times to 0.06 s).
Before the event, at the gauge nearest the piston: the carrier amplitude sqrt(2 mean
eta^2) over [ramp_up + 4 s, focus_time - 8 s], against the theory's over the same window.
"""
import argparse
import math
import os

import h5py
import numpy as np
import yaml

G = 9.81


def read_run(run_dir):
    os.environ.setdefault("HDF5_USE_FILE_LOCKING", "FALSE")  # readable while a run writes
    with open(os.path.join(run_dir, "scene.resolved.yaml")) as f:
        scene = yaml.safe_load(f)
    with h5py.File(os.path.join(run_dir, "series.h5"), "r") as f:
        g = f["gauges"]
        t = g["time"][:]
        gauges = {k: g[k][:] for k in g.keys() if k != "time"}
        energy = f["energy"]
        wall = float(energy["wall_time"][-1]) if "wall_time" in energy else float("nan")
        steps = int(energy["steps"][-1]) if "steps" in energy else 0
    return scene, t, gauges, wall, steps


def read_theory(path):
    data = np.loadtxt(path, delimiter=",", skiprows=1)
    return data[:, 0], data[:, 1]


def envelope_peak_time(t, eta, period):
    """Time of the largest moving mean (one carrier period) of eta^2: the envelope's peak,
    refined by a parabola through the three samples around it."""
    dt = t[1] - t[0]
    n = max(1, int(round(period / dt)))
    e = np.convolve(eta * eta, np.ones(n) / n, mode="same")
    e[: n // 2] = e[-(n // 2) - 1:] = 0.0  # the mean is cut short at the ends
    i = int(np.argmax(e))
    if i == 0 or i == len(e) - 1:
        return float("nan")
    den = e[i - 1] - 2.0 * e[i] + e[i + 1]
    return float(t[i] + (0.5 * dt * (e[i - 1] - e[i + 1]) / den if den != 0.0 else 0.0))


def wave_number(omega, depth):
    """Finite-depth linear dispersion omega^2 = g k tanh(k d), by Newton from deep water."""
    k = np.maximum(omega * omega / G, 1e-12)
    for _ in range(60):
        th = np.tanh(k * depth)
        k = k - (G * k * th - omega * omega) / (G * th + G * k * depth * (1.0 - th * th))
    return k


def finite_depth_arrival(t, eta_from, distance, depth, period, t_from, t_to):
    """Envelope-peak time of the series eta_from carried `distance` downstream by linear
    waves on depth d, each frequency with its own k(omega): where finite depth alone (its
    group speed above deep water's) puts the envelope."""
    spectrum = np.fft.rfft(eta_from)
    omega = 2.0 * np.pi * np.fft.rfftfreq(len(eta_from), t[1] - t[0])
    moved = np.fft.irfft(spectrum * np.exp(-1j * wave_number(omega, depth) * distance), len(eta_from))
    window = (t >= t_from) & (t <= t_to)  # the event window, as for the run and the theory
    return envelope_peak_time(t[window], moved[window], period)


def carrier_amplitude(t, eta, t0, t1):
    sel = (t >= t0) & (t <= t1)
    return math.sqrt(2.0 * float(np.mean(eta[sel] ** 2))) if sel.any() else float("nan")


def analyse(run_dir, theory_stem):
    scene, t, gauges, wall, steps = read_run(run_dir)
    piston = scene["piston"]
    sig = piston["signal"]
    a0, k0, tf = sig["a0"], sig["k0"], sig["focus_time"]
    period = 2.0 * math.pi / math.sqrt(G * k0)
    x_piston = piston["x"]
    rows = []
    first = None  # the theory at the gauge nearest the piston, the start of the linear transport
    for gauge in scene["gauges"]:
        name = gauge["name"]
        dist = gauge["x"] - x_piston
        tt, surface = read_theory("%s_theory_x%g.csv" % (theory_stem, round(dist, 6)))
        eta_th = surface - sig["depth"]
        eta = gauges[name] - np.mean(gauges[name][t <= 0.3])
        th = np.interp(t, tt, eta_th)
        event = t >= tf - 6.0
        if first is None:
            first = (dist, tt, eta_th)
        span = (tt >= 0.0) & (tt <= 2.0 * tf)
        rows.append({
            "gauge": name, "distance": dist, "t": t, "eta": eta, "theory": th,
            "crest": eta[event].max() / a0, "crest_theory": th[event].max() / a0,
            "arrival": envelope_peak_time(t[event], eta[event], period),
            "arrival_theory": envelope_peak_time(tt[(tt >= tf - 6.0) & (tt <= t[-1])],
                                                 eta_th[(tt >= tf - 6.0) & (tt <= t[-1])], period),
            "arrival_linear_depth": finite_depth_arrival(tt[span], first[2][span], dist - first[0], sig["depth"], period,
                                                         tf - 6.0, t[-1]),
            "rms": math.sqrt(float(np.mean((eta[event] - th[event]) ** 2))) / a0,
            "carrier": carrier_amplitude(t, eta, sig["ramp_up"] + 4.0, tf - 8.0) / a0,
            "carrier_theory": carrier_amplitude(t, th, sig["ramp_up"] + 4.0, tf - 8.0) / a0,
        })
    return {"dir": run_dir, "dx": scene["resolution"]["dx"], "order": sig["order"], "a0": a0, "k0": k0,
            "focus_time": tf, "focus_distance": sig["focus_distance"], "period": period, "end": float(t[-1]),
            "wall": wall, "steps": steps, "rows": rows}


def group_speed(rows, key, focus_distance):
    past = [r for r in rows if r["distance"] >= focus_distance - 1e-9 and not math.isnan(r[key])]
    if len(past) < 2:
        return float("nan")
    return float(np.polyfit([r[key] for r in past], [r["distance"] for r in past], 1)[0])


def particles_of(run_dir):
    try:
        with open(os.path.join(run_dir, "log.txt")) as f:
            for line in f:
                if "fluid" in line and "particles" in line:
                    for word in line.replace(",", " ").split():
                        if word.isdigit():
                            return int(word)
    except OSError:
        pass
    return 0


def table(results):
    out = []
    for r in results:
        cg_th = 0.5 * math.sqrt(G * r["k0"]) / r["k0"]
        out.append("### order %d, dx = %g m (a0/dx = %.1f): %s fluid particles, %d steps, %.0f s wall, to t = %.1f s\n"
                   % (r["order"], r["dx"], r["a0"] / r["dx"], format(particles_of(r["dir"]), ","), r["steps"],
                      r["wall"], r["end"]))
        out.append("| gauge | from piston [m] | crest / a0 (theory) | arrival [s] (theory; linear on depth d) | RMS error / a0 | carrier before the event / a0 (theory) |")
        out.append("|---|---:|---|---|---:|---|")
        for g in r["rows"]:
            out.append("| %s | %.2f | %.2f (%.2f) | %.2f (%.2f; %.2f) | %.3f | %.3f (%.3f) |" % (
                g["gauge"], g["distance"], g["crest"], g["crest_theory"], g["arrival"], g["arrival_theory"],
                g["arrival_linear_depth"],
                g["rms"], g["carrier"], g["carrier_theory"]))
        out.append("\nGroup speed from the arrivals at the gauges from the focus on: %.3f m/s (the theory's "
                   "series measured the same way: %.3f m/s, carried by linear waves on the depth: %.3f m/s; deep-water "
                   "omega0/2k0 = %.3f m/s).\n"
                   % (group_speed(r["rows"], "arrival", r["focus_distance"]),
                      group_speed(r["rows"], "arrival_theory", r["focus_distance"]),
                      group_speed(r["rows"], "arrival_linear_depth", r["focus_distance"]), cg_th))
    return "\n".join(out)


def plot(results, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    names = [g["gauge"] for g in results[0]["rows"]]
    fig, axes = plt.subplots(len(names), 1, figsize=(10, 2.0 * len(names)), sharex=True)
    r0 = results[0]
    for ax, name in zip(np.atleast_1d(axes), names):
        first = next(g for g in r0["rows"] if g["gauge"] == name)
        sel = first["t"] >= r0["focus_time"] - 8.0
        ax.plot(first["t"][sel], first["theory"][sel] / r0["a0"], "k-", lw=1.2, label="Peregrine theory")
        for r in results:
            g = next(g for g in r["rows"] if g["gauge"] == name)
            s = g["t"] >= r0["focus_time"] - 8.0
            ax.plot(g["t"][s], g["eta"][s] / r["a0"], lw=0.9, label="SPH dx = %g m" % r["dx"])
        ax.set_ylabel("%s\neta / a0" % name)
        ax.text(0.01, 0.85, "%.2f m from the piston" % first["distance"], transform=ax.transAxes, fontsize=8)
        ax.grid(alpha=0.3)
    np.atleast_1d(axes)[0].legend(fontsize=8, loc="upper right", ncol=len(results) + 1)
    np.atleast_1d(axes)[-1].set_xlabel("t [s]")
    fig.suptitle("Peregrine breather, order %d (a0 = %g m, k0 = %g rad/m), focus %g m from the piston at t = %g s"
                 % (r0["order"], r0["a0"], r0["k0"], r0["focus_distance"], r0["focus_time"]))
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--out", required=True)
    p.add_argument("--theory-stem", required=True)
    p.add_argument("runs", nargs="+")
    a = p.parse_args()
    results = [analyse(d, a.theory_stem) for d in a.runs]
    text = table(results)
    print(text)
    with open(a.out + ".md", "w") as f:
        f.write(text + "\n")
    plot(results, a.out + ".png")


if __name__ == "__main__":
    main()
