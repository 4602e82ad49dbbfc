#pragma once
// Integral properties of a closed triangle mesh, all from the divergence theorem on the
// triangles (exact for the polygonal surface, no voxels or sampling):
//  - closedness: every edge used by exactly two triangles, in opposite directions;
//  - the enclosed solid's volume, centroid and inertia tensor (uniform density);
//  - hydrostatics of the part below a horizontal plane y = h (y up, METHOD.md axes):
//    displaced volume, centre of buoyancy, waterplane area, its centroid and second
//    moments, hence the metacentric radii BM = I / V.
#include <Eigen/Core>

#include <moorsph/io/triangle_mesh.hpp>

namespace moorsph::io {

struct MeshEdgeReport {
  int edges = 0;          ///< distinct undirected edges
  int open_edges = 0;     ///< used by one triangle only (a hole)
  int overused_edges = 0; ///< used by more than two triangles (non-manifold)
  int same_direction = 0; ///< used twice in the same direction (inconsistent winding)
  int degenerate = 0;     ///< triangles repeating a vertex index
  bool closed() const { return open_edges == 0 && overused_edges == 0 && same_direction == 0 && degenerate == 0; }
};

MeshEdgeReport checkEdges(const TriangleMesh& mesh);

struct SolidProperties {
  double volume = 0.0;                                        ///< [m^3], > 0 for outward normals
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();         ///< [m]
  Eigen::Matrix3d inertia_per_density = Eigen::Matrix3d::Zero(); ///< about the centroid [m^5]: times density gives kg m^2
};

/// Volume, centroid and inertia of the solid enclosed by a closed mesh of uniform density,
/// summed over the tetrahedra (origin, a, b, c) of its triangles (signed volumes).
SolidProperties solidProperties(const TriangleMesh& mesh);

struct Hydrostatics {
  double draught = 0.0;                                  ///< plane height h [m] (mesh y)
  double volume = 0.0;                                   ///< displaced volume below y = h [m^3]
  Eigen::Vector3d centre_of_buoyancy = Eigen::Vector3d::Zero();  ///< its centroid [m]
  double waterplane_area = 0.0;                          ///< area of the section y = h [m^2]
  Eigen::Vector2d floatation_centre = Eigen::Vector2d::Zero();   ///< its centroid (x, z) [m]
  double transverse_moment = 0.0;   ///< I_T = integral (z - z_F)^2 dA [m^4] (roll)
  double longitudinal_moment = 0.0; ///< I_L = integral (x - x_F)^2 dA [m^4] (pitch)
  double bmTransverse() const { return transverse_moment / volume; }    ///< BM_T [m]
  double bmLongitudinal() const { return longitudinal_moment / volume; } ///< BM_L [m]
};

/// The part of a closed, outward-wound mesh below the plane y = h. The clipped surface plus
/// the waterplane cap is closed, so every integral is a sum over the clipped triangles of a
/// field whose divergence is the integrand and which vanishes on (or is normal to) the cap:
/// V = sum (y - h) n_y dA, int x dV = sum x (y - h) n_y dA, int y dV = sum (y^2 - h^2)/2 n_y dA,
/// A_wp = -sum n_y dA, int_wp f dA = -sum f n_y dA for f = x, z, x^2, z^2 (f independent of y).
Hydrostatics hydrostatics(const TriangleMesh& mesh, double h);

}  // namespace moorsph::io
