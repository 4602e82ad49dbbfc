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

  near_body_flow.py RUN [--radius 0.05] [--dx 0.005] [--centre-x 0.3] [--plot PNG]
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
    o = p.parse_args()
    side_layers(o)
    if o.plot:
        plot(o)


if __name__ == "__main__":
    main()
