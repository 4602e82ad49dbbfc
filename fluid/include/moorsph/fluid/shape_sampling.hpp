#pragma once
// Boundary particles on curved body surfaces, with outward unit normals (pointing
// into the fluid), at a spacing no coarser than requested (METHOD.md section 2: a
// boundary coarser than the fluid lets fluid leak in).
//  - sphere: in 2D a circle of N = ceil(2 pi R / s) equally spaced points; in 3D a
//    Fibonacci (golden-angle) lattice of N = ceil(4 pi R^2 / s^2) nearly uniform points.
//  - cylinder (3D): axis along z, rings on the mantle plus filled end discs.
#include <moorsph/fluid/boundary_particles.hpp>

namespace moorsph::fluid {

template <int D>
BoundaryParticles<D> sampleSphere(const Vec<D>& centre, double radius, double spacing);

/// Sphere sampled on latitude rings about y, mirror-symmetric in x and z (3D only):
/// no spurious sideways force or torque in a height-only pressure field.
BoundaryParticles<3> sampleSphereRings(const Vec<3>& centre, double radius, double spacing);

/// Closed circular cylinder, axis along z from z0 to z1 (3D only).
BoundaryParticles<3> sampleCylinder(const Vec<3>& axis_point, double radius, double z0, double z1, double spacing);

}  // namespace moorsph::fluid
