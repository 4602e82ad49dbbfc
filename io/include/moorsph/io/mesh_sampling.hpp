#pragma once
// Boundary particles on a triangle mesh (METHOD.md section 2: one layer of particles
// with unit normals pointing into the fluid).
//
// The wall force of METHOD.md grows with the number of boundary particles per area, so
// the sampling aims at one particle per spacing^2 whatever the mesh's triangle sizes:
// candidate points are offered in order (points along the sharp edges, below; every
// vertex; each triangle's lattice spanned
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
// Sharp edges are sampled first, each point with both faces' normals, at the fewest
// equal steps not longer than spacing, then spacing/2 and spacing/4: no point of a sharp
// edge is then farther than 0.875 spacing (spacing/8 to a candidate, 0.75 spacing from
// it to the particle that excluded it) from a particle with both normals. An edge point
// whose nearest particle lacks one of its edge's normals (another sharp edge's particle,
// across a face narrower than 0.75 spacing) is kept down to 0.5 spacing from it, so that
// both edges are covered; where edges meet at a corner the test on the ship's hull
// measures up to 0.86 spacing. Until session 39 the second edge of a narrow face stayed bare (1.02 spacing at
// the ship's 4 m wide bow cut at dx = 6 m), and fluid went into the bow there. Without
// this pass an edge got such particles only where a vertex or lattice point of both
// faces happened to fall on it: a face's interior vertex near the edge could take its
// place, leaving a strip along the edge covered by one face's particles only. The wall
// force law drops those particles' push on fluid beyond the edge (boundary_force_law.hpp,
// "Beyond an edge"), so fluid there met no wall: in the ship at dx = 6 m a particle
// slid along the transom onto its lower edge unopposed and was thrown off at 216 m/s
// when the push switched back on (docs/validation/ship.md).
//
// The normals point out of the enclosed volume (an obstacle or a body in the fluid)
// or into it (a container), whatever the file's winding: it is made consistent with
// the sign of the enclosed volume, so the mesh must be closed.
#include <moorsph/fluid/box_geometry.hpp>
#include <moorsph/io/triangle_mesh.hpp>

namespace moorsph::io {

/// An edge of the mesh whose two triangles' normals differ by more than 30 degrees
/// (the angle within which sampled particles merge normals): ends a, b and the two
/// triangles' unit normals as wound (outward for a positive volume).
struct SharpEdge {
  Eigen::Vector3d a, b, n1, n2;
};

/// The sharp edges of a mesh whose vertices are shared (readMesh welds them); edges
/// with one or more than two triangles are left out.
std::vector<SharpEdge> sharpEdges(const TriangleMesh& mesh);

fluid::BoundaryParticles<3> sampleMeshSurface(const TriangleMesh& mesh, double spacing, fluid::NormalSide side);

/// Distance [m] from p to the nearest point of the mesh's surface.
double distanceToMesh(const TriangleMesh& mesh, const Eigen::Vector3d& p);

/// True if p lies inside the closed mesh (parity of the crossings of a ray).
bool meshContains(const TriangleMesh& mesh, const Eigen::Vector3d& p);

}  // namespace moorsph::io
