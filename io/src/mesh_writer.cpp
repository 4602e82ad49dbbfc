#include <moorsph/io/mesh_writer.hpp>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <stdexcept>

namespace moorsph::io {
namespace {

std::ofstream openForWriting(const std::string& path, std::ios::openmode mode) {
  std::ofstream out(path, mode);
  if (!out) throw std::runtime_error(path + ": cannot open the mesh file for writing");
  return out;
}

void putFloats(std::string& record, std::size_t at, const Eigen::Vector3d& v) {
  const float xyz[3] = {static_cast<float>(v.x()), static_cast<float>(v.y()), static_cast<float>(v.z())};
  std::memcpy(record.data() + at, xyz, 12);
}

}  // namespace

void writeStl(const std::string& path, const TriangleMesh& mesh) {
  std::ofstream out = openForWriting(path, std::ios::binary);
  std::string header(80, ' ');
  const std::string title = "moorsph binary STL";
  std::copy(title.begin(), title.end(), header.begin());
  out.write(header.data(), 80);
  const std::uint32_t count = static_cast<std::uint32_t>(mesh.triangles.size());
  out.write(reinterpret_cast<const char*>(&count), 4);
  std::string record(50, '\0');  // normal, 3 vertices, 2-byte attribute count (0)
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3d& a = mesh.vertices[t[0]];
    const Eigen::Vector3d& b = mesh.vertices[t[1]];
    const Eigen::Vector3d& c = mesh.vertices[t[2]];
    const Eigen::Vector3d n = (b - a).cross(c - a);
    putFloats(record, 0, n.norm() > 0.0 ? Eigen::Vector3d(n.normalized()) : Eigen::Vector3d::Zero());
    putFloats(record, 12, a);
    putFloats(record, 24, b);
    putFloats(record, 36, c);
    out.write(record.data(), 50);
  }
  if (!out) throw std::runtime_error(path + ": writing the STL file failed");
}

void writeObj(const std::string& path, const TriangleMesh& mesh) {
  std::ofstream out = openForWriting(path, std::ios::out);
  out.precision(17);
  out << "# moorsph triangle mesh: " << mesh.vertices.size() << " vertices, " << mesh.triangles.size() << " triangles\n";
  for (const auto& v : mesh.vertices) out << "v " << v.x() << ' ' << v.y() << ' ' << v.z() << '\n';
  for (const auto& t : mesh.triangles) out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
  if (!out) throw std::runtime_error(path + ": writing the OBJ file failed");
}

void writeMesh(const std::string& path, const TriangleMesh& mesh) {
  const auto dot = path.find_last_of('.');
  std::string ext = dot == std::string::npos ? "" : path.substr(dot);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext == ".stl") return writeStl(path, mesh);
  if (ext == ".obj") return writeObj(path, mesh);
  throw std::runtime_error(path + ": unknown mesh format (expected .stl or .obj)");
}

}  // namespace moorsph::io
