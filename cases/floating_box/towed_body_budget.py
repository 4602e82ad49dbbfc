#!/usr/bin/env python3
"""The water next to a towed cylinder, from `moorsph_towed_body ... dump=S` output.

For the particles of the first three layers (gap to the surface 0-1, 1-2, 2-3 dx) in the
front, side and back sectors (45 degrees wide, counted from the direction of motion), prints
their mean pressure, the kernel moment M = sum_j V_j r_ji (x) grad_i W_ij along the surface
normal (M_nn) and along the surface (M_tt) (about 0.95 in a full neighbourhood: how full it
is), and for the first layer the budget along the outward normal of METHOD.md 1-2: the
pressure sum split into its P_i part -P_i/rho_i^2 sum_j m_j grad_i W_ij and its P_j part,
the wall law of the body's particles (reference form), and gravity. The body's particles
come from the '# wall' lines, so the tank walls are left out: use it for the particles near
the body only (the dump covers 3 R). Neighbours beyond the dump's 3 R are missing, so
particles farther than 2.4 R from the centre are skipped.

  towed_body_budget.py OUTPUT [--down] [--dx 0.005] [--radius 0.05] [--h-factor 1.2]
      [--cs-factor 10] [--depth 0.5] [--boff 0.5] [--strength 0.01]

--down: the body was moving down (the front is the bottom). The defaults are the program's.
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from near_body_flow import wall_shape, wendland_gradient_2d  # noqa: E402  (same kernel and wall law)

G = 9.81
RHO0 = 1000.0


def wendland_gradient(rij, h):
    """grad_i W_ij of the 2D Wendland C2 kernel for rows rij = r_i - r_j."""
    r = np.linalg.norm(rij, axis=1)
    return (wendland_gradient_2d(r, h) / r)[:, None] * rij


def read_dump(path):
    fluid, wall = [], []
    with open(path) as f:
        for line in f:
            if line.startswith("# dump ") and not line.startswith("# dump at"):
                fluid.append(line.split()[2:])
            elif line.startswith("# wall "):
                wall.append(line.split()[2:])
    if not fluid or not wall:
        raise SystemExit(f"{path}: no '# dump' or '# wall' lines (run moorsph_towed_body with dump=S)")
    return np.array(fluid, float), np.array(wall, float)


def wall_push(x_i, wall, a):
    """Acceleration of a fluid particle at x_i by the body's particles (reference law)."""
    rik = x_i - wall[:, :2]
    nk = wall[:, 2:]
    perp = (rik * nk).sum(axis=1)
    par = np.abs(rik[:, 0] * nk[:, 1] - rik[:, 1] * nk[:, 0])
    q = (np.maximum(perp, 0.0) + a.boff * a.dx) / a.h
    reach = np.linalg.norm(rik, axis=1) < 2.0 * a.h
    weight = np.clip(1.0 - par / a.dx, 0.0, None) * reach * wall_shape(q)
    return (a.strength * a.cs**2 / a.h * weight)[:, None] * nk


def particle_terms(i, x, rho, p, wall, a):
    """Kernel moment and, along the outward normal, the budget of particle i."""
    m = RHO0 * a.dx * a.dx
    rij = x[i] - x
    d = np.linalg.norm(rij, axis=1)
    nb = (d < 2.0 * a.h) & (d > 0.0)
    grad = wendland_gradient(rij[nb], a.h)
    volume = m / rho[nb]
    moment = np.einsum("j,ja,jb->ab", volume, -rij[nb], grad)
    normal = x[i] / np.linalg.norm(x[i])
    tangent = np.array([-normal[1], normal[0]])
    own = -(p[i] / rho[i] ** 2) * m * grad.sum(axis=0)
    others = -(m * (p[nb] / rho[nb] ** 2)[:, None] * grad).sum(axis=0)
    push = wall_push(x[i], wall, a).sum(axis=0)
    return [p[i], normal @ moment @ normal, tangent @ moment @ tangent,
            own @ normal, others @ normal, push @ normal, -G * normal[1]]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("output")
    ap.add_argument("--down", action="store_true")
    ap.add_argument("--dx", type=float, default=0.005)
    ap.add_argument("--radius", type=float, default=0.05)
    ap.add_argument("--h-factor", type=float, default=1.2)
    ap.add_argument("--cs-factor", type=float, default=10.0)
    ap.add_argument("--depth", type=float, default=0.5)
    ap.add_argument("--boff", type=float, default=0.5)
    ap.add_argument("--strength", type=float, default=0.01)
    a = ap.parse_args()
    a.h = a.h_factor * a.dx
    a.cs = a.cs_factor * np.sqrt(2.0 * G * a.depth)

    fluid, wall = read_dump(a.output)
    x, rho, p = fluid[:, :2], fluid[:, 4], fluid[:, 5]
    r = np.linalg.norm(x, axis=1)
    gap = (r - a.radius) / a.dx
    ahead = x[:, 1] * (-1.0 if a.down else 1.0) / r  # cosine of the angle from the motion
    sectors = {"front": ahead > np.cos(np.pi / 8), "side": np.abs(ahead) < np.sin(np.pi / 8),
               "back": ahead < -np.cos(np.pi / 8)}
    print("sector layer  n   p [Pa]  M_nn  M_tt | first layer along the normal [m/s^2]: P_i part  P_j part  wall  gravity  sum")
    for name, in_sector in sectors.items():
        for layer in range(3):
            chosen = np.where(in_sector & (gap >= layer) & (gap < layer + 1) & (r < 2.4 * a.radius))[0]
            if chosen.size == 0:
                continue
            t = np.array([particle_terms(i, x, rho, p, wall, a) for i in chosen]).mean(axis=0)
            line = f"{name:6s} {layer + 1:5d} {chosen.size:3d} {t[0]:8.0f} {t[1]:5.2f} {t[2]:5.2f}"
            if layer == 0:
                line += f" | {t[3]:9.1f} {t[4]:9.1f} {t[5]:7.1f} {t[6]:7.2f} {t[3:].sum():6.2f}"
            print(line)


if __name__ == "__main__":
    main()
