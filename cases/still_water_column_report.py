#!/usr/bin/python3
"""How a still-water column run sinks (cases/still_water_column_132m_3d.yaml), per run directory:

- the surface layer: the mean height change of the particles that start in the top 12 m, at
  each particle snapshot, and its rate (least squares over the snapshots from 10 s on), which
  is what a floating body resting on the water feels;
- the bulk strain: the slope of the height change against the starting height over 20-110 m
  (negative: the column compresses), from the first to the last snapshot;
- the fluid's kinetic energy over the last 5 s (the noise).

    /usr/bin/python3 cases/still_water_column_report.py RUN_DIR [RUN_DIR ...]

Reads RUN_DIR/particles.h5 and RUN_DIR/series.h5 (set HDF5_USE_FILE_LOCKING=FALSE while a run
is still writing them).
"""
import sys

import h5py
import numpy as np


def snapshots(run):
    group = h5py.File(f"{run}/particles.h5", "r")["snapshots"]
    for key in sorted(group.keys()):
        snap = group[key]
        order = np.argsort(snap["id"][:])
        yield float(snap.attrs.get("time", 0.0)), snap["position"][:][order]


def report(run):
    snaps = list(snapshots(run))
    t0, r0 = snaps[0]
    top = r0[:, 1] > r0[:, 1].max() - 12.0
    bulk = (r0[:, 1] >= 20.0) & (r0[:, 1] <= 110.0)
    times = np.array([t for t, _ in snaps])
    sink = np.array([np.mean(r[top, 1] - r0[top, 1]) for _, r in snaps])
    late = times >= 9.9
    rate = np.polyfit(times[late], sink[late], 1)[0] if late.sum() > 1 else float("nan")
    r_end = snaps[-1][1]
    strain = np.polyfit(r0[bulk, 1], r_end[bulk, 1] - r0[bulk, 1], 1)[0]
    energy = h5py.File(f"{run}/series.h5", "r")["energy"]
    t, kinetic = energy["time"][:], energy["kinetic"][:]
    ke = kinetic[t >= t[-1] - 5.0].mean()
    at = " ".join(f"{ti:.0f} s {s:+.3f}" for ti, s in zip(times, sink) if ti > 0)
    print(f"{run}: surface layer [m] {at} | rate from 10 s {rate * 1e3:+.2f} mm/s | "
          f"bulk strain {strain:+.2e} | KE over the last 5 s {ke:.2e} J")


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    for run in sys.argv[1:]:
        report(run)
