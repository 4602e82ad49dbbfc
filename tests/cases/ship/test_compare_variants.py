#!/usr/bin/python3
"""cases/ship/compare_variants.py and plot_ship_run.stitch on two synthetic run segments whose
answers are known in closed form (run by ctest as test_cases_ship_compare_variants).

Fairlead tension T(t) = max(0, 5 + 10 sin(2 pi t / 10)) MN on every line, sampled every
0.05 s: peaks of 15 MN at t = 2.5 + 10 k, zero (slack) where sin < -1/2, i.e. on
(5.833 + 10 k, 9.167 + 10 k), below 0.5 MN where sin < -0.45 (5.745-9.255 + 10 k), and
the steepest rise 10 MN x 2 pi / 10 s = 6.28 MN/s where sin crosses zero upwards (t = 10 k).
A spell is printed from its first sample to the first sample after it (5.85 and 9.2 s). The
second segment starts at 10 s and replaces the first one's rows from there on (a restart).
"""
import os
import sys
import tempfile

import h5py
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "..", "cases", "ship"))
import compare_variants as cv  # noqa: E402
import mean_levels as ml  # noqa: E402
from plot_ship_run import GROUPS, stitch  # noqa: E402

failures = []


def check(label, got, want):
    if got != want:
        failures.append(f"{label}: got {got!r}, want {want!r}")


def tension(t):
    return np.maximum(0.0, 5e6 + 10e6 * np.sin(2 * np.pi * t / 10.0))


def write_segment(path, t0, t1, offset):
    """A series.h5 over [t0, t1] with every column plot_ship_run reads; `offset` is added to
    the CoM height so that the stitch can be told which segment a row came from."""
    t = np.round(np.arange(t0, t1 + 1e-9, 0.05), 6)
    with h5py.File(path, "w") as f:
        for group, cols in GROUPS.items():
            g = f.create_group(group)
            g["time"] = t
            for c in cols:
                g[c] = np.zeros_like(t)
        for line in cv.LINES:
            f[line]["fairlead_tension"][...] = tension(t)
            f[line]["slack"][...] = (tension(t) == 0.0).astype(float)
        f["points_ship/com_y"][...] = 130.0 + offset + np.sin(t)
        f["body_ship/pitch"][...] = np.radians(3.0) * np.sin(t)
        f["wrench_ship/Fy"][...] = 5e8 + 1e7 * np.cos(t)
        vol = np.where(np.abs(t - 12.0) < 0.3, 100.0 * (1 - np.abs(t - 12.0) / 0.3), 0.0)
        f["green_water_ship/volume"][...] = vol
        for k in range(1, 5):
            f[f"probes/sensor{k}_interpolated_mean"][...] = 1e3 * k * (1 + np.sin(t))
        f["gauges/G150"][...] = 132.0 + 2.0 * np.sin(t)
        f["gauges/G200_side"][...] = 132.0 + 3.0 * np.sin(2 * np.pi * (t - 13.0) / 20.0 + np.pi / 2)
        f["gauges/G470"][...] = 132.0 - 0.01 * t  # a level falling 1 cm/s
        f["packing_probes/bulk_fore_xi_mean"][...] = 0.997 + 1e-4 * t  # the bulk packing 1e-4 per second


with tempfile.TemporaryDirectory() as d:
    first, second = os.path.join(d, "first"), os.path.join(d, "second")
    os.makedirs(first)
    os.makedirs(second)
    write_segment(os.path.join(first, "series.h5"), 0.0, 12.0, offset=100.0)  # overlapped after 10 s
    write_segment(os.path.join(second, "series.h5"), 10.0, 20.0, offset=0.0)
    s = stitch([first, second])
    t = s["points_ship"]["time"]
    check("stitched rows", len(t), 401)
    check("rows after 10 s come from the second segment", bool(np.all(s["points_ship"]["com_y"][t >= 10.0] < 140)), True)
    check("rows before 10 s from the first", bool(np.all(s["points_ship"]["com_y"][t < 10.0] > 220)), True)

    r = cv.rows(cv.window(s, 1.0, 20.0))
    check("fore: tension range", r["fore: tension range [MN]"], "0.0-15.0 (peak 2.5 s)")
    check("fore: slack", r["fore: slack [s]"], "5.8-9.2, 15.8-19.2")
    check("fore: below 0.5 MN", r["fore: below 0.5 MN [s]"], "5.8-9.3, 15.8-19.3")
    check("fore: fastest rise", r["fore: fastest rise [MN/s]"], "6.3 (10.0 s)")
    check("pitch", r["pitch [deg]"], "-3.0 / +3.0")
    check("green water", r["green water, most [m^3]"], "100 (12.0 s)")
    check("sensors", r["sensors 1-4, 0.3 s mean peak [kPa]"], "2 / 4 / 6 / 8")
    check("focus gauge", r["gauge at the focus, 200 m [m]"], "129.0-135.0 (crest 13.0 s)")

    # Window means over one whole period of the tension, 10 <= t < 20 s (the second
    # segment's rows): the tension's sampled mean is within 0.01 MN of its integral
    # (1 / 2 pi)(5 x 4 pi / 3 + 10 sqrt 3) = 10/3 + 5 sqrt(3) / pi; the falling gauge's mean is
    # its value at the samples' middle (14.975 s); CoM = 130 + the mean of sin t.
    m = ml.levels(s, 10.0, 20.0)
    tt = np.round(np.arange(10.0, 20.0 - 1e-9, 0.05), 6)  # the samples in [10, 20)
    check("mean tension over a period", round(m["fore"], 6), round(float(tension(tt).mean()) / 1e6, 6))
    check("mean tension near its integral", abs(m["fore"] - (10.0 / 3.0 + 5.0 * np.sqrt(3) / np.pi)) < 0.01, True)
    check("falling gauge", round(m["G470"], 4), round(132.0 - 0.01 * 14.975, 4))
    check("CoM from the second segment", round(m["CoM"], 6), round(130.0 + float(np.sin(tt).mean()), 6))
    check("windows", ml.parse_windows("20-30,60-100"), [(20.0, 30.0), (60.0, 100.0)])
    check("an empty window", np.isnan(ml.levels(s, 30.0, 40.0)["CoM"]), True)
    check("bulk packing, the window's middle sample", round(m["bulk_fore"], 6), round(0.997 + 1e-4 * 14.975, 6))

    # A run that stops inside the window (here at 20 s, window to 40 s) still compares;
    # one whose series end before the window's first second says so instead of failing
    # deep inside numpy.
    # T is 5 MN at 15 s, falls to 0 at 17.5 s and rises back to 5 MN at 20 s.
    check("a run that stops inside the window", cv.rows(cv.window(s, 15.0, 40.0))["fore: tension range [MN]"],
          "0.0-5.0 (peak 15.0 s)")
    try:
        cv.window(s, 19.5, 40.0, "short")
        failures.append("a window past the run's end: no error")
    except SystemExit as e:
        check("a window past the run's end names the run and its span",
              "short: its line_fore series cover 0.00-20.00 s" in str(e), True)

if failures:
    print("\n".join(failures))
    sys.exit(1)
print("compare_variants: stitching, peaks, slack and hanging spells, fastest rise, green water, sensors, gauges and window means as expected")
