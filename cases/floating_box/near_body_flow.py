#!/usr/bin/env python3
"""The flow next to the released light cylinder (cases/floating_box/submerged_cylinder_2d.yaml)
against potential flow's dipole.

Needs a run with particle snapshots, e.g.
  moorsph run cases/floating_box/submerged_cylinder_2d.yaml --set output.particles_interval=0.02 --out RUN

For each snapshot after the release: the body's speed U, and at its sides (|sin theta| < 0.4
about the centre, theta from the horizontal) the mean vertical velocity of the fluid in
layers 0.5 dx thick by their gap to the surface, beside the unbounded dipole's
-U R^2 / r^2 there (the fluid at the sides slips down past a rising cylinder). With
--plot PNG, the particles around the body at two snapshots, coloured by pressure, with
their ground-frame velocities.

With --forces, the budget along the surface of the first layer (gap < 1 dx) within 30 deg
of the sides, per snapshot: the pressure term of METHOD.md 1 split into its P_i part
-P_i/rho_i^2 sum_j m_j grad W_ij and its P_j part, the wall law of METHOD.md 2 summed over
the body's boundary particles, and gravity, each as an acceleration up the surface. Kernel,
spacing, c_s, b_off and wall strength are read from RUN/scene.resolved.yaml; the wall law's
h is the kernel's (boundary_h_factor unset) and its form the reference one.

  near_body_flow.py RUN [--radius 0.05] [--dx 0.005] [--centre-x 0.3] [--plot PNG] [--forces]
"""
import argparse

import h5py
import numpy as np

FLUID = 0


def snapshots(run):
    with h5py.File(run + "/particles.h5", "r") as f:
        for key in sorted(f["snapshots"].keys()):
            g = f["snapshots/" + key]
            yield (g.attrs["time"], g["type"][...], g["position"][...][:, :2], g["velocity"][...][:, :2],
                   g["pressure"][...])


def body_state(run):
    with h5py.File(run + "/series.h5", "r") as f:
        return (f["body_cylinder/time"][...], f["body_cylinder/y"][...], f["velocity_cylinder/time"][...],
                f["velocity_cylinder/vy"][...])


def side_layers(o):
    tb, yb, tv, vb = body_state(o.run)
    release = tv[np.argmax(np.abs(vb) > 0)] if np.any(vb != 0) else np.inf
    print("time [s]  U [m/s]  fluid u_y at the sides by gap to the surface [m/s] (dipole's in brackets)")
    for t, kind, r, u, _ in snapshots(o.run):
        if t < release:
            continue
        y_b, speed = np.interp(t, tb, yb), np.interp(t, tv, vb)
        d = r - np.array([o.centre_x, y_b])
        dist = np.linalg.norm(d, axis=1)
        side = (kind == FLUID) & (np.abs(d[:, 1]) < 0.4 * dist)
        cells = []
        for gap in np.arange(0.5, 3.5, 0.5):
            m = side & (dist >= o.radius + gap * o.dx) & (dist < o.radius + (gap + 0.5) * o.dx)
            if m.any():
                dipole = -speed * o.radius ** 2 / np.mean(dist[m]) ** 2
                cells.append(f"{gap:.1f}-{gap + 0.5:.1f} dx: {u[m, 1].mean():+.3f} ({dipole:+.3f})")
        print(f"{t:.3f}  {speed:.3f}  " + "  ".join(cells))


def wendland_gradient_2d(r, h):
    """dW/dr of the 2D Wendland C2 kernel, support 2h (METHOD.md 1)."""
    q = r / h
    return np.where(q < 2.0, 7.0 / (64.0 * np.pi * h * h) * (2.0 - q) ** 3 * (-10.0 * q) / h, 0.0)


def wall_shape(q):
    """S(q) of METHOD.md 2 (s = 8, d = 1)."""
    return np.where((q > 0) & (q < 0.8), (0.8 / np.maximum(q, 1e-12)) ** 8, np.where((q >= 0.8) & (q < 1), 25 * (q - 1) ** 2, 0.0))


def force_budget(o):
    import yaml
    from scipy.spatial import cKDTree
    with open(o.run + "/scene.resolved.yaml") as f:
        scene = yaml.safe_load(f)
    dx, c = scene["resolution"]["dx"], scene["fluid"]["sound_speed"]
    h = scene["method"]["h_factor"] * dx
    offset, strength = scene["method"]["b_off"] * dx, scene["method"]["boundary_strength"]
    mass, g = scene["fluid"].get("density", 1000.0) * dx * dx, 9.81
    tb, yb, _, _ = body_state(o.run)
    print("time [s]  up the surface at the sides [m/s^2]: pressure (P_i part + P_j part)  wall  gravity  sum  | layer speed [m/s]")
    for t, kind, r, u, p in snapshots(o.run):
        centre = np.array([o.centre_x, np.interp(t, tb, yb)])
        fluid = kind == FLUID
        rf, uf, pf = r[fluid], u[fluid], p[fluid]
        rho = scene["fluid"].get("density", 1000.0) * (1.0 + pf / (scene["fluid"].get("density", 1000.0) * c * c / 7.0)) ** (1.0 / 7.0)
        rb = r[~fluid]
        rb = rb[np.abs(np.linalg.norm(rb - centre, axis=1) - o.radius) < 1e-3 * dx]
        nb = (rb - centre) / o.radius
        d = rf - centre
        dist, theta = np.linalg.norm(d, axis=1), np.arctan2(d[:, 1], d[:, 0])
        layer = np.where((dist < o.radius + dx) & (np.abs(np.cos(theta)) > np.cos(np.radians(30))))[0]
        tree = cKDTree(rf)
        rows = []
        for i in layer:
            up = np.array([-np.sin(theta[i]), np.cos(theta[i])])
            up = up if up[1] > 0 else -up
            js = np.array([j for j in tree.query_ball_point(rf[i], 2 * h) if j != i])
            rij = rf[i] - rf[js]
            grad = (wendland_gradient_2d(np.linalg.norm(rij, axis=1), h) / np.linalg.norm(rij, axis=1))[:, None] * rij
            own = -(mass * pf[i] / rho[i] ** 2 * grad).sum(0) @ up
            others = -(mass * (pf[js] / rho[js] ** 2)[:, None] * grad).sum(0) @ up
            rik = rf[i] - rb
            perp = np.einsum("kd,kd->k", rik, nb)
            par = np.sqrt(np.maximum(np.einsum("kd,kd->k", rik, rik) - perp ** 2, 0.0))
            push = strength * c * c / h * np.where((perp + offset > 0) & (par < dx), 1.0 - par / dx, 0.0) * \
                wall_shape((np.maximum(perp, 0.0) + offset) / h)
            wall = (push[:, None] * nb).sum(0) @ up
            rows.append((own, others, wall, -g * up[1], uf[i] @ up))
        a = np.array(rows)
        total = a[:, :4].sum(1)
        print(f"{t:.3f}  {a[:, 0].mean() + a[:, 1].mean():+7.2f} ({a[:, 0].mean():+6.2f} {a[:, 1].mean():+6.2f})  "
              f"{a[:, 2].mean():+6.2f}  {a[:, 3].mean():+6.2f}  {total.mean():+6.2f} (rms {total.std():.1f})  | {a[:, 4].mean():+.3f}")


def plot(o):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    tb, yb, tv, vb = body_state(o.run)
    frames = [s for s in snapshots(o.run) if np.interp(s[0], tv, vb) > 0]
    frames = [frames[len(frames) // 3], frames[-1]] if len(frames) > 1 else frames
    fig, axes = plt.subplots(1, len(frames), figsize=(7 * len(frames), 7))
    for ax, (t, kind, r, u, p) in zip(np.atleast_1d(axes), frames):
        y_b, speed = np.interp(t, tb, yb), np.interp(t, tv, vb)
        near = (np.abs(r[:, 0] - o.centre_x) < 1.8 * o.radius) & (np.abs(r[:, 1] - y_b) < 1.8 * o.radius)
        fluid, wall = near & (kind == FLUID), near & (kind != FLUID)
        dots = ax.scatter(r[fluid, 0], r[fluid, 1], c=p[fluid], s=12, cmap="viridis")
        ax.scatter(r[wall, 0], r[wall, 1], c="k", s=6)
        ax.quiver(r[fluid, 0], r[fluid, 1], u[fluid, 0], u[fluid, 1], scale=4, width=0.002)
        ax.set_aspect("equal")
        ax.set_xlabel("x [m]")
        ax.set_ylabel("y [m]")
        ax.set_title(f"t = {t:.2f} s, cylinder rising at {speed:.3f} m/s\n(arrows: fluid velocity, ground frame)")
        fig.colorbar(dots, ax=ax, shrink=0.7, label="pressure [Pa]")
    fig.tight_layout()
    fig.savefig(o.plot, dpi=80)
    print("wrote", o.plot)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("run")
    p.add_argument("--radius", type=float, default=0.05)
    p.add_argument("--dx", type=float, default=0.005)
    p.add_argument("--centre-x", type=float, default=0.3)
    p.add_argument("--plot")
    p.add_argument("--forces", action="store_true")
    o = p.parse_args()
    side_layers(o)
    if o.forces:
        force_budget(o)
    if o.plot:
        plot(o)


if __name__ == "__main__":
    main()
