#!/usr/bin/env python3
"""When does the released light cylinder fall behind potential flow, and in what form?

Reads the series of runs of cases/floating_box/submerged_cylinder_2d.yaml and, for each,
the speed against potential flow's a0 t and the deficit impulse

    J(t) = (m + m_a) (a0 t - v(t))      [N s/m]

(what the fluid has taken from the body beyond the added-mass reaction of the tank's
potential flow, m_a = C_a rho pi R^2, C_a = 1.0547 from confined_added_mass.py). An added
mass too large from the start would make v / (a0 t) constant and J proportional to v; a
drag makes J grow as the integral of v|v|; a history force of Basset's form
b int v'(tau) / sqrt(t - tau) dtau makes it grow as b 2 int v'(tau) sqrt(t - tau) dtau.
Least-squares fits of each form (and of pairs) over 5-100 ms say which describes it.

    release_impulse.py RUN [RUN ...] [--release 0.3]
"""
import argparse

import h5py
import numpy as np

RHO, R, G, CA = 1000.0, 0.05, 9.81, 1.0547


def first_100ms(run, release):
    """Time since release and the cylinder's upward speed over the first 100 ms."""
    with h5py.File(run + "/series.h5", "r") as f:
        t = f["velocity_cylinder/time"][:]
        v = f["velocity_cylinder/vy"][:]
    w = (t >= release) & (t <= release + 0.1 + 1e-6)
    return t[w] - release, v[w]


def forms(tt, vv):
    """The regressors of the three forms, each a function of the speed history."""
    drag = np.concatenate([[0.0], np.cumsum(0.5 * (vv[1:] * abs(vv[1:]) + vv[:-1] * abs(vv[:-1])) * np.diff(tt))])
    dv, tm = np.diff(vv), 0.5 * (tt[1:] + tt[:-1])
    history = np.array([np.sum(dv[tm < T] * 2.0 * np.sqrt(T - tm[tm < T])) for T in tt])
    return {"extra mass [kg/m]": vv, "drag k [N s^2/m^3]": drag, "history b [N s^0.5/m^2]": history}


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("runs", nargs="+")
    p.add_argument("--release", type=float, default=0.3, help="release time [s]")
    p.add_argument("--mass", type=float, default=1.570796, help="body mass [kg/m] (density ratio 0.2)")
    a = p.parse_args()
    V = np.pi * R * R
    ma, r = CA * RHO * V, a.mass / (RHO * V)
    a0 = (1.0 - r) * G / (r + CA)
    print("a0 = %.4f m/s^2, m = %.4f kg/m, m_a = %.3f kg/m" % (a0, a.mass, ma))
    for run in a.runs:
        tt, vv = first_100ms(run, a.release)
        J = (a.mass + ma) * (a0 * tt - vv)
        print(run)
        print("  t [ms]  v/(a0 t)  J [N s/m]")
        for ms in (10, 20, 40, 60, 80, 100):
            i = np.argmin(abs(tt - ms / 1000.0))
            print("  %5d   %7.2f   %8.3f" % (ms, vv[i] / (a0 * tt[i]), J[i]))
        s = tt >= 0.005
        regs = forms(tt, vv)
        names = list(regs)
        for cols in ([0], [1], [2], [0, 1], [0, 2]):
            A = np.column_stack([regs[names[c]][s] for c in cols])
            c, *_ = np.linalg.lstsq(A, J[s], rcond=None)
            res = np.sqrt(np.mean((J[s] - A @ c) ** 2))
            print("  fit %-48s rms residual %.3f N s/m (J rms %.3f)" % (
                ", ".join("%s %.3g" % (names[k], x) for k, x in zip(cols, c)), res, np.sqrt(np.mean(J[s] ** 2))))


if __name__ == "__main__":
    main()
