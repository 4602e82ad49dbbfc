// The `bodies`, `moorings` and `coupling` sections of a scene file
// (docs/scene-reference.md). Checks what can be checked without building the
// multibody system: sizes against dx, positive mass, a physical inertia tensor; the
// lines are read by scene_mooring_reader.cpp.
#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <moorsph/io/mesh_sampling.hpp>
#include <moorsph/io/primitive_shapes.hpp>
#include "scene_sections.hpp"

namespace moorsph::io::detail {
namespace {

const double kPi = 3.14159265358979323846;

void failSmall(MapReader& m, const std::string& key, const std::string& what, double size, double least, double dx) {
  char msg[240];
  std::snprintf(msg, sizeof msg,
                "the body's %s is %g m, finer than the resolution allows (at least %g m at dx = %g m): the body "
                "would be smaller than a few particles; refine resolution.dx or enlarge the body",
                what.c_str(), size, least, dx);
  m.fail(key, msg);
}

void readSphereOrCylinder(MapReader& m, const std::string& kind, BodyShapeConfig& s, const SceneConfig& c) {
  s.centre = toTriple(m.vector("centre", c.dim, std::vector<double>(c.dim, 0.0)));
  s.radius = m.positive("radius", 0.0, "radius [m]");
  if (s.radius < c.dx * (1.0 - 1e-9)) failSmall(m, "radius", "radius", s.radius, c.dx, c.dx);
  if (kind == "sphere" && c.dim == 3) {
    s.sampling = m.text("sampling", "fibonacci");
    if (s.sampling != "fibonacci" && s.sampling != "rings")
      m.fail("sampling", "expected fibonacci or rings, got '" + s.sampling + "'");
  }
  if (kind == "cylinder" && c.dim == 3) {
    s.length = m.positive("length", 0.0, "length along the axis [m]");
    if (s.length < 2.0 * c.dx * (1.0 - 1e-9)) failSmall(m, "length", "length", s.length, 2.0 * c.dx, c.dx);
    const std::string axis = m.text("axis", "z");
    if (axis != "x" && axis != "y" && axis != "z") m.fail("axis", "expected x, y or z, got '" + axis + "'");
    s.axis = axis[0] - 'x';
    const Eigen::Vector3d at(s.centre[0], s.centre[1], s.centre[2]);
    s.mesh = makeCylinderMesh(at, s.radius, s.length, s.axis, 0.5 * c.spacing());
  }
}

void readBox(MapReader& m, BodyShapeConfig& s, const SceneConfig& c) {
  s.centre = toTriple(m.vector("centre", c.dim, std::vector<double>(c.dim, 0.0)));
  s.size = toTriple(m.vector("size", c.dim));
  for (int k = 0; k < c.dim; ++k) {
    if (!(s.size[k] > 0.0)) m.fail("size", "expected edge lengths > 0 [m]");
    if (s.size[k] < 2.0 * c.dx * (1.0 - 1e-9)) failSmall(m, "size", std::string("edge along ") + "xyz"[k], s.size[k], 2.0 * c.dx, c.dx);
  }
}

void readMeshShape(MapReader& m, BodyShapeConfig& s, const SceneConfig& c) {
  if (c.dim != 3) m.fail("file", "a mesh body is 3D only (dim: 3); in 2D use a box, cylinder or sphere");
  s.file = m.requiredText("file");
  const std::filesystem::path file(s.file);
  s.path = file.is_absolute() ? s.file : (std::filesystem::path(c.file).parent_path() / file).string();
  s.scale = m.positive("scale", 1.0, "factor from file units to metres");
  s.translate = toTriple(m.vector("translate", 3, {0.0, 0.0, 0.0}));
  try {
    s.mesh = readMesh(s.path);
  } catch (const std::exception& e) {
    m.fail("file", std::string("cannot use the mesh: ") + e.what());
  }
  for (auto& v : s.mesh.vertices) v = s.scale * v + Eigen::Vector3d(s.translate[0], s.translate[1], s.translate[2]);
  const Eigen::Vector3d size = s.mesh.upper() - s.mesh.lower();
  if (std::abs(s.mesh.signedVolume()) < 1e-12 * std::pow(size.maxCoeff(), 3))
    m.fail("file", "the mesh encloses no volume: a body's mesh must be a closed surface");
  for (int k = 0; k < 3; ++k)
    if (size[k] < 2.0 * c.dx * (1.0 - 1e-9)) failSmall(m, "file", std::string("extent along ") + "xyz"[k], size[k], 2.0 * c.dx, c.dx);
}

void readShape(MapReader& b, BodyConfig& body, const SceneConfig& c) {
  if (!b.has("shape")) b.fail("shape", "required key is missing (expected one of sphere:, box:, cylinder:, mesh: with its keys)");
  const YAML::Node node = b.child("shape");
  const std::string path = b.childPath("shape");
  if (!node.IsMap() || node.size() != 1)
    b.source().fail(node, path, "expected one of 'sphere:', 'box:', 'cylinder:', 'mesh:' followed by its keys");
  MapReader one(node, path, b.source());
  const std::string kind = node.begin()->first.as<std::string>();
  for (const char* k : {"sphere", "box", "cylinder", "mesh"})
    if (kind != k) one.child(k);
  if (kind != "sphere" && kind != "box" && kind != "cylinder" && kind != "mesh") one.finish();  // unknown word: hint
  MapReader m(one.child(kind), path + "." + kind, b.source());
  body.shape.kind = kind;
  if (kind == "box") readBox(m, body.shape, c);
  else if (kind == "mesh") readMeshShape(m, body.shape, c);
  else readSphereOrCylinder(m, kind, body.shape, c);
  m.finish();
  one.finish();
}

/// 3D: [Ixx, Iyy, Izz] or [Ixx, Iyy, Izz, Ixy, Ixz, Iyz]; 2D: Izz (a number).
void readInertia(MapReader& b, BodyConfig& body, const SceneConfig& c) {
  if (!b.has("inertia"))
    b.fail("inertia", c.dim == 2 ? "required key is missing (expected Izz about the centre of mass [kg m^2/m])"
                                 : "required key is missing (expected [Ixx, Iyy, Izz] or [Ixx, Iyy, Izz, Ixy, Ixz, Iyz] "
                                   "about the centre of mass [kg m^2])");
  Eigen::Matrix3d I = Eigen::Matrix3d::Zero();
  if (c.dim == 2) {
    const double izz = b.positive("inertia", 0.0, "moment of inertia about the centre of mass, z axis [kg m^2/m]");
    // Planar bodies: Simbody still needs a full, physical tensor; x and y moments
    // play no part in the planar motion.
    I.diagonal() << izz / 2.0, izz / 2.0, izz;
  } else {
    const YAML::Node n = b.child("inertia");
    const std::string expected = "expected [Ixx, Iyy, Izz] or [Ixx, Iyy, Izz, Ixy, Ixz, Iyz] [kg m^2]";
    if (!n.IsSequence() || (n.size() != 3 && n.size() != 6)) b.fail("inertia", expected + ", got " + describeNode(n));
    const std::vector<double> v = b.vector("inertia", n.size());
    I.diagonal() << v[0], v[1], v[2];
    if (v.size() == 6) {
      I(0, 1) = I(1, 0) = v[3];
      I(0, 2) = I(2, 0) = v[4];
      I(1, 2) = I(2, 1) = v[5];
    }
  }
  // A rigid body's inertia tensor is positive definite and its principal moments
  // satisfy the triangle inequality I1 + I2 >= I3 (each is a sum of two second moments).
  const Eigen::Vector3d p = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(I).eigenvalues();
  if (!(p.minCoeff() > 0.0)) {
    char msg[200];
    std::snprintf(msg, sizeof msg, "the inertia tensor is not positive definite (principal moments %g, %g, %g kg m^2)",
                  p[0], p[1], p[2]);
    b.fail("inertia", msg);
  }
  if (p[0] + p[1] < p[2] * (1.0 - 1e-9)) {
    char msg[200];
    std::snprintf(msg, sizeof msg,
                  "no rigid body has these principal moments (%g + %g < %g kg m^2: they must satisfy I1 + I2 >= I3)",
                  p[0], p[1], p[2]);
    b.fail("inertia", msg);
  }
  for (int r = 0; r < 3; ++r)
    for (int k = 0; k < 3; ++k) body.inertia[r][k] = I(r, k);
}

void readFixed(MapReader& b, BodyConfig& body, const SceneConfig& c) {
  const std::vector<std::string> words = c.dim == 2 ? std::vector<std::string>{"x", "y", "rz"}
                                                    : std::vector<std::string>{"x", "y", "z", "rx", "ry", "rz"};
  const std::vector<std::string> all{"x", "y", "z", "rx", "ry", "rz"};
  for (const auto& w : b.textList("fixed", {})) {
    if (std::find(words.begin(), words.end(), w) == words.end()) {
      std::string list;
      for (const auto& k : words) list += (list.empty() ? "" : ", ") + k;
      b.fail("fixed", "unknown degree of freedom '" + w + "'; expected among " + list);
    }
    body.fixed[std::find(all.begin(), all.end(), w) - all.begin()] = true;
  }
}

bool surfaceNameTaken(const SceneConfig& c, const std::string& name) {
  for (const auto& t : c.tanks) if (t.name == name) return true;
  for (const auto& b : c.boxes) if (b.name == name) return true;
  for (const auto& m : c.meshes) if (m.name == name) return true;
  for (const auto& k : c.circles) if (k.name == name) return true;
  return c.bodyIndex(name) >= 0;
}

/// bodies[].points: {name: [x, y(, z)], ...} in the body frame.
void readPoints(MapReader& b, BodyConfig& body, const SceneConfig& c) {
  const YAML::Node node = b.child("points");
  if (!node.IsDefined() || node.IsNull()) return;
  if (!node.IsMap()) b.fail("points", "expected a map of named body-frame points, e.g. {bow: [0, 23.5, 0]}, got " + describeNode(node));
  MapReader m(node, b.childPath("points"), b.source());
  for (const auto& item : node) {
    const std::string name = item.first.as<std::string>();
    if (name == "com") m.fail(name, "'com' is recorded anyway (the centre of mass); pick another name");
    body.points.emplace_back(name, toTriple(m.vector(name, c.dim)));
  }
  m.finish();
}

/// The deck outline file: rows x, z or x, y, z (y ignored), body frame [m].
void readOutlineFile(MapReader& m, BodyConfig& body, const SceneConfig& c) {
  body.deck_outline_file = resolveSceneFile(c, m.requiredText("outline_file"));
  for (const NumberRow& row : readNumberRows(m, "outline_file", body.deck_outline_file, "deck outline")) {
    if (row.values.size() != 2 && row.values.size() != 3)
      m.fail("outline_file", body.deck_outline_file + ":" + std::to_string(row.line) + ": expected x, z or x, y, z [m]");
    body.deck_outline.push_back({row.values.front(), row.values.back()});
  }
  if (body.deck_outline.size() < 3) m.fail("outline_file", "the deck outline needs at least three vertices (x, z)");
}

/// bodies[].green_water: {deck_height, outline_file (3D) | x_range (2D)}.
void readGreenWater(MapReader& b, BodyConfig& body, const SceneConfig& c) {
  const YAML::Node node = b.child("green_water");
  if (!node.IsDefined() || node.IsNull()) return;
  MapReader m(node, b.childPath("green_water"), b.source());
  body.green_water = true;
  body.deck_height = m.requiredNumber("deck_height");
  if (c.dim == 3) {
    readOutlineFile(m, body, c);
  } else {
    const auto r = m.vector("x_range", 2);
    if (!(r[1] > r[0])) m.fail("x_range", "expected [x_min, x_max] with x_max > x_min [m]");
    body.deck_outline = {{r[0], 0.0}, {r[1], 0.0}};
  }
  m.finish();
}

BodyConfig readBody(MapReader& b, const SceneConfig& c, std::size_t index) {
  BodyConfig body;
  body.name = b.text("name", "body" + std::to_string(index));
  if (surfaceNameTaken(c, body.name)) b.fail("name", "another body or surface is already named '" + body.name + "'");
  body.mass = b.requiredNumber("mass");
  if (!(body.mass > 0.0))
    b.fail("mass", std::string("expected a mass > 0 [") + (c.dim == 2 ? "kg per metre of span" : "kg") + "], got " +
                       describeNode(b.node()["mass"]));
  body.centre_of_mass = toTriple(b.vector("centre_of_mass", c.dim, std::vector<double>(c.dim, 0.0)));
  readInertia(b, body, c);
  readFixed(b, body, c);
  body.position = toTriple(b.vector("position", c.dim));
  if (c.dim == 2) {
    body.orientation[1] = b.number("orientation_deg", 0.0) * kPi / 180.0;  // about z: pitch
  } else {
    const auto o = b.vector("orientation_deg", 3, {0.0, 0.0, 0.0});
    for (int k = 0; k < 3; ++k) body.orientation[k] = o[k] * kPi / 180.0;
  }
  body.offset = toTriple(b.vector("offset", c.dim, std::vector<double>(c.dim, 0.0)));
  body.velocity = toTriple(b.vector("velocity", c.dim, std::vector<double>(c.dim, 0.0)));
  readShape(b, body, c);
  readPoints(b, body, c);
  readGreenWater(b, body, c);
  body.where.text = b.source().locate(b.node(), b.path());
  // The body must start in the water's container (or the domain).
  const Triple s = body.start();
  bool inside = c.tanks.empty() && !c.domain_given;
  auto within = [&](const BoxExtent& e) {
    for (int k = 0; k < c.dim; ++k)
      if (s[k] < e.lower[k] || s[k] > e.upper[k]) return false;
    return true;
  };
  for (const auto& t : c.tanks) inside = inside || within(t.box);
  if (c.domain_given) inside = inside || within(c.domain);
  if (!inside) b.fail("position", "the body's reference point (position + offset) lies outside every tank and the domain");
  return body;
}

}  // namespace

void readBodies(MapReader& top, SceneConfig& c) {
  forEachListEntry(top, "bodies", "rigid bodies", [&](MapReader& b, std::size_t i) {
    c.bodies.push_back(readBody(b, c, i));
    b.finish();
  });
  const YAML::Node lines = top.child("moorings");
  if (lines.IsDefined() && !lines.IsNull()) {
    if (!lines.IsSequence()) top.fail("moorings", "expected a list of mooring lines, got " + describeNode(lines));
    if (c.bodies.empty()) top.fail("moorings", "mooring lines need bodies (the 'bodies' list is empty)");
    for (std::size_t i = 0; i < lines.size(); ++i) {
      MapReader m(lines[i], "moorings[" + std::to_string(i) + "]", top.source());
      c.moorings.push_back(readMooring(m, c, i));
    }
  }
  if (top.has("coupling")) {
    MapReader m(top.child("coupling"), "coupling", top.source());
    c.coupling.release_time = m.positive("release_time", 0.0, "bodies held while the fluid settles [s]", true);
    c.coupling.ramp_time = m.positive("ramp_time", 0.0, "fluid load ramped in after release [s]", true);
    c.coupling.max_step = m.positive("max_body_step", c.coupling.max_step, "largest internal step of the body integrator [s]");
    if (c.bodies.empty()) top.fail("coupling", "the scene has no bodies to couple");
    m.finish();
  } else {
    top.child("coupling");
  }
  if (!c.bodies.empty() && !c.hasEffect("walls"))
    top.fail("effects", "the scene has bodies but 'walls' is not in its effects (bodies are boundary surfaces)");
}

}  // namespace moorsph::io::detail
