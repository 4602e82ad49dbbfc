#include <moorsph/io/mesh_sampling.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <stdexcept>
#include <unordered_map>
#include <vector>

namespace moorsph::io {
namespace {

constexpr double kSameGroupCos = 0.86602540378443865;  // cos 30 deg: normals within it share a group

/// Points with their groups of normals, found by a hash grid of cell `cell`.
class PointSet {
 public:
  explicit PointSet(double cell) : cell_(cell) {}

  /// Index of the point nearest to p within `radius` (radius <= 2 cells), or -1.
  int find(const Eigen::Vector3d& p, double radius) const {
    const auto c = cellOf(p);
    int nearest = -1;
    double best = radius * radius;
    for (int dx = -2; dx <= 2; ++dx)
      for (int dy = -2; dy <= 2; ++dy)
        for (int dz = -2; dz <= 2; ++dz) {
          const auto it = cells_.find(key(c[0] + dx, c[1] + dy, c[2] + dz));
          if (it == cells_.end()) continue;
          for (int k : it->second) {
            const double d2 = (points_[k] - p).squaredNorm();
            if (d2 < best) {
              best = d2;
              nearest = k;
            }
          }
        }
    return nearest;
  }

  void add(const Eigen::Vector3d& p, const Eigen::Vector3d& normal) {
    const int k = static_cast<int>(points_.size());
    points_.push_back(p);
    groups_.emplace_back();
    const auto c = cellOf(p);
    cells_[key(c[0], c[1], c[2])].push_back(k);
    addNormal(k, normal);
  }
  const Eigen::Vector3d& point(int k) const { return points_[k]; }
  /// Whether point k carries a normal within 30 degrees of `normal`.
  bool carries(int k, const Eigen::Vector3d& normal) const {
    return std::any_of(groups_[k].begin(), groups_[k].end(),
                       [&normal](const Eigen::Vector3d& g) { return g.normalized().dot(normal) > kSameGroupCos; });
  }

  /// Join `normal` to the group within 30 degrees, or start a new group (a sharp edge).
  void addNormal(int k, const Eigen::Vector3d& normal) {
    auto& groups = groups_[k];
    for (auto& g : groups)
      if (g.normalized().dot(normal) > kSameGroupCos) {
        g += normal;
        return;
      }
    groups.push_back(normal);
  }

  fluid::BoundaryParticles<3> particles(double sign) const {
    fluid::BoundaryParticles<3> out;
    for (std::size_t k = 0; k < points_.size(); ++k) {
      std::vector<fluid::Vec<3>> normals;
      for (const auto& g : groups_[k]) normals.push_back(sign * g.normalized());
      out.add(points_[k], normals, 0);
    }
    return out;
  }

 private:
  std::array<std::int64_t, 3> cellOf(const Eigen::Vector3d& p) const {
    return {static_cast<std::int64_t>(std::floor(p.x() / cell_)), static_cast<std::int64_t>(std::floor(p.y() / cell_)),
            static_cast<std::int64_t>(std::floor(p.z() / cell_))};
  }
  static std::int64_t key(std::int64_t i, std::int64_t j, std::int64_t k) {
    return (i & 0x1FFFFF) | ((j & 0x1FFFFF) << 21) | ((k & 0x1FFFFF) << 42);
  }
  double cell_;
  std::vector<Eigen::Vector3d> points_;
  std::vector<std::vector<Eigen::Vector3d>> groups_;
  std::unordered_map<std::int64_t, std::vector<int>> cells_;
};

// Candidates closer than kAcceptFraction x spacing to a particle are dropped (so
// fine meshes are not over-sampled: the wall force grows with the particle density);
// those closer than kMergeFraction x spacing add their face normal to it.
constexpr double kAcceptFraction = 0.75;
constexpr double kMergeFraction = 0.25;
// A sharp edge's point whose nearest particle lacks one of the edge's normals (another
// sharp edge's particle, across a face narrower than kAcceptFraction x spacing) is kept
// down to this distance from it.
constexpr double kEdgeAcceptFraction = 0.5;

int steps(double length, double spacing) { return std::max(1, static_cast<int>(std::ceil(length / spacing - 1e-9))); }

Eigen::Vector3d faceNormal(const TriangleMesh& mesh, const std::array<int, 3>& t) {
  return (mesh.vertices[t[1]] - mesh.vertices[t[0]]).cross(mesh.vertices[t[2]] - mesh.vertices[t[0]]);
}

/// Ends of sharp edges where three or more groups of face normals (normals within 30
/// degrees of each other form a group) meet: a box's corners, a transom's ends at the
/// deck. Each comes with the normals of the edges that meet there.
std::vector<std::pair<Eigen::Vector3d, std::vector<Eigen::Vector3d>>> corners(const std::vector<SharpEdge>& edges) {
  std::map<std::array<double, 3>, std::vector<Eigen::Vector3d>> at;
  for (const auto& e : edges)
    for (const Eigen::Vector3d& end : {e.a, e.b}) {
      auto& normals = at[{end.x(), end.y(), end.z()}];
      normals.push_back(e.n1);
      normals.push_back(e.n2);
    }
  std::vector<std::pair<Eigen::Vector3d, std::vector<Eigen::Vector3d>>> out;
  for (const auto& [p, normals] : at) {
    std::vector<Eigen::Vector3d> groups;
    for (const auto& n : normals)
      if (std::none_of(groups.begin(), groups.end(), [&n](const Eigen::Vector3d& g) { return g.dot(n) > kSameGroupCos; }))
        groups.push_back(n);
    if (groups.size() >= 3) out.emplace_back(Eigen::Vector3d(p[0], p[1], p[2]), normals);
  }
  return out;
}

}  // namespace

std::vector<SharpEdge> sharpEdges(const TriangleMesh& mesh) {
  std::map<std::pair<int, int>, std::vector<int>> faces_of_edge;
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int u = mesh.triangles[f][k], v = mesh.triangles[f][(k + 1) % 3];
      faces_of_edge[{std::min(u, v), std::max(u, v)}].push_back(static_cast<int>(f));
    }
  std::vector<SharpEdge> edges;
  for (const auto& [ends, faces] : faces_of_edge) {
    if (faces.size() != 2) continue;
    const Eigen::Vector3d n1 = faceNormal(mesh, mesh.triangles[faces[0]]), n2 = faceNormal(mesh, mesh.triangles[faces[1]]);
    if (n1.norm() == 0.0 || n2.norm() == 0.0) continue;  // degenerate triangle: no normal
    if (n1.normalized().dot(n2.normalized()) > kSameGroupCos) continue;
    edges.push_back({mesh.vertices[ends.first], mesh.vertices[ends.second], n1.normalized(), n2.normalized()});
  }
  return edges;
}

fluid::BoundaryParticles<3> sampleMeshSurface(const TriangleMesh& mesh, double spacing, fluid::NormalSide side) {
  if (!(spacing > 0.0)) throw std::invalid_argument("mesh sampling: spacing must be positive");
  const double volume = mesh.signedVolume();
  if (volume == 0.0) throw std::invalid_argument("mesh sampling: the mesh encloses no volume (is it closed?)");
  // Outward normals of the enclosed volume, times -1 for a container.
  const double sign = (volume > 0.0 ? 1.0 : -1.0) * (side == fluid::NormalSide::Outward ? 1.0 : -1.0);
  const double accept = kAcceptFraction * spacing;  // no two particles closer than this
  const double merge = kMergeFraction * spacing;    // candidates this close add their normal
  PointSet set(0.5 * spacing);
  auto offer = [&](const Eigen::Vector3d& q, const Eigen::Vector3d& normal) {
    const int near = set.find(q, accept);
    if (near < 0) set.add(q, normal);
    else if ((set.point(near) - q).norm() < merge) set.addNormal(near, normal);
  };
  // Sharp edges first, each point with both faces' normals (mesh_sampling.hpp), and
  // before them the corners where they meet, so that an edge's end is not taken by a
  // particle of the other edge without this edge's normals. Where another edge's
  // particle (lacking this edge's normals) is what excludes a point, the point is kept
  // down to kEdgeAcceptFraction x spacing: across a face narrower than 0.75 spacing
  // (the ship's bow cut at dx = 6 m) the second edge would otherwise have no particle
  // with both normals, and fluid went into the hull there (docs/validation/ship.md).
  const double edge_accept = kEdgeAcceptFraction * spacing;
  auto offerEdgePoint = [&](const Eigen::Vector3d& q, const Eigen::Vector3d& n1, const Eigen::Vector3d& n2) {
    const int near = set.find(q, accept);
    const bool other_edge = near >= 0 && !(set.carries(near, n1) && set.carries(near, n2));
    if (other_edge && set.find(q, edge_accept) < 0) set.add(q, n1);
    offer(q, n1);
    offer(q, n2);
  };
  const auto edges = sharpEdges(mesh);
  for (const auto& [corner, normals] : corners(edges))
    for (const auto& n : normals) offer(corner, n);
  for (const double fraction : {1.0, 0.5, 0.25})
    for (const auto& e : edges) {
      const int n = steps((e.b - e.a).norm(), fraction * spacing);
      for (int k = 0; k <= n; ++k) offerEdgePoint(e.a + (static_cast<double>(k) / n) * (e.b - e.a), e.n1, e.n2);
    }
  // Then candidates in three passes: vertices, the coarse lattices (steps <= spacing; a box
  // gives exactly its lattice), then fine lattices (steps <= spacing/2) that fill what
  // the coarse ones leave between differently shaped or small triangles.
  // Each lattice pass completes before the longest edges are offered, so an edge
  // point is judged against both neighbouring triangles' lattices.
  struct Pass {
    double fraction;
    bool lattice;
  };
  for (const Pass pass : {Pass{0.0, false}, Pass{1.0, true}, Pass{1.0, false}, Pass{0.5, true}, Pass{0.5, false}}) {
    const double fraction = pass.fraction;
    for (const auto& t : mesh.triangles) {
      const Eigen::Vector3d p[3] = {mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]};
      const Eigen::Vector3d cross = (p[1] - p[0]).cross(p[2] - p[0]);
      if (cross.norm() == 0.0) continue;  // degenerate: no area, no normal
      const Eigen::Vector3d normal = cross.normalized();
      if (fraction == 0.0) {
        for (const auto& v : p) offer(v, normal);
        continue;
      }
      // The vertex opposite the longest edge is the lattice origin.
      int o = 0;
      double best = -1.0;
      for (int k = 0; k < 3; ++k) {
        const double len = (p[(k + 2) % 3] - p[(k + 1) % 3]).norm();
        if (len > best) {
          best = len;
          o = k;
        }
      }
      const Eigen::Vector3d origin = p[o], e1 = p[(o + 1) % 3] - origin, e2 = p[(o + 2) % 3] - origin;
      if (!pass.lattice) {
        const int n3 = steps(best, fraction * spacing);  // the longest edge itself
        for (int k = 0; k <= n3; ++k) offer(p[(o + 1) % 3] + (static_cast<double>(k) / n3) * (e2 - e1), normal);
        continue;
      }
      const int n1 = steps(e1.norm(), fraction * spacing), n2 = steps(e2.norm(), fraction * spacing);
      for (int i = 0; i <= n1; ++i)
        for (int j = 0; j <= n2; ++j) {
          const double a = static_cast<double>(i) / n1, b = static_cast<double>(j) / n2;
          if (a + b > 1.0 + 1e-9) break;
          offer(origin + a * e1 + b * e2, normal);
        }
    }
  }
  return set.particles(sign);
}

namespace {

// Closest point to p on triangle abc, by the region of the triangle's plane p
// projects into (vertex, edge or face region).
Eigen::Vector3d closestOnTriangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                  const Eigen::Vector3d& c) {
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return a;
  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return a + (d1 / (d1 - d3)) * ab;
  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return a + (d2 / (d2 - d6)) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
  const double denom = 1.0 / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

}  // namespace

double distanceToMesh(const TriangleMesh& mesh, const Eigen::Vector3d& p) {
  double best = 1e300;
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3d q = closestOnTriangle(p, mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]);
    best = std::min(best, (q - p).squaredNorm());
  }
  return std::sqrt(best);
}

bool meshContains(const TriangleMesh& mesh, const Eigen::Vector3d& p) {
  // An irrational-ish direction makes hits on edges and vertices practically impossible.
  const Eigen::Vector3d dir = Eigen::Vector3d(1.0, 0.0003141592653, 0.0002718281828).normalized();
  int crossings = 0;
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3d& a = mesh.vertices[t[0]];
    const Eigen::Vector3d e1 = mesh.vertices[t[1]] - a, e2 = mesh.vertices[t[2]] - a;
    const Eigen::Vector3d h = dir.cross(e2);
    const double det = e1.dot(h);
    if (std::abs(det) < 1e-300) continue;
    const Eigen::Vector3d s = p - a;
    const double u = s.dot(h) / det;
    if (u < 0.0 || u > 1.0) continue;
    const Eigen::Vector3d q = s.cross(e1);
    const double v = dir.dot(q) / det;
    if (v < 0.0 || u + v > 1.0) continue;
    if (e2.dot(q) / det > 0.0) ++crossings;
  }
  return crossings % 2 == 1;
}

}  // namespace moorsph::io
