#!/usr/bin/python3
"""Cut the knife-edge stem off a hull mesh: keep x >= x_cut (hull frame, x aft from the bow)
and close the cut with a flat plate, so the hull has no part thinner than 2 hb(x_cut).

Why: a boundary particle pushes a fluid particle whenever it is less than b_off dx behind the
particle's plane (METHOD.md section 2: q = (r_perp . n + b_off dx) / h > 0). Where the hull is
thinner than b_off dx, a fluid particle beside one face is "in front of" the opposite face's
particles too and is pushed INTO the hull with S(q) -> infinity as q -> 0: at dx = 4 m the
preset's pointed stem (half-breadth < 2 m over its first 6 m) blows a run up at its first step.
Cutting where the half-breadth reaches 2 m makes the hull at least 4 m thick everywhere, enough
for b_off dx <= 4 m, i.e. dx <= 8 m with b_off = 0.5. The cut removes 6.15 m of stem, about
0.2 % of the displaced volume (the scenes' equilibrium is computed on the cut mesh).

    blunt_bow.py hull.stl hull_blunt.stl [x_cut=6.15]

The section at the cut must be convex (it is for the parametric hull: superellipse sections
with n >= 1 below the waterline, vertical sides and a flat deck above). Writes binary STL.
"""
import struct
import sys

import numpy as np


def read_binary_stl(path):
    with open(path, "rb") as f:
        f.read(80)
        (n,) = struct.unpack("<I", f.read(4))
        data = np.frombuffer(f.read(50 * n), dtype=np.dtype([("n", "<f4", 3), ("v", "<f4", (3, 3)), ("a", "<u2")]))
    return data["v"].astype(np.float64)


def write_binary_stl(path, triangles):
    with open(path, "wb") as f:
        f.write(b"moorsph binary STL (blunt_bow.py)".ljust(80, b" "))
        f.write(struct.pack("<I", len(triangles)))
        for t in triangles:
            n = np.cross(t[1] - t[0], t[2] - t[0])
            norm = np.linalg.norm(n)
            n = n / norm if norm > 0 else n
            f.write(struct.pack("<3f", *n))
            for v in t:
                f.write(struct.pack("<3f", *v))
            f.write(b"\0\0")


def cut_point(a, b, x):
    """Where edge a-b crosses the plane; the same bits whichever triangle asks (ordered ends)."""
    if tuple(a) > tuple(b):
        a, b = b, a
    s = (x - a[0]) / (b[0] - a[0])
    p = a + s * (b - a)
    p[0] = x
    return np.float32(p).astype(np.float64)


def clip(tri, x):
    """The part of a triangle with x >= x_cut, as 0, 1 or 2 triangles, and its cut segment."""
    keep = [v[0] >= x for v in tri]
    if all(keep):
        return [tri], None
    if not any(keep):
        return [], None
    poly, cut = [], []
    for i in range(3):
        a, b = tri[i], tri[(i + 1) % 3]
        if keep[i]:
            poly.append(a)
        if keep[i] != keep[(i + 1) % 3]:
            p = cut_point(a, b, x)
            poly.append(p)
            cut.append(p)
    out = [np.array([poly[0], poly[k], poly[k + 1]]) for k in range(1, len(poly) - 1)]
    return out, cut


def main():
    src, dst = sys.argv[1], sys.argv[2]
    x_cut = float(sys.argv[3]) if len(sys.argv) > 3 else 6.15
    tris = read_binary_stl(src)
    kept, points = [], {}
    for t in tris:
        part, cut = clip(t, x_cut)
        kept.extend(p for p in part if np.linalg.norm(np.cross(p[1] - p[0], p[2] - p[0])) > 1e-12)
        for p in cut or []:
            points[tuple(p)] = p
    pts = np.array(list(points.values()))
    centre = np.float32(pts.mean(axis=0)).astype(np.float64)
    centre[0] = x_cut
    angle = np.arctan2(pts[:, 1] - centre[1], pts[:, 2] - centre[2])
    ring = pts[np.argsort(angle)]
    # Cap facing -x (outward, toward the bow): wound so its normal is -x.
    cap = []
    for k in range(len(ring)):
        a, b = ring[k], ring[(k + 1) % len(ring)]
        t = np.array([centre, a, b])
        if np.cross(t[1] - t[0], t[2] - t[0])[0] > 0:
            t = np.array([centre, b, a])
        cap.append(t)
    write_binary_stl(dst, kept + cap)
    half = np.abs(pts[:, 2]).max()
    print(f"cut at x = {x_cut} m: {len(tris)} -> {len(kept) + len(cap)} triangles, cap of {len(ring)} points, "
          f"half-breadth there {half:.3f} m")


if __name__ == "__main__":
    main()
