#include <moorsph/io/primitive_shapes.hpp>

#include <cmath>
#include <map>

namespace moorsph::io {

TriangleMesh makeSphereMesh(const Eigen::Vector3d& centre, double radius, double max_edge) {
  TriangleMesh m;
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  const double v[12][3] = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                           {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  for (const auto& p : v) m.vertices.push_back(Eigen::Vector3d(p[0], p[1], p[2]).normalized());
  m.triangles = {{0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                 {11, 10, 2}, {10, 7, 6}, {7, 1, 8}, {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8},
                 {3, 8, 9}, {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
  // Each subdivision halves the edges (the icosahedron's is 1.05 on the unit sphere).
  double edge = 1.0515 * radius;
  while (edge > max_edge) {
    std::map<std::pair<int, int>, int> middle;
    auto mid = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      const auto it = middle.find(key);
      if (it != middle.end()) return it->second;
      m.vertices.push_back((m.vertices[a] + m.vertices[b]).normalized());
      return middle[key] = static_cast<int>(m.vertices.size()) - 1;
    };
    std::vector<std::array<int, 3>> finer;
    for (const auto& tri : m.triangles) {
      const int a = mid(tri[0], tri[1]), b = mid(tri[1], tri[2]), c = mid(tri[2], tri[0]);
      finer.push_back({tri[0], a, c});
      finer.push_back({tri[1], b, a});
      finer.push_back({tri[2], c, b});
      finer.push_back({a, b, c});
    }
    m.triangles = finer;
    edge *= 0.5;
  }
  for (auto& p : m.vertices) p = centre + radius * p;
  return m;
}

TriangleMesh makeCylinderMesh(const Eigen::Vector3d& centre, double radius, double length, int axis, double max_edge) {
  const int n = std::max(8, static_cast<int>(std::ceil(2.0 * M_PI * radius / max_edge)));
  // Axis a, and the two other axes b, c ordered so that (b, c, a) is right-handed.
  const int a = axis, b = (axis + 1) % 3, c = (axis + 2) % 3;
  TriangleMesh m;
  for (int end = 0; end < 2; ++end)
    for (int k = 0; k < n; ++k) {
      Eigen::Vector3d p = centre;
      const double angle = 2.0 * M_PI * k / n;
      p[a] += (end == 0 ? -0.5 : 0.5) * length;
      p[b] += radius * std::cos(angle);
      p[c] += radius * std::sin(angle);
      m.vertices.push_back(p);
    }
  Eigen::Vector3d low = centre, high = centre;
  low[a] -= 0.5 * length;
  high[a] += 0.5 * length;
  m.vertices.push_back(low);
  m.vertices.push_back(high);
  const int lc = 2 * n, hc = 2 * n + 1;
  for (int k = 0; k < n; ++k) {
    const int l0 = k, l1 = (k + 1) % n, h0 = n + k, h1 = n + (k + 1) % n;
    m.triangles.push_back({l0, l1, h1});  // counter-clockwise seen from outside
    m.triangles.push_back({l0, h1, h0});
    m.triangles.push_back({lc, l1, l0});
    m.triangles.push_back({hc, h0, h1});
  }
  return m;
}

fluid::BoundaryParticles<2> sampleCircle(const Eigen::Vector2d& centre, double radius, double spacing,
                                         fluid::NormalSide side) {
  const int n = std::max(3, static_cast<int>(std::ceil(2.0 * M_PI * radius / spacing - 1e-9)));
  const double sign = side == fluid::NormalSide::Outward ? 1.0 : -1.0;
  fluid::BoundaryParticles<2> out;
  for (int k = 0; k < n; ++k) {
    const double angle = 2.0 * M_PI * k / n;
    const Eigen::Vector2d radial(std::cos(angle), std::sin(angle));
    out.add(centre + radius * radial, {sign * radial}, 0);
  }
  return out;
}

}  // namespace moorsph::io
