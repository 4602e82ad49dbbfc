// Triangle meshes (STL ASCII/binary, OBJ) sampled into boundary particles: a box mesh
// gives exactly fluid::sampleBoxSurface's particles and normals; a sphere mesh gives
// single outward radial normals at spacing <= s; inside tests by ray parity.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <moorsph/io/mesh_sampling.hpp>
#include <moorsph/io/primitive_shapes.hpp>

using namespace moorsph;
using Eigen::Vector3d;

namespace {

/// The 12 triangles of the box [lo, hi], wound counter-clockwise seen from outside.
io::TriangleMesh boxMesh(const Vector3d& lo, const Vector3d& hi) {
  io::TriangleMesh m;
  for (int k = 0; k < 8; ++k) m.vertices.emplace_back(k & 1 ? hi.x() : lo.x(), k & 2 ? hi.y() : lo.y(), k & 4 ? hi.z() : lo.z());
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    m.triangles.push_back({q[0], q[1], q[2]});
    m.triangles.push_back({q[0], q[2], q[3]});
  }
  return m;
}

void writeAsciiStl(const std::string& path, const io::TriangleMesh& m) {
  std::ofstream out(path);
  out << "solid box\n";
  for (const auto& t : m.triangles) {
    out << " facet normal 0 0 0\n  outer loop\n";
    for (int v : t) out << "   vertex " << m.vertices[v].x() << " " << m.vertices[v].y() << " " << m.vertices[v].z() << "\n";
    out << "  endloop\n endfacet\n";
  }
  out << "endsolid box\n";
}

void writeBinaryStl(const std::string& path, const io::TriangleMesh& m) {
  std::ofstream out(path, std::ios::binary);
  char header[80] = "solid binary file starting with the word solid";
  out.write(header, 80);
  const std::uint32_t n = m.triangles.size();
  out.write(reinterpret_cast<const char*>(&n), 4);
  for (const auto& t : m.triangles) {
    float record[12] = {0, 0, 0};
    for (int v = 0; v < 3; ++v)
      for (int d = 0; d < 3; ++d) record[3 + 3 * v + d] = static_cast<float>(m.vertices[t[v]][d]);
    out.write(reinterpret_cast<const char*>(record), 48);
    const std::uint16_t attributes = 0;
    out.write(reinterpret_cast<const char*>(&attributes), 2);
  }
}

/// An icosphere subdivided `levels` times: io::makeSphereMesh stops when the edge
/// (1.0515 R for the icosahedron, halved by each subdivision) is below its bound.
io::TriangleMesh sphereMesh(double radius, int levels) {
  const double edge = 1.0515 * radius / std::pow(2.0, levels);
  return io::makeSphereMesh(Vector3d::Zero(), radius, edge * (1.0 + 1e-9));
}

/// Every particle of `a` has one in `b` at the same place with the same normals.
void expectSameParticles(const fluid::BoundaryParticles<3>& a, const fluid::BoundaryParticles<3>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    std::size_t match = b.size();
    for (std::size_t j = 0; j < b.size(); ++j)
      if ((a.r[i] - b.r[j]).norm() < 1e-12) match = j;
    ASSERT_LT(match, b.size()) << "no particle at " << a.r[i].transpose();
    ASSERT_EQ(a.normalCount(i), b.normalCount(match)) << a.r[i].transpose();
    for (std::uint32_t x = a.normal_begin[i]; x < a.normal_begin[i + 1]; ++x) {
      bool found = false;
      for (std::uint32_t y = b.normal_begin[match]; y < b.normal_begin[match + 1]; ++y)
        found = found || (a.normals[x] - b.normals[y]).norm() < 1e-12;
      EXPECT_TRUE(found) << a.r[i].transpose();
    }
  }
}

}  // namespace

TEST(MeshSampling, BoxMeshGivesTheBoxLattice) {
  const Vector3d lo(0.0, 0.0, 0.0), hi(0.1, 0.06, 0.05);
  const auto reference = fluid::sampleBoxSurface<3>(lo, hi, 0.01, fluid::allFaces<3>(), fluid::NormalSide::Outward);
  const std::string path = testing::TempDir() + "box.stl";
  writeAsciiStl(path, boxMesh(lo, hi));
  const auto mesh = io::readMesh(path);
  EXPECT_EQ(mesh.vertices.size(), 8u);  // STL copies welded
  EXPECT_NEAR(mesh.signedVolume(), 0.1 * 0.06 * 0.05, 1e-15);
  expectSameParticles(reference, io::sampleMeshSurface(mesh, 0.01, fluid::NormalSide::Outward));
  // Inward normals for a container, the same lattice.
  const auto tank = fluid::sampleBoxSurface<3>(lo, hi, 0.01, fluid::allFaces<3>(), fluid::NormalSide::Inward);
  expectSameParticles(tank, io::sampleMeshSurface(mesh, 0.01, fluid::NormalSide::Inward));
}

TEST(MeshSampling, BinaryStlAndObjWithReversedWinding) {
  const Vector3d lo(-0.02, 0.01, 0.0), hi(0.05, 0.04, 0.03);
  auto box = boxMesh(lo, hi);
  const auto reference = fluid::sampleBoxSurface<3>(lo, hi, 0.007, fluid::allFaces<3>(), fluid::NormalSide::Outward);
  const std::string stl = testing::TempDir() + "box_binary.stl";
  writeBinaryStl(stl, box);
  const auto from_binary = io::readMesh(stl);
  EXPECT_EQ(from_binary.triangles.size(), 12u);
  EXPECT_NEAR(from_binary.signedVolume(), 0.07 * 0.03 * 0.03, 1e-9);  // float precision
  // OBJ with quads (split into fans), 1-based and negative indices, inward winding.
  const std::string obj = testing::TempDir() + "box.obj";
  {
    std::ofstream out(obj);
    out << "# box\n";
    for (const auto& v : box.vertices) out << "v " << v.x() << " " << v.y() << " " << v.z() << "\n";
    const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& q : quads) out << "f " << q[3] + 1 << "/1 " << q[2] + 1 << "//2 " << q[1] + 1 << " " << q[0] - 8 << "\n";
  }
  const auto from_obj = io::readMesh(obj);
  EXPECT_EQ(from_obj.triangles.size(), 12u);
  EXPECT_LT(from_obj.signedVolume(), 0.0);  // wound inward in the file...
  expectSameParticles(reference, io::sampleMeshSurface(from_obj, 0.007, fluid::NormalSide::Outward));  // ...normals still out
  EXPECT_THROW(io::readMesh(testing::TempDir() + "missing.obj"), std::runtime_error);
}

TEST(MeshSampling, SphereHasRadialNormalsAtTheSpacing) {
  const double radius = 0.1, s = 0.01;
  // A coarse mesh (edges ~1.3 s) and a fine one (edges ~0.33 s, 20480 triangles): both
  // sampled at about one particle per s^2, not at every vertex.
  for (const int levels : {3, 5}) {
    SCOPED_TRACE(levels);
    const auto mesh = sphereMesh(radius, levels);
    const auto b = io::sampleMeshSurface(mesh, s, fluid::NormalSide::Outward);
    double min_gap = 1e9, worst_cos = 1.0;
    for (std::size_t i = 0; i < b.size(); ++i) {
      ASSERT_EQ(b.normalCount(i), 1u);  // smooth: one averaged normal
      worst_cos = std::min(worst_cos, b.normals[b.normal_begin[i]].dot(b.r[i].normalized()));
      for (std::size_t j = i + 1; j < b.size(); ++j) min_gap = std::min(min_gap, (b.r[i] - b.r[j]).norm());
    }
    EXPECT_GT(worst_cos, 0.98);
    EXPECT_GE(min_gap, 0.75 * s * (1.0 - 1e-9));
    // No hole: every triangle centroid has a particle within the spacing.
    double worst_cover = 0.0;
    for (const auto& t : mesh.triangles) {
      const Vector3d c = (mesh.vertices[t[0]] + mesh.vertices[t[1]] + mesh.vertices[t[2]]) / 3.0;
      double nearest = 1e9;
      for (std::size_t j = 0; j < b.size(); ++j) nearest = std::min(nearest, (c - b.r[j]).norm());
      worst_cover = std::max(worst_cover, nearest);
    }
    EXPECT_LE(worst_cover, s);
    const double per_area = b.size() * s * s / mesh.area();
    EXPECT_GT(per_area, 0.8);
    EXPECT_LT(per_area, 1.3);
    std::printf("levels %d: %zu particles, %.3f per s^2, closest pair %.3f s, worst cover %.3f s\n", levels, b.size(),
                per_area, min_gap / s, worst_cover / s);
  }
  const auto mesh = sphereMesh(radius, 3);
  EXPECT_TRUE(io::meshContains(mesh, Vector3d(0.01, 0.02, -0.03)));
  EXPECT_FALSE(io::meshContains(mesh, Vector3d(0.08, 0.08, 0.0)));
  EXPECT_FALSE(io::meshContains(mesh, Vector3d(0.5, 0.0, 0.0)));
}

namespace {

/// Largest distance from a point of a sharp edge (looked at every spacing/20) to the
/// nearest particle carrying a normal within 30 degrees of each of the edge's faces.
struct EdgeCover {
  double distance = 0.0;  ///< the largest
  Vector3d where = Vector3d::Zero();
};
EdgeCover worstSharpEdgeCover(const io::TriangleMesh& mesh, const fluid::BoundaryParticles<3>& b, double spacing) {
  const double sign = mesh.signedVolume() > 0.0 ? 1.0 : -1.0;  // sampled Outward
  auto carries = [&b](std::size_t i, const Vector3d& n) {
    for (std::uint32_t x = b.normal_begin[i]; x < b.normal_begin[i + 1]; ++x)
      if (b.normals[x].dot(n) > std::cos(M_PI / 6.0)) return true;
    return false;
  };
  EdgeCover worst;
  for (const auto& e : io::sharpEdges(mesh)) {
    const int n = std::max(1, static_cast<int>(std::ceil(20.0 * (e.b - e.a).norm() / spacing)));
    for (int k = 0; k <= n; ++k) {
      const Vector3d q = e.a + (static_cast<double>(k) / n) * (e.b - e.a);
      double nearest = 1e300;
      for (std::size_t i = 0; i < b.size(); ++i) {
        const double d = (b.r[i] - q).norm();
        if (d < nearest && carries(i, sign * e.n1) && carries(i, sign * e.n2)) nearest = d;
      }
      if (nearest > worst.distance) worst = {nearest, q};
    }
  }
  return worst;
}

}  // namespace

TEST(MeshSampling, SharpEdgesOfABoxAreItsTwelveEdges) {
  const auto edges = io::sharpEdges(boxMesh(Vector3d(0, 0, 0), Vector3d(0.05, 0.03, 0.02)));
  ASSERT_EQ(edges.size(), 12u);  // the six face diagonals are flat
  for (const auto& e : edges) {
    EXPECT_NEAR(e.n1.dot(e.n2), 0.0, 1e-12);
    EXPECT_EQ((e.b - e.a).cwiseAbs().maxCoeff(), (e.b - e.a).norm());  // along an axis
  }
}

// The section 6.5 hull (cases/ship/hull_blunt.stl, 2.4 m triangles along its transom):
// every point of its sharp edges (transom outline, deck edge, keel, the blunt bow's cut)
// has, within 0.9 spacing, a particle with both faces' normals, so fluid beyond an edge
// is pushed off it by an edge particle's corner rule (boundary_force_law.hpp). 0.875
// spacing holds along one edge by construction (mesh_sampling.hpp); where edges meet,
// their particles crowd each other a little. At 6 m the bow's cut face is 4 m wide,
// narrower than the 4.5 m particles otherwise keep apart: the second of its side edges is
// covered because edge points excluded only by another edge's particles are kept down to
// 0.5 spacing (until session 39 it was not, 1.02 spacing, and fluid went into the bow
// there in the order-2 run at 6 m). Before the sharp-edge pass the worst edge point had no
// such particle within 15 spacings at 6 m (the transom's lower edge was bare) and none at
// all at 4 m.
TEST(MeshSampling, ShipHullSharpEdgesCarryBothNormals) {
  const char* root = std::getenv("MOORSPH_SOURCE_DIR");
  if (!root) GTEST_SKIP() << "MOORSPH_SOURCE_DIR not set";
  const auto mesh = io::readMesh(std::string(root) + "/cases/ship/hull_blunt.stl");
  const auto edges = io::sharpEdges(mesh);
  EXPECT_GT(edges.size(), 20u);
  for (const double s : {6.0, 4.0, 3.0, 2.0}) {
    SCOPED_TRACE(s);
    const auto b = io::sampleMeshSurface(mesh, s, fluid::NormalSide::Outward);
    const EdgeCover all = worstSharpEdgeCover(mesh, b, s);
    std::printf("hull at %.0f m: %zu particles, %zu sharp edges, worst edge cover %.3f spacing at (%.2f, %.2f, %.2f)\n",
                s, b.size(), edges.size(), all.distance / s, all.where.x(), all.where.y(), all.where.z());
    EXPECT_LE(all.distance, 0.9 * s);
    // The edge pass does not crowd the wall: particles keep 0.75 spacing apart, except
    // edge particles across a narrow face (both with two or more normals), 0.5.
    double min_gap = 1e300, min_face_gap = 1e300;
    for (std::size_t i = 0; i < b.size(); ++i)
      for (std::size_t j = i + 1; j < b.size(); ++j) {
        const double d = (b.r[i] - b.r[j]).norm();
        min_gap = std::min(min_gap, d);
        if (b.normalCount(i) < 2 || b.normalCount(j) < 2) min_face_gap = std::min(min_face_gap, d);
      }
    std::printf("  closest pair %.3f spacing, closest with a one-normal particle %.3f\n", min_gap / s, min_face_gap / s);
    EXPECT_GE(min_gap, 0.5 * s * (1.0 - 1e-9));
    EXPECT_GE(min_face_gap, 0.75 * s * (1.0 - 1e-9));
  }
}
