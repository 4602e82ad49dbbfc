#!/usr/bin/env python3
"""Potential-flow added mass of a circle rising in a rectangular tank (2D), the reference of
cases/floating_box/submerged_cylinder_2d.yaml.

The unbounded circle has C_a = 1, but the tank's floor, walls and free surface change it: a
body released from rest starts an impulsive flow whose potential phi has dphi/dn = 0 on the
walls and floor, phi = 0 on the free surface (the pressure impulse vanishes there), and
dphi/dn = n_y on the body for unit upward speed. The added mass is then
m_a = -rho * integral over the body of phi n_y ds (n pointing out of the body), i.e. twice the
kinetic energy of the flow (Newman, Marine Hydrodynamics, 1977, ch. 4).

phi is solved by a direct boundary-element method with straight constant panels: for a
collocation point x on the boundary, phi(x)/2 = integral [G dphi/dn - phi dG/dn] ds with
G = -ln(r)/(2 pi) and n the outward normal of the fluid domain; the panel integrals are the
closed forms of ln r and of the subtended angle. A check in an almost unbounded box
(40 m tank) must return C_a = 1.

  confined_added_mass.py [--width 0.6] [--depth 0.5] [--radius 0.05] [--centre-height 0.2]
                         [--ratio 0.2] [--panels 400]

prints C_a, and the initial acceleration a0 = (1 - r) g / (r + C_a) of a body of density
ratio r, unbounded and confined.
"""
import argparse

import numpy as np

G = 9.81


def polygon_panels(points):
    """Closed polyline (counter-clockwise for the fluid on the left) -> panel ends a, b."""
    a = np.asarray(points)
    return a, np.roll(a, -1, axis=0)


def segment(p, q, n):
    t = (np.arange(n) / n)[:, None]
    return p + t * (q - p)


def panel_integrals(x, a, b):
    """For points x (M,2) and panels a->b (N,2): S = int G ds, D = int dG/dn ds (n = right of a->b)."""
    L = np.linalg.norm(b - a, axis=1)
    t = (b - a) / L[:, None]
    nrm = np.stack([t[:, 1], -t[:, 0]], axis=1)  # right-hand normal: outward for a CCW domain boundary
    d = x[:, None, :] - a[None, :, :]
    xi = np.einsum("mnk,nk->mn", d, t)   # along the panel
    eta = np.einsum("mnk,nk->mn", d, nrm)  # off the panel, positive on the normal's side
    s0, s1 = -xi, L[None, :] - xi        # panel ends relative to the foot of x
    small = np.abs(eta) < 1e-9 * L[None, :]  # on the panel's line (round-off exceeds 1e-14 L)
    eta_safe = np.where(small, 1.0, eta)

    def lnr_primitive(s):
        r2 = s * s + eta * eta
        with np.errstate(divide="ignore", invalid="ignore"):
            ln_term = np.where(r2 > 0, 0.5 * s * np.log(np.where(r2 > 0, r2, 1.0)), 0.0)
        return ln_term - s + np.where(small, 0.0, eta * np.arctan(s / eta_safe))

    int_ln_r = lnr_primitive(s1) - lnr_primitive(s0)
    S = -int_ln_r / (2.0 * np.pi)
    # dG/dn_y = (1/2pi) (x - y).n / r^2 = eta / (2 pi r^2); its integral is the subtended angle / 2pi
    angle = np.where(small, 0.0, np.arctan(s1 / eta_safe) - np.arctan(s0 / eta_safe))
    D = angle / (2.0 * np.pi)
    return S, D, nrm


def added_mass(width, depth, radius, centre, panels, wall_panel=None):
    """C_a of the circle (per unit length, over rho pi R^2) in the tank [0,width] x [0,depth]."""
    # C_a is scale-free; shrinking the tank to 0.1 keeps the single-layer operator away from
    # 2D BEM's degenerate scale (a boundary of logarithmic capacity 1, which makes it singular)
    scale = 0.1 / max(width, depth)
    width, depth, radius, centre = scale * width, scale * depth, scale * radius, scale * np.asarray(centre)
    wall_panel = wall_panel and scale * wall_panel
    h = wall_panel or 2.0 * np.pi * radius / panels  # default: wall panels as long as the body's
    nx, ny = max(4, int(round(width / h))), max(4, int(round(depth / h)))
    outer = np.vstack([segment(np.array([0.0, 0.0]), np.array([width, 0.0]), nx),
                       segment(np.array([width, 0.0]), np.array([width, depth]), ny),
                       segment(np.array([width, depth]), np.array([0.0, depth]), nx),
                       segment(np.array([0.0, depth]), np.array([0.0, 0.0]), ny)])
    surface = np.zeros(len(outer), bool)
    surface[nx + ny:2 * nx + ny] = True  # the top side: phi = 0
    theta = -2.0 * np.pi * np.arange(panels) / panels  # clockwise: the fluid is outside the circle
    circle = centre + radius * np.stack([np.cos(theta), np.sin(theta)], axis=1)
    a_o, b_o = polygon_panels(outer)
    a_c, b_c = polygon_panels(circle)
    a, b = np.vstack([a_o, a_c]), np.vstack([b_o, b_c])
    mid = 0.5 * (a + b)
    S, D, nrm = panel_integrals(mid, a, b)
    n_out = len(a_o)
    body = np.zeros(len(a), bool)
    body[n_out:] = True
    # known data: q = dphi/dn (outward of the fluid) on walls (0) and body (-n_body_y), phi = 0 on the surface
    q_known = np.zeros(len(a))
    q_known[body] = nrm[body, 1]  # nrm is the fluid's outward normal; the body normal is -nrm, dphi/dn_f = -n_b.U
    # 0.5 phi_i + sum_j D_ij phi_j - sum_j S_ij q_j = 0, unknown phi on Neumann panels, q on Dirichlet panels
    dirichlet = np.zeros(len(a), bool)
    dirichlet[:n_out] = surface
    A = 0.5 * np.eye(len(a)) + D
    lhs = np.where(dirichlet[None, :], -S, A)
    rhs = S @ np.where(dirichlet, 0.0, q_known)
    sol = np.linalg.solve(lhs, rhs)
    phi = np.where(dirichlet, 0.0, sol)
    L = np.linalg.norm(b - a, axis=1)
    # m_a = rho * integral over the body of phi dphi/dn_f ds (twice the kinetic energy for U = 1)
    m_a = np.sum((phi * q_known * L)[body])
    return m_a / (np.pi * radius ** 2)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--width", type=float, default=0.6)
    p.add_argument("--depth", type=float, default=0.5)
    p.add_argument("--radius", type=float, default=0.05)
    p.add_argument("--centre-height", type=float, default=0.2)
    p.add_argument("--ratio", type=float, default=0.2)
    p.add_argument("--panels", type=int, default=400)
    o = p.parse_args()
    big = 40.0
    free = added_mass(big, big, o.radius, np.array([big / 2, big / 2]), o.panels // 2, wall_panel=big / 250)
    print(f"check, circle in a {big:.0f} m tank: C_a = {free:.4f} (unbounded: 1)")
    for n in (o.panels // 2, o.panels):
        ca = added_mass(o.width, o.depth, o.radius, np.array([o.width / 2, o.centre_height]), n)
        print(f"tank {o.width} x {o.depth} m, R = {o.radius} m at height {o.centre_height} m, {n} body panels: C_a = {ca:.4f}")
    a_free = (1 - o.ratio) * G / (o.ratio + 1.0)
    a_tank = (1 - o.ratio) * G / (o.ratio + ca)
    print(f"density ratio {o.ratio}: a0 = {a_free:.4f} m/s^2 unbounded, {a_tank:.4f} m/s^2 in the tank "
          f"({100 * (a_tank / a_free - 1):+.2f}%)")


if __name__ == "__main__":
    main()
