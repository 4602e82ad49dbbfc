#pragma once
// Boundary particles on a triangle mesh (METHOD.md section 2: one layer of particles
// with unit normals pointing into the fluid).
//
// The wall force of METHOD.md grows with the number of boundary particles per area, so
// the sampling aims at one particle per spacing^2 whatever the mesh's triangle sizes:
// candidate points are offered in order (every vertex; each triangle's lattice spanned
// by its two shorter edges, divided into the fewest equal steps not longer than
// `spacing`; then the same lattices at half that step) and a candidate is kept only if
// no kept particle lies within 0.75 spacing. A box split into triangles thus gives
// exactly fluid::sampleBoxSurface's lattice (no point of a square lattice of step
// <= spacing is farther than 0.71 spacing from it), and a fine mesh is thinned
// instead of sampled at every vertex: a sphere gives about 1.3 particles per spacing^2
// whether its triangles are 1.3 or 0.33 spacings wide (test_io_mesh_sampling). A
// dropped candidate within spacing/4 of a particle adds its face normal to it: a
// particle keeps one normal per
// group of face normals within 30 degrees of each other, so flat and smooth parts carry
// one (averaged) normal, sharp edges two and corners three, as box edges and corners do.
//
// The normals point out of the enclosed volume (an obstacle or a body in the fluid)
// or into it (a container), whatever the file's winding: it is made consistent with
// the sign of the enclosed volume, so the mesh must be closed.
#include <moorsph/fluid/box_geometry.hpp>
#include <moorsph/io/triangle_mesh.hpp>

namespace moorsph::io {

fluid::BoundaryParticles<3> sampleMeshSurface(const TriangleMesh& mesh, double spacing, fluid::NormalSide side);

/// Distance [m] from p to the nearest point of the mesh's surface.
double distanceToMesh(const TriangleMesh& mesh, const Eigen::Vector3d& p);

/// True if p lies inside the closed mesh (parity of the crossings of a ray).
bool meshContains(const TriangleMesh& mesh, const Eigen::Vector3d& p);

}  // namespace moorsph::io
