#pragma once
// A triangle mesh read from STL (ASCII or binary) or Wavefront OBJ, in metres after
// `scale` and `translate`. Used for boundary surfaces of arbitrary shape (3D only).
#include <array>
#include <string>
#include <vector>
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace moorsph::io {

struct TriangleMesh {
  std::vector<Eigen::Vector3d> vertices;         ///< [m]
  std::vector<std::array<int, 3>> triangles;     ///< vertex indices, counter-clockwise seen from outside

  Eigen::Vector3d lower() const;
  Eigen::Vector3d upper() const;
  /// Signed enclosed volume [m^3] (divergence theorem); positive when the winding
  /// makes the normals point outward.
  double signedVolume() const;
  double area() const;
  /// Reverse every triangle's winding (flips the normals).
  void flip();
};

/// Reads .stl (ASCII or binary) or .obj, chosen by extension (case-insensitive); OBJ
/// polygons are split into triangle fans. Throws std::runtime_error naming the file
/// and the line on malformed input.
TriangleMesh readMesh(const std::string& path);

}  // namespace moorsph::io
