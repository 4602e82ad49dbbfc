#!/usr/bin/env python3
"""Window means of the floating sphere's draught error (cases/sphere_offset/floating_sphere_3d.yaml).

For each run directory: the mean of the eight gauges minus the sphere's centroid height plus R,
against R (Archimedes: a sphere of half the water's density floats with its centroid at the
surface), in 1 s windows from 0.5 s, with the sphere's height and the level. Shows when the
draught has settled, beside `moorsph study --metric relaxed_level` (docs/validation/sphere-offset.md).

  floating_draught.py RUN_DIR...
"""
import sys

import h5py
import numpy as np

R = 0.1015  # [m]

for run in sys.argv[1:]:
    with h5py.File(run + "/series.h5", "r") as f:
        t = f["gauges/time"][...]
        level = np.mean([f[f"gauges/G{k}"][...] for k in range(1, 9)], axis=0)
        y = np.interp(t, f["body_sphere/time"][...], f["body_sphere/y"][...])
    draught = level - y + R
    print(run)
    for start in np.arange(0.5, t[-1] - 0.01, 1.0):
        m = (t >= start) & (t < start + 1.0)
        print(f"  {start:.1f}-{start + 1:.1f} s: draught error {100 * (draught[m].mean() - R) / R:+.2f}%, "
              f"centroid {1e3 * y[m].mean():.2f} mm, level {1e3 * level[m].mean():.2f} mm")
