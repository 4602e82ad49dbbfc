#pragma once
// Writes a TriangleMesh as binary STL or Wavefront OBJ, so a generated surface (the ship
// hull) can be viewed and read back by io::readMesh. Both formats keep the winding
// (counter-clockwise seen from outside); binary STL stores single-precision coordinates.
#include <string>

#include <moorsph/io/triangle_mesh.hpp>

namespace moorsph::io {

/// Binary STL: 80-byte header, triangle count, per triangle the unit normal and the three
/// vertices as float32. Throws std::runtime_error naming the file if it cannot be written.
void writeStl(const std::string& path, const TriangleMesh& mesh);

/// OBJ: one `v x y z` per vertex (17 significant digits), one `f a b c` per triangle.
void writeObj(const std::string& path, const TriangleMesh& mesh);

/// writeStl or writeObj chosen by the extension (.stl or .obj, case-insensitive).
void writeMesh(const std::string& path, const TriangleMesh& mesh);

}  // namespace moorsph::io
