#pragma once
// Spheres and cylinders for scene files. In 3D they become closed triangle meshes,
// fine enough (edges <= max_edge) that the polygonal surface lies within
// max_edge^2 / (8 radius) of the true one, and are sampled like any mesh. In 2D a
// cylinder is a circle in the x-y plane, sampled directly.
#include <moorsph/fluid/boundary_particles.hpp>
#include <moorsph/fluid/box_geometry.hpp>
#include <moorsph/io/triangle_mesh.hpp>

namespace moorsph::io {

/// An icosphere: the icosahedron subdivided until its edges are <= max_edge [m].
TriangleMesh makeSphereMesh(const Eigen::Vector3d& centre, double radius, double max_edge);

/// A closed cylinder of the given radius and length [m] along axis 0, 1 or 2 (x, y, z),
/// centred at `centre`, its circles split into chords <= max_edge [m].
TriangleMesh makeCylinderMesh(const Eigen::Vector3d& centre, double radius, double length, int axis, double max_edge);

/// A circle in 2D: the fewest equally spaced particles not farther apart than
/// `spacing` along the arc, each with the radial normal (outward: an obstacle).
fluid::BoundaryParticles<2> sampleCircle(const Eigen::Vector2d& centre, double radius, double spacing, fluid::NormalSide side);

}  // namespace moorsph::io
