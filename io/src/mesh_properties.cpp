#include <moorsph/io/mesh_properties.hpp>

#include <algorithm>
#include <array>
#include <map>
#include <utility>
#include <vector>

namespace moorsph::io {

MeshEdgeReport checkEdges(const TriangleMesh& mesh) {
  std::map<std::pair<int, int>, std::pair<int, int>> uses;  // (min, max) -> (forward, backward) counts
  MeshEdgeReport r;
  for (const auto& t : mesh.triangles) {
    if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) {
      ++r.degenerate;
      continue;
    }
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      auto& u = uses[std::minmax(a, b)];
      (a < b ? u.first : u.second) += 1;
    }
  }
  r.edges = static_cast<int>(uses.size());
  for (const auto& [edge, u] : uses) {
    const int n = u.first + u.second;
    if (n == 1) ++r.open_edges;
    if (n > 2) ++r.overused_edges;
    if (n == 2 && u.first != 1) ++r.same_direction;
  }
  return r;
}

SolidProperties solidProperties(const TriangleMesh& mesh) {
  // Tetrahedron (0, a, b, c) of signed volume v: int x dV = v (a + b + c)/4 and
  // int x x^T dV = v/20 (a a^T + b b^T + c c^T + s s^T), s = a + b + c (the standard
  // second moment of a tetrahedron with one vertex at the origin).
  SolidProperties p;
  Eigen::Vector3d first = Eigen::Vector3d::Zero();
  Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
  // Shift to a point near the mesh for round-off (a ship 300 m from the origin).
  const Eigen::Vector3d o = 0.5 * (mesh.lower() + mesh.upper());
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3d a = mesh.vertices[t[0]] - o, b = mesh.vertices[t[1]] - o, c = mesh.vertices[t[2]] - o;
    const double v = a.dot(b.cross(c)) / 6.0;
    const Eigen::Vector3d s = a + b + c;
    p.volume += v;
    first += v * s / 4.0;
    second += v / 20.0 * (a * a.transpose() + b * b.transpose() + c * c.transpose() + s * s.transpose());
  }
  if (p.volume == 0.0) return p;
  const Eigen::Vector3d g = first / p.volume;
  const Eigen::Matrix3d about_g = second - p.volume * g * g.transpose();  // parallel-axis shift
  p.centroid = o + g;
  p.inertia_per_density = about_g.trace() * Eigen::Matrix3d::Identity() - about_g;
  return p;
}

namespace {

using Tri = std::array<Eigen::Vector3d, 3>;

/// The part of triangle t with y <= h, as 0, 1 or 2 triangles wound like t.
std::vector<Tri> clipBelow(const Tri& t, double h) {
  std::array<bool, 3> below{};
  int n = 0;
  for (int k = 0; k < 3; ++k) n += (below[k] = t[k].y() <= h);
  if (n == 3) return {t};
  if (n == 0) return {};
  auto cut = [&](const Eigen::Vector3d& p, const Eigen::Vector3d& q) {
    const double s = (h - p.y()) / (q.y() - p.y());
    Eigen::Vector3d r = p + s * (q - p);
    r.y() = h;
    return r;
  };
  // Rotate so that vertex 0 is the odd one out (alone below when n == 1, alone above when n == 2).
  int k = 0;
  while (below[k] != (n == 1)) ++k;
  const Eigen::Vector3d& p0 = t[k];
  const Eigen::Vector3d& p1 = t[(k + 1) % 3];
  const Eigen::Vector3d& p2 = t[(k + 2) % 3];
  const Eigen::Vector3d c01 = cut(p0, p1), c02 = cut(p0, p2);
  if (n == 1) return {Tri{p0, c01, c02}};
  return {Tri{c01, p1, p2}, Tri{c01, p2, c02}};
}

/// Mean of f over the triangle by the edge-midpoint rule (exact for quadratics).
template <class F>
double mean(const Tri& t, F f) {
  return (f(0.5 * (t[0] + t[1])) + f(0.5 * (t[1] + t[2])) + f(0.5 * (t[2] + t[0]))) / 3.0;
}

}  // namespace

Hydrostatics hydrostatics(const TriangleMesh& mesh, double h) {
  Hydrostatics r;
  r.draught = h;
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();  // int (x, y, z) dV
  double wx = 0.0, wz = 0.0, wxx = 0.0, wzz = 0.0;     // int x, z, x^2, z^2 dA over the waterplane
  for (const auto& ids : mesh.triangles) {
    const Tri t{mesh.vertices[ids[0]], mesh.vertices[ids[1]], mesh.vertices[ids[2]]};
    for (const Tri& c : clipBelow(t, h)) {
      const double ny_da = 0.5 * (c[1] - c[0]).cross(c[2] - c[0]).y();  // n_y dA
      r.volume += ny_da * mean(c, [&](const Eigen::Vector3d& p) { return p.y() - h; });
      moment.x() += ny_da * mean(c, [&](const Eigen::Vector3d& p) { return p.x() * (p.y() - h); });
      moment.y() += ny_da * mean(c, [&](const Eigen::Vector3d& p) { return 0.5 * (p.y() * p.y() - h * h); });
      moment.z() += ny_da * mean(c, [&](const Eigen::Vector3d& p) { return p.z() * (p.y() - h); });
      r.waterplane_area -= ny_da;
      wx -= ny_da * mean(c, [](const Eigen::Vector3d& p) { return p.x(); });
      wz -= ny_da * mean(c, [](const Eigen::Vector3d& p) { return p.z(); });
      wxx -= ny_da * mean(c, [](const Eigen::Vector3d& p) { return p.x() * p.x(); });
      wzz -= ny_da * mean(c, [](const Eigen::Vector3d& p) { return p.z() * p.z(); });
    }
  }
  if (r.volume > 0.0) r.centre_of_buoyancy = moment / r.volume;
  if (r.waterplane_area > 0.0) {
    r.floatation_centre = Eigen::Vector2d(wx, wz) / r.waterplane_area;
    r.longitudinal_moment = wxx - r.waterplane_area * r.floatation_centre.x() * r.floatation_centre.x();
    r.transverse_moment = wzz - r.waterplane_area * r.floatation_centre.y() * r.floatation_centre.y();
  }
  return r;
}

}  // namespace moorsph::io
