#!/usr/bin/python3
"""horizontal_release_report.py on a damped oscillation with closed-form turns:
x - rest = A exp(-z w0 t') cos(wd t') from the release t' = t - 0.3 s, so the velocity
vanishes where tan(wd t') = -z w0 / wd: half a damped period apart, each turn
exp(-z w0 pi / wd) of the one before, and the crossings of the rest at wd t' = pi/2 + k pi."""
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "..", "cases", "tethered_buoy"))
import horizontal_release_report as hr  # noqa: E402

failures = []


def near(label, got, want, tol):
    if not abs(got - want) <= tol:
        failures.append(f"{label}: got {got}, want {want} +- {tol}")


rest, release, A, w0, z = 0.746, 0.3, 0.508, 2 * np.pi / 5.0, 0.3
wd = w0 * np.sqrt(1 - z * z)
t = np.arange(0.0, 12.0, 0.001)
tp = np.maximum(t - release, 0.0)
x = rest + A * np.exp(-z * w0 * tp) * np.cos(wd * tp)
v = np.gradient(x, t)
v[t <= release] = 0.0
r = hr.analyse(t, x, v, rest, release)
near("release offset", r["start"], A, 1e-9)
near("number of turns in 12 s", len(r["turns"]), 4, 0)
phase = np.arctan2(-z * w0, wd) + np.pi  # first turn: wd t' = pi - atan(z w0 / wd)
near("first turn time", r["turns"][0][0], release + phase / wd, 0.002)
for k, h in enumerate(r["half_periods_turns"]):
    near(f"half period between turns {k}", h, np.pi / wd, 0.002)
for k, h in enumerate(r["half_periods_crossings"]):
    near(f"half period between crossings {k}", h, np.pi / wd, 1e-4)
near("first crossing", r["crossings"][0], release + 0.5 * np.pi / wd, 1e-4)
for k, ratio in enumerate(r["decay"][1:]):
    near(f"decay per half cycle {k + 1}", ratio, np.exp(-z * w0 * np.pi / wd), 1e-3)
near("turns alternate in sign", float(np.prod(np.sign([d for _, d in r["turns"][:2]]))), -1.0, 0)

if failures:
    print("\n".join(failures))
    sys.exit(1)
print(f"horizontal_release_report: {len(r['turns'])} turns, half period {np.pi / wd:.4f} s, decay "
      f"{np.exp(-z * w0 * np.pi / wd):.4f} per half cycle, as expected")
