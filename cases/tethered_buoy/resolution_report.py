#!/usr/bin/python3
"""Vertical release of the tethered lab buoy at several resolutions: table and plots.

usage: resolution_report.py OUT NAME [NAME ...]
Reads OUT/NAME.txt (the summary moorsph_tethered_buoy prints) and OUT/NAME.csv (its time
series) for each run, coarsest first, and writes OUT/report.md and OUT/report.png.

Measured on the heave from the nominal rest: the first overshoot (the largest heave of
the first half period after the buoy comes up through its rest), the first trough after
it, the period (twice the time between them), and the rest offset (mean heave over the
last 0.5 s, runs of 3 s or more). The reference for each is the least-squares order-2 fit
f = f0 + C dx^2 over all runs when there are four or more, else the Richardson extrapolate of
the three finest runs (Roache 1998: p = ln((f3 - f2)/(f2 - f1)) / ln r for a constant ratio r; here the
ratios differ, so p is found by bisection on the generalised relation of Celik et al.
2008, J. Fluids Eng. 130:078001, eqs. 3-4), when the three converge monotonically.
"""
import math
import os
import sys

import numpy as np


def summary(path):
    out = {}
    with open(path) as f:
        for line in f:
            if line.startswith("period_s="):
                for item in line.split():
                    if "=" in item:
                        k, v = item.split("=", 1)
                        out[k] = v
            elif line.startswith("# release="):
                out["header"] = line[2:].strip()
    return out


def measures(csv):
    data = np.genfromtxt(csv, delimiter=",", names=True)
    t, y = data["t_s"], data["heave_m"]
    up = np.where((y[:-1] < 0.0) & (y[1:] >= 0.0))[0]
    if len(up) == 0:
        return None
    i0 = up[0]
    # first overshoot: the largest heave before it falls back through rest
    down = np.where((y[i0:-1] >= 0.0) & (y[i0 + 1:] < 0.0))[0]
    i1 = i0 + (down[0] + 1 if len(down) else len(y) - i0 - 1)
    k_peak = i0 + int(np.argmax(y[i0:i1 + 1]))
    up2 = np.where((y[i1:-1] < 0.0) & (y[i1 + 1:] >= 0.0))[0]
    i2 = i1 + (up2[0] + 1 if len(up2) else len(y) - i1 - 1)
    k_trough = i1 + int(np.argmin(y[i1:i2 + 1]))
    rest = float(np.mean(y[t >= t[-1] - 0.5]))
    return {"t": t, "heave": y, "peak": float(y[k_peak]), "t_peak": float(t[k_peak]), "trough": float(y[k_trough]),
            "t_trough": float(t[k_trough]), "period": 2.0 * float(t[k_trough] - t[k_peak]), "rest": rest}


def richardson(h, f):
    """Extrapolate f(h -> 0) from three (h coarse to fine), or None if not monotone."""
    (h1, h2, h3), (f1, f2, f3) = h, f
    e21, e32 = f2 - f1, f3 - f2
    if e21 == 0.0 or e32 == 0.0 or (e32 / e21) <= 0.0:
        return None, None
    r21, r32 = h1 / h2, h2 / h3

    def g(p):  # Celik et al. eq. 3 with s = sign(e32/e21) = 1
        return p - abs(math.log(abs(e21 / e32)) + math.log((r32 ** p - 1.0) / (r21 ** p - 1.0))) / math.log(r32)

    lo, hi = 0.05, 8.0
    if g(lo) * g(hi) > 0.0:
        return None, None
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if g(lo) * g(mid) <= 0.0:
            hi = mid
        else:
            lo = mid
    p = 0.5 * (lo + hi)
    return f3 + (f3 - f2) / (r32 ** p - 1.0), p


def order2_fit(h, f):
    """Least-squares f = f0 + C h^2 over every run: the extrapolate f0 and the largest
    residual. With four or more spacings it uses them all, where the three-point
    Richardson estimate is at the mercy of one run's scatter."""
    a = np.vstack([np.ones(len(h)), np.asarray(h) ** 2]).T
    coef, _, _, _ = np.linalg.lstsq(a, np.asarray(f), rcond=None)
    return float(coef[0]), float(np.max(np.abs(np.asarray(f) - a @ coef)))


def main():
    out, names = sys.argv[1], sys.argv[2:]
    runs = []
    for n in names:
        s = summary(os.path.join(out, n + ".txt"))
        m = measures(os.path.join(out, n + ".csv"))
        if not s or m is None:
            print("skipping %s (not finished)" % n)
            continue
        dx = float(s["header"].split("dx=")[1].split()[0])
        runs.append(dict(name=n, dx=dx, D_over=0.203 / dx, particles=int(s["particles"]), steps=int(s["steps"]),
                         wall=float(s["wall_s"]), **m))
    lines = ["| dx | fluid particles | steps | wall [s] | first overshoot [mm] | first trough [mm] | period [s] | rest offset [mm] |",
             "|---|---:|---:|---:|---:|---:|---:|---:|"]
    for r in runs:
        rest = "%+.1f" % (1e3 * r["rest"]) if r["t"][-1] >= 3.0 else "- (run < 3 s)"
        lines.append("| D/%.0f (%.1f mm) | %s | %s | %.0f | %+.1f | %+.1f | %.3f | %s |" % (
            r["D_over"], 1e3 * r["dx"], format(r["particles"], ","), format(r["steps"], ","), r["wall"],
            1e3 * r["peak"], 1e3 * r["trough"], r["period"], rest))
    extrap = {}
    reference = "the Richardson extrapolate"
    if len(runs) >= 3:
        h = [r["dx"] for r in runs[-3:]]
        for key in ("peak", "trough", "period"):
            extrap[key] = richardson(h, [r[key] for r in runs[-3:]])
        scale = {"peak": 1e3, "trough": 1e3, "period": 1.0}
        cells = []
        for key in ("peak", "trough", "period"):
            v, p = extrap[key]
            cells.append("n/a (not monotone)" if v is None else ("%+.1f (p = %.2f)" % (scale[key] * v, p) if key != "period"
                                                               else "%.3f (p = %.2f)" % (v, p)))
        lines.append("| Richardson (three finest) | | | | %s | %s | %s | |" % tuple(cells))
        if len(runs) >= 4:
            h = [r["dx"] for r in runs]
            fits = {key: order2_fit(h, [r[key] for r in runs]) for key in ("peak", "trough")}
            lines.append("| order-2 least-squares fit, all runs (largest residual) | | | | %+.1f (%.1f) | %+.1f (%.1f) | | |" % (
                1e3 * fits["peak"][0], 1e3 * fits["peak"][1], 1e3 * fits["trough"][0], 1e3 * fits["trough"][1]))
            extrap = {key: (fits[key][0], 2.0) for key in fits}
            reference = "the order-2 fit"
        lines.append("")
        lines.append("Error of each run against %s (where there is one):" % reference)
        lines.append("")
        lines.append("| dx | wall [s] | first overshoot | first trough | period |")
        lines.append("|---|---:|---:|---:|---:|")
        for r in runs:
            cells = []
            for key in ("peak", "trough", "period"):
                v, _ = extrap.get(key, (None, None))
                cells.append("-" if v is None else "%+.1f%%" % (100.0 * (r[key] - v) / abs(v)))
            lines.append("| D/%.0f | %.0f | %s | %s | %s |" % (r["D_over"], r["wall"], *cells))
    text = "\n".join(lines)
    print(text)
    with open(os.path.join(out, "report.md"), "w") as f:
        f.write(text + "\n")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (a, b) = plt.subplots(1, 2, figsize=(12, 4.5))
    for r in runs:
        a.plot(r["t"], 1e3 * r["heave"], lw=1.0, label="D/%.0f (%s particles, %.0f s)" % (
            r["D_over"], format(r["particles"], ","), r["wall"]))
    a.axhline(0.0, color="k", lw=0.5)
    a.set_xlabel("t after release [s]")
    a.set_ylabel("heave from the nominal rest [mm]")
    a.set_title("Tethered buoy, vertical release (0.6 x 0.6 m tank, 0.5 m deep)")
    a.legend(fontsize=8)
    a.grid(alpha=0.3)
    for key, label in (("peak", "first overshoot"), ("trough", "first trough"), ("period", "period")):
        v, _ = extrap.get(key, (None, None))
        if v is None:
            continue
        err = [abs(r[key] - v) / abs(v) for r in runs]
        b.loglog([r["wall"] for r in runs], err, "o-", label=label)
    b.set_xlabel("wall time [s] (one thread)")
    b.set_ylabel("|error| against " + reference)
    b.grid(alpha=0.3, which="both")
    b.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "report.png"), dpi=110)


if __name__ == "__main__":
    main()
