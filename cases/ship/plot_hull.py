#!/usr/bin/env python3
"""Draws a hull mesh (binary STL in the hull frame: x aft from the bow, y up, z across) as a
3D view plus body plan, profile and half-breadth plan, with the waterline y = T.
usage: plot_hull.py hull.stl out.png [draught]"""
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
from mpl_toolkits.mplot3d.art3d import Poly3DCollection


def read_binary_stl(path):
    data = open(path, "rb").read()
    count = int(np.frombuffer(data, dtype="<u4", count=1, offset=80)[0])
    rec = np.dtype([("n", "<f4", 3), ("v", "<f4", (3, 3)), ("attr", "<u2")])
    return np.frombuffer(data, dtype=rec, count=count, offset=84)["v"].astype(float)


def main():
    tris = read_binary_stl(sys.argv[1])
    draught = float(sys.argv[3]) if len(sys.argv) > 3 else 12.0
    L = tris[..., 0].max() - tris[..., 0].min()
    B = tris[..., 2].max() - tris[..., 2].min()
    D = tris[..., 1].max() - tris[..., 1].min()
    fig = plt.figure(figsize=(13, 9))
    grid = fig.add_gridspec(3, 2, height_ratios=[1.6, 1, 1])
    ax = fig.add_subplot(grid[0, :], projection="3d")
    # Plot axes: ship x -> plot x, ship z -> plot y, ship y (up) -> plot z.
    # Shade by the face normal's angle to a light so the shape reads without edges.
    e1, e2 = tris[:, 1] - tris[:, 0], tris[:, 2] - tris[:, 0]
    n = np.cross(e1, e2)
    n /= np.maximum(np.linalg.norm(n, axis=1, keepdims=True), 1e-30)
    light = np.array([-0.2, -0.7, -0.7]) / np.linalg.norm([-0.2, -0.7, -0.7])  # near the viewer
    shade = 0.25 + 0.75 * np.clip(n @ light, 0, 1)
    colours = np.clip(np.outer(shade, [0.75, 0.85, 1.0]), 0, 1)
    poly = Poly3DCollection(tris[..., [0, 2, 1]], facecolors=colours, edgecolor="none")
    ax.add_collection3d(poly)
    ax.set_xlim(0, L); ax.set_ylim(-B / 2, B / 2); ax.set_zlim(0, D)
    ax.set_box_aspect((L, B, D), zoom=1.3)
    ax.set_xlabel("x aft [m]"); ax.set_ylabel("z [m]"); ax.set_zlabel("y up [m]")
    ax.view_init(elev=-22, azim=-125)
    ax.set_yticks([-15, 0, 15]); ax.set_zticks([0, 12, 23.5])
    ax.set_title("hull mesh (%d triangles), seen from below the bow" % len(tris))

    # Body plan: sections at stations, cut from the mesh edges crossing each x.
    ax2 = fig.add_subplot(grid[1:, 0])
    for xs in np.linspace(0.02, 0.98, 13) * L:
        pts = []
        for t in tris:
            for a, b in ((0, 1), (1, 2), (2, 0)):
                p, q = t[a], t[b]
                if (p[0] - xs) * (q[0] - xs) < 0:
                    s = (xs - p[0]) / (q[0] - p[0])
                    pts.append(p + s * (q - p))
        if not pts:
            continue
        pts = np.array(pts)
        side = -1 if xs < L / 2 else 1  # forward sections left, aft right (body-plan habit)
        sel = pts[:, 2] * side >= -1e-9
        ax2.plot(pts[sel, 2], pts[sel, 1], ".", ms=1.5)
    ax2.axhline(draught, color="b", lw=0.8)
    ax2.set_aspect("equal"); ax2.set_xlabel("z [m] (left: forward half, right: aft half)"); ax2.set_ylabel("y [m]")
    ax2.set_title("body plan, 13 stations; blue: waterline T = %.1f m" % draught)

    ax3 = fig.add_subplot(grid[1, 1])
    v = tris.reshape(-1, 3)
    ax3.plot(v[:, 0], v[:, 2], ",", color="k")
    ax3.set_aspect("equal"); ax3.set_xlabel("x aft from the bow [m]"); ax3.set_ylabel("z [m]")
    ax3.set_title("plan (mesh vertices)")
    ax4 = fig.add_subplot(grid[2, 1])
    ax4.plot(v[:, 0], v[:, 1], ",", color="k")
    ax4.axhline(draught, color="b", lw=0.8)
    ax4.set_aspect("equal"); ax4.set_xlabel("x aft from the bow [m]"); ax4.set_ylabel("y [m]")
    ax4.set_title("profile (mesh vertices)")
    fig.tight_layout()
    fig.savefig(sys.argv[2], dpi=110)


if __name__ == "__main__":
    main()
