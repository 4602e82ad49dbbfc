#!/usr/bin/env python3
"""METHOD.md 6.2c report for the tethered buoy in regular waves.

  buoy_waves_report.py RUN_DIR --period T --amplitude A [--depth 0.8] [--from T0] [--out PNG]

Reads RUN_DIR/series.h5 (body_buoy, line_tether) and writes the heave and surge in the
non-dimensional form of METHOD.md 6.2c against t* = t/T:
  y* = (y - y_e)/a,  x* = (x - x_e) d/(a lambda),
with (x_e, y_e) the buoy's rest position (the first sample, before the waves reach it) and
lambda from the linear dispersion relation. Prints, over the window [T0, end] (default the
last five periods): heave and surge half peak-to-peak in those units, the mean surge offset
x_mean - x_e [m], and the tether's mean and largest tension [N] and the fraction of samples
it is slack.
"""
import argparse
import math

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

G = 9.81


def wavelength(period, depth):
    """Linear dispersion omega^2 = g k tanh(k d), Newton from the deep-water guess."""
    omega = 2.0 * math.pi / period
    k = omega * omega / G
    for _ in range(50):
        f = G * k * math.tanh(k * depth) - omega * omega
        df = G * math.tanh(k * depth) + G * k * depth / math.cosh(k * depth) ** 2
        k -= f / df
    return 2.0 * math.pi / k


def period_amplitude(t, v, period, t0):
    """Mean over the whole periods after t0 of half of (max - min) within each period."""
    halves = []
    start = t0
    while start + period <= t[-1] + 1e-9:
        m = (t >= start) & (t < start + period)
        if m.sum() > 2:
            halves.append(0.5 * (v[m].max() - v[m].min()))
        start += period
    return float(np.mean(halves)) if halves else float("nan")


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("run")
    p.add_argument("--period", type=float, required=True)
    p.add_argument("--amplitude", type=float, required=True)
    p.add_argument("--depth", type=float, default=0.8)
    p.add_argument("--from", dest="t0", type=float, default=None)
    p.add_argument("--out", default=None)
    a = p.parse_args()
    lam = wavelength(a.period, a.depth)
    with h5py.File(f"{a.run}/series.h5", "r") as f:
        t = f["body_buoy/time"][:]
        x, y = f["body_buoy/x"][:], f["body_buoy/y"][:]
        tension = f["line_tether/fairlead_tension"][:]
        slack = f["line_tether/slack"][:]
        gauges = {}
        if "gauges" in f:
            tg = f["gauges/time"][:]
            gauges = {k: f[f"gauges/{k}"][:] for k in f["gauges"].keys() if k != "time"}
    x_e, y_e = x[0], y[0]
    xs = (x - x_e) * a.depth / (a.amplitude * lam)
    ys = (y - y_e) / a.amplitude
    ts = t / a.period
    t0 = a.t0 if a.t0 is not None else t[-1] - 5.0 * a.period
    w = t >= t0
    print(f"T = {a.period} s, a = {a.amplitude} m, d = {a.depth} m, lambda = {lam:.4f} m; window {t0:.2f}-{t[-1]:.2f} s")
    heave = period_amplitude(t, y, a.period, t0)
    print(f"heave y*: half peak-to-peak {0.5 * (ys[w].max() - ys[w].min()):.3f}; "
          f"mean per-period half height {heave / a.amplitude:.3f}")
    for name, eta in gauges.items():
        amp = period_amplitude(tg, eta, a.period, t0)
        print(f"gauge {name}: wave amplitude (mean per-period half height) {amp:.4f} m = {amp / a.amplitude:.3f} "
              f"of the requested; heave / this amplitude {heave / amp:.3f}")
    print(f"surge x*: half peak-to-peak {0.5 * (xs[w].max() - xs[w].min()):.3f}; "
          f"mean offset {np.mean(x[w]) - x_e:+.4f} m")
    print(f"tether: mean {np.mean(tension[w]):.3f} N, largest {np.max(tension[w]):.3f} N, "
          f"slack {100.0 * np.mean(slack[w]):.1f}% of samples")
    fig, ax = plt.subplots(2, 1, sharex=True, figsize=(8, 6))
    ax[0].plot(ts, ys)
    ax[0].set_ylabel("heave y* = (y - y_e)/a")
    ax[1].plot(ts, xs)
    ax[1].set_ylabel("surge x* = (x - x_e) d/(a lambda)")
    ax[1].set_xlabel("t* = t/T")
    ax[0].set_title(f"tethered buoy in regular waves, T = {a.period} s, a = {a.amplitude} m")
    fig.tight_layout()
    out = a.out or f"{a.run}/buoy_waves.png"
    fig.savefig(out, dpi=120)
    print(f"plot: {out}")


if __name__ == "__main__":
    main()
