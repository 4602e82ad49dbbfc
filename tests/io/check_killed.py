#!/usr/bin/python3
"""Reads the run directory of a moorsph run killed with SIGKILL: everything flushed up
to its last output must be readable.

Usage: check_killed.py RUN_DIR
Exit 0: readable; 77: h5py is not available (the test skips); 1: a check failed.
"""
import os
import sys
import xml.etree.ElementTree as ET

try:
    import h5py
    import numpy as np
except ImportError as error:
    print(f"h5py not available in {sys.executable}: {error}")
    sys.exit(77)

run = sys.argv[1]
failures = []

with h5py.File(os.path.join(run, "series.h5"), "r") as f:
    lengths = {f"{g}/{d}": f[g][d].shape[0] for g in f for d in f[g]}
    rows = min(lengths.values())
    if rows < 2:
        failures.append(f"series.h5 holds fewer than 2 complete rows: {lengths}")
    for g in f:
        t = f[g]["time"][:rows]
        if not np.all(np.diff(t) > 0):
            failures.append(f"/{g}/time does not increase")
        for d in f[g]:
            if not np.all(np.isfinite(f[g][d][:rows])):
                failures.append(f"/{g}/{d} has non-finite values")
    print(f"series.h5: {rows} rows up to t = {f['energy/time'][rows - 1]:.4f} s")

grids = ET.parse(os.path.join(run, "particles.xmf")).getroot().findall("./Domain/Grid/Grid")
with h5py.File(os.path.join(run, "particles.h5"), "r") as f:
    for grid in grids:  # every snapshot the XDMF file lists is complete
        for item in grid.iter("DataItem"):
            path = item.text.split(":", 1)[1]
            shape = tuple(int(n) for n in item.get("Dimensions").split())
            if path not in f or f[path].shape != shape:
                failures.append(f"particles.xmf lists {path} {shape}, particles.h5 does not hold it")
            elif not np.all(np.isfinite(f[path][...])):
                failures.append(f"{path} has non-finite values")
    print(f"particles.xmf: {len(grids)} snapshots readable")
if len(grids) < 1:
    failures.append("no particle snapshot listed")
if failures:
    print("FAILED:\n  " + "\n  ".join(failures))
    sys.exit(1)
