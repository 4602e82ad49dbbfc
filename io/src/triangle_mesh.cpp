#include <moorsph/io/triangle_mesh.hpp>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

namespace moorsph::io {

Eigen::Vector3d TriangleMesh::lower() const {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300);
  for (const auto& v : vertices) lo = lo.cwiseMin(v);
  return lo;
}

Eigen::Vector3d TriangleMesh::upper() const {
  Eigen::Vector3d hi = Eigen::Vector3d::Constant(-1e300);
  for (const auto& v : vertices) hi = hi.cwiseMax(v);
  return hi;
}

double TriangleMesh::signedVolume() const {
  double six_v = 0.0;
  for (const auto& t : triangles) six_v += vertices[t[0]].dot(vertices[t[1]].cross(vertices[t[2]]));
  return six_v / 6.0;
}

double TriangleMesh::area() const {
  double a = 0.0;
  for (const auto& t : triangles) a += 0.5 * (vertices[t[1]] - vertices[t[0]]).cross(vertices[t[2]] - vertices[t[0]]).norm();
  return a;
}

void TriangleMesh::flip() {
  for (auto& t : triangles) std::swap(t[1], t[2]);
}

namespace {

/// STL stores each triangle with its own copies of the vertices: weld identical ones
/// so that shared edges are recognised.
int weld(TriangleMesh& mesh, std::map<std::array<double, 3>, int>& index, const Eigen::Vector3d& p) {
  const std::array<double, 3> key{p.x(), p.y(), p.z()};
  const auto it = index.find(key);
  if (it != index.end()) return it->second;
  mesh.vertices.push_back(p);
  const int k = static_cast<int>(mesh.vertices.size()) - 1;
  index.emplace(key, k);
  return k;
}

TriangleMesh readBinaryStl(const std::string& path, const std::string& bytes) {
  std::uint32_t count = 0;
  std::memcpy(&count, bytes.data() + 80, 4);
  TriangleMesh mesh;
  std::map<std::array<double, 3>, int> index;
  for (std::uint32_t k = 0; k < count; ++k) {
    const char* record = bytes.data() + 84 + 50 * static_cast<std::size_t>(k);
    std::array<int, 3> tri{};
    for (int v = 0; v < 3; ++v) {
      float xyz[3];
      std::memcpy(xyz, record + 12 + 12 * v, 12);
      tri[v] = weld(mesh, index, Eigen::Vector3d(xyz[0], xyz[1], xyz[2]));
    }
    mesh.triangles.push_back(tri);
  }
  if (mesh.triangles.empty()) throw std::runtime_error(path + ": the STL file has no triangles");
  return mesh;
}

TriangleMesh readAsciiStl(const std::string& path, const std::string& text) {
  TriangleMesh mesh;
  std::map<std::array<double, 3>, int> index;
  std::istringstream in(text);
  std::vector<int> pending;
  int line_number = 0;
  for (std::string line; std::getline(in, line);) {
    ++line_number;
    std::istringstream words(line);
    std::string word;
    words >> word;
    if (word == "vertex") {
      Eigen::Vector3d p;
      if (!(words >> p.x() >> p.y() >> p.z()))
        throw std::runtime_error(path + ":" + std::to_string(line_number) + ": expected 'vertex x y z'");
      pending.push_back(weld(mesh, index, p));
    } else if (word == "endloop") {
      if (pending.size() != 3)
        throw std::runtime_error(path + ":" + std::to_string(line_number) + ": a facet must have 3 vertices");
      mesh.triangles.push_back({pending[0], pending[1], pending[2]});
      pending.clear();
    }
  }
  if (mesh.triangles.empty()) throw std::runtime_error(path + ": the STL file has no facets");
  return mesh;
}

TriangleMesh readObj(const std::string& path, const std::string& text) {
  TriangleMesh mesh;
  std::istringstream in(text);
  int line_number = 0;
  for (std::string line; std::getline(in, line);) {
    ++line_number;
    std::istringstream words(line);
    std::string word;
    words >> word;
    const std::string where = path + ":" + std::to_string(line_number);
    if (word == "v") {
      Eigen::Vector3d p;
      if (!(words >> p.x() >> p.y() >> p.z())) throw std::runtime_error(where + ": expected 'v x y z'");
      mesh.vertices.push_back(p);
    } else if (word == "f") {
      std::vector<int> polygon;
      for (std::string corner; words >> corner;) {
        int k = 0;
        try {
          k = std::stoi(corner.substr(0, corner.find('/')));  // "v", "v/vt", "v//vn", "v/vt/vn"
        } catch (...) {
          throw std::runtime_error(where + ": bad face corner '" + corner + "'");
        }
        k = k < 0 ? static_cast<int>(mesh.vertices.size()) + k : k - 1;  // negative: relative
        if (k < 0 || k >= static_cast<int>(mesh.vertices.size()))
          throw std::runtime_error(where + ": face refers to a vertex not defined before it");
        polygon.push_back(k);
      }
      if (polygon.size() < 3) throw std::runtime_error(where + ": a face needs at least 3 vertices");
      for (std::size_t a = 1; a + 1 < polygon.size(); ++a) mesh.triangles.push_back({polygon[0], polygon[a], polygon[a + 1]});
    }
  }
  if (mesh.triangles.empty()) throw std::runtime_error(path + ": the OBJ file has no faces");
  return mesh;
}

}  // namespace

TriangleMesh readMesh(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot open the mesh file");
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string bytes = buffer.str();
  std::string ext = path.substr(path.find_last_of('.') == std::string::npos ? path.size() : path.find_last_of('.'));
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext == ".obj") return readObj(path, bytes);
  if (ext != ".stl") throw std::runtime_error(path + ": unknown mesh format (expected .stl or .obj)");
  // Binary STL: 80-byte header, count, 50 bytes per triangle. Some binary files also
  // start with "solid", so the size decides.
  if (bytes.size() >= 84) {
    std::uint32_t count = 0;
    std::memcpy(&count, bytes.data() + 80, 4);
    if (bytes.size() == 84 + 50 * static_cast<std::size_t>(count)) return readBinaryStl(path, bytes);
  }
  return readAsciiStl(path, bytes);
}

}  // namespace moorsph::io
