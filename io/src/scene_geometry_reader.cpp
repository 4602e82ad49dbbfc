// Geometry and sensor sections of a scene file.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <moorsph/fluid/packing_probe.hpp>
#include <moorsph/io/body_geometry.hpp>
#include <moorsph/io/mesh_sampling.hpp>
#include <moorsph/io/primitive_shapes.hpp>
#include "scene_sections.hpp"

namespace moorsph::io::detail {
namespace {

const char* const kAxis = "xyz";

BoxExtent readExtent(MapReader& m, const SceneConfig& c, double min_edge, const std::string& what) {
  BoxExtent b;
  b.lower = toTriple(m.vector("lower", c.dim));
  b.upper = toTriple(m.vector("upper", c.dim));
  for (int k = 0; k < c.dim; ++k) {
    const double edge = b.upper[k] - b.lower[k];
    if (!(edge > 0.0)) m.fail("upper", std::string("expected upper > lower along ") + kAxis[k] + " [m]");
    if (edge < min_edge * (1.0 - 1e-9)) {
      char msg[240];
      std::snprintf(msg, sizeof msg,
                    "the %s is %g m along %c, finer than the resolution allows (at least %g m at dx = %g m); "
                    "refine resolution.dx or enlarge it",
                    what.c_str(), edge, kAxis[k], min_edge, c.dx);
      m.fail("upper", msg);
    }
  }
  return b;
}

bool inside(const BoxExtent& inner, const BoxExtent& outer, int dim) {
  const double tol = 1e-9;
  for (int k = 0; k < dim; ++k)
    if (inner.lower[k] < outer.lower[k] - tol || inner.upper[k] > outer.upper[k] + tol) return false;
  return true;
}

std::string uniqueName(const SceneConfig& c, const std::string& name) {
  for (const auto& t : c.tanks) if (t.name == name) return "";
  for (const auto& b : c.boxes) if (b.name == name) return "";
  for (const auto& m : c.meshes) if (m.name == name) return "";
  for (const auto& k : c.circles) if (k.name == name) return "";
  return name;
}

/// `sphere` (3D) or `cylinder` (3D: a mesh; 2D: a circle).
void readPrimitive(MapReader& m, const std::string& kind, SceneConfig& c) {
  const std::string name = m.text("name", kind + std::to_string(c.meshes.size() + c.circles.size()));
  if (uniqueName(c, name).empty()) m.fail("name", "another surface is already named '" + name + "'");
  const auto centre = m.vector("centre", c.dim);
  const double radius = m.positive("radius", 0.0, "radius [m]");
  if (radius < c.dx * (1.0 - 1e-9)) {
    char msg[200];
    std::snprintf(msg, sizeof msg, "the %s's radius %g m is finer than the resolution allows (at least dx = %g m)",
                  kind.c_str(), radius, c.dx);
    m.fail("radius", msg);
  }
  if (c.dim == 2) {
    if (kind == "sphere") m.fail("radius", "a sphere is 3D only; in 2D use a cylinder (a circle in the x-y plane)");
    CircleConfig k;
    k.name = name;
    k.x = centre[0];
    k.y = centre[1];
    k.radius = radius;
    m.finish();
    c.circles.push_back(k);
    return;
  }
  MeshConfig g;
  g.name = name;
  g.shape = kind;
  g.centre = toTriple(centre);
  g.radius = radius;
  const Eigen::Vector3d at(centre[0], centre[1], centre[2]);
  if (kind == "sphere") {
    g.mesh = makeSphereMesh(at, radius, 0.5 * c.spacing());
  } else {
    g.length = m.positive("length", 0.0, "length along the axis [m]");
    if (g.length < 2.0 * c.dx * (1.0 - 1e-9)) m.fail("length", "expected a length of at least 2 dx [m]");
    const std::string axis = m.text("axis", "z");
    if (axis != "x" && axis != "y" && axis != "z") m.fail("axis", "expected x, y or z, got '" + axis + "'");
    g.axis = axis[0] - 'x';
    g.mesh = makeCylinderMesh(at, radius, g.length, g.axis, 0.5 * c.spacing());
  }
  m.finish();
  c.meshes.push_back(std::move(g));
}

MeshConfig readMeshItem(MapReader& m, const SceneConfig& c) {
  MeshConfig g;
  g.name = m.text("name", "mesh" + std::to_string(c.meshes.size()));
  g.file = m.requiredText("file");
  const std::filesystem::path file(g.file);
  g.path = file.is_absolute() ? g.file : (std::filesystem::path(c.file).parent_path() / file).string();
  g.scale = m.positive("scale", 1.0, "factor from file units to metres");
  g.translate = toTriple(m.vector("translate", 3, {0.0, 0.0, 0.0}));
  const std::string normals = m.text("normals", "outward");
  if (normals != "outward" && normals != "inward")
    m.fail("normals", "expected 'outward' (an obstacle or body in the fluid) or 'inward' (a container), got '" + normals + "'");
  g.inward = normals == "inward";
  if (c.dim != 3) m.fail("file", "mesh geometry is 3D only (dim: 3)");
  try {
    g.mesh = readMesh(g.path);
  } catch (const std::exception& e) {
    m.fail("file", std::string("cannot use the mesh: ") + e.what());
  }
  for (auto& v : g.mesh.vertices) v = g.scale * v + Eigen::Vector3d(g.translate[0], g.translate[1], g.translate[2]);
  if (std::abs(g.mesh.signedVolume()) < 1e-12 * std::pow(g.mesh.upper().x() - g.mesh.lower().x(), 3))
    m.fail("file", "the mesh encloses no volume: it must be a closed surface");
  const Eigen::Vector3d size = g.mesh.upper() - g.mesh.lower();
  for (int k = 0; k < 3; ++k)
    if (size[k] < 2.0 * c.dx * (1.0 - 1e-9)) {
      char msg[240];
      std::snprintf(msg, sizeof msg,
                    "the mesh is %g m along %c, finer than the resolution allows (at least %g m at dx = %g m); "
                    "refine resolution.dx or check 'scale'",
                    size[k], kAxis[k], 2.0 * c.dx, c.dx);
      m.fail("file", msg);
    }
  if (uniqueName(c, g.name).empty()) m.fail("name", "another surface is already named '" + g.name + "'");
  return g;
}

/// Distance [m] from a point to the surface of an axis-aligned box (inside or out).
double distanceToBox(const BoxExtent& b, const Triple& p, int dim) {
  double outside2 = 0.0, inside = 1e300;
  bool in = true;
  for (int k = 0; k < dim; ++k) {
    const double below = b.lower[k] - p[k], above = p[k] - b.upper[k];
    const double out = std::max({below, above, 0.0});
    outside2 += out * out;
    in = in && out == 0.0;
    inside = std::min(inside, std::min(-below, -above));
  }
  return in ? inside : std::sqrt(outside2);
}

/// Distance [m] from a probe's point to the named surface.
double distanceToSurface(const SceneConfig& c, const std::string& name, const Triple& p) {
  for (const auto& t : c.tanks)
    if (t.name == name) return distanceToBox(t.box, p, c.dim);
  for (const auto& b : c.boxes)
    if (b.name == name) return distanceToBox(b.box, p, c.dim);
  for (const auto& g : c.meshes)
    if (g.name == name) return distanceToMesh(g.mesh, Eigen::Vector3d(p[0], p[1], p[2]));
  for (const auto& k : c.circles)
    if (k.name == name) return std::abs(std::hypot(p[0] - k.x, p[1] - k.y) - k.radius);
  return 0.0;
}

/// Distance [m] from a body-frame point to the sampled surface of the named body.
double distanceToBodySurface(const SceneConfig& c, const std::string& name, const Triple& p) {
  double best = std::numeric_limits<double>::infinity();
  for (const auto& b : c.bodies) {
    if (b.name != name) continue;
    const Eigen::Vector3d point(p[0], p[1], p[2]);
    auto nearest = [&](const auto& particles, const Triple& start) {
      for (const auto& r : particles.r) {
        Eigen::Vector3d offset = Eigen::Vector3d::Zero();
        for (int k = 0; k < r.size(); ++k) offset[k] = r[k] - start[k];
        best = std::min(best, (offset - point).norm());
      }
    };
    if (c.dim == 2) nearest(sampleBodySurface<2>(b, c.spacing()), b.start());
    else nearest(sampleBodySurface<3>(b, c.spacing()), b.start());
  }
  return best;
}

}  // namespace

Triple toTriple(const std::vector<double>& v) {
  Triple t{0.0, 0.0, 0.0};
  for (std::size_t k = 0; k < v.size() && k < 3; ++k) t[k] = v[k];
  return t;
}

void readGeometry(MapReader& top, SceneConfig& c) {
  const YAML::Node list = top.child("geometry");
  if (!list.IsDefined() || list.IsNull()) top.fail("geometry", "required key is missing (expected a list with at least one water block)");
  if (!list.IsSequence()) top.fail("geometry", "expected a list of items (tank, water, box), got " + describeNode(list));
  const YamlSource& src = top.source();
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string item_path = "geometry[" + std::to_string(i) + "]";
    const YAML::Node item = list[i];
    if (!item.IsMap() || item.size() != 1)
      src.fail(item, item_path, "expected one of 'tank:', 'water:', 'box:', 'mesh:', 'sphere:', 'cylinder:' followed by its keys");
    MapReader one(item, item_path, src);
    one.rejectUnsupported({"stl", "obj", "body"}, "geometry items are tank, water, box, mesh, sphere and cylinder");
    const std::string kind = item.begin()->first.as<std::string>();
    for (const char* k : {"tank", "water", "box", "mesh", "sphere", "cylinder"})
      if (kind != k) one.child(k);  // known here, for the misspelling hint
    if (kind == "tank") {
      MapReader m(one.child("tank"), item_path + ".tank", src);
      TankConfig t;
      t.name = m.text("name", "tank");
      t.box = readExtent(m, c, 2.0 * c.dx, "tank");
      t.lid = m.boolean("lid", false);
      const std::string floor = m.text("floor", "walls");
      if (floor != "walls" && floor != "mirror")
        m.fail("floor", "expected 'walls' (a row of boundary particles) or 'mirror' (the mirror_floor effect), got '" +
                            floor + "'");
      t.mirror_floor = floor == "mirror";
      const std::string sides = m.text("sides", "walls");
      if (sides != "walls" && sides != "mirror")
        m.fail("sides", "expected 'walls' (boundary particles) or 'mirror' (the mirror_walls effect), got '" + sides + "'");
      t.mirror_sides = sides == "mirror";
      for (int k = 0; k < c.dim && t.mirror_sides; ++k)
        if (k != 1 && c.periodic[k])
          m.fail("sides", "'mirror' needs side walls, but the domain is periodic along " + std::string(k == 0 ? "x" : "z"));
      t.where.text = src.locate(item, item_path);
      if (uniqueName(c, t.name).empty()) m.fail("name", "another surface is already named '" + t.name + "'");
      m.finish();
      c.tanks.push_back(t);
    } else if (kind == "water") {
      MapReader m(one.child("water"), item_path + ".water", src);
      WaterConfig w;
      w.box = readExtent(m, c, c.dx, "water block");
      w.packed = m.boolean("packed", w.packed);
      w.packing_iterations = m.integer("packing_iterations", w.packing_iterations);
      if (w.packing_iterations < 1) m.fail("packing_iterations", "expected a positive number of iterations");
      if (m.has("packing_iterations") && !w.packed) m.fail("packing_iterations", "set 'packed: true' as well, or drop the key");
      w.where.text = src.locate(item, item_path);
      m.finish();
      bool contained = c.tanks.empty();
      for (const auto& t : c.tanks) contained = contained || inside(w.box, t.box, c.dim);
      if (!contained) m.fail("lower", "the water block must lie inside a tank listed before it");
      if (c.domain_given && !inside(w.box, c.domain, c.dim)) m.fail("lower", "the water block must lie inside the domain");
      c.water.push_back(w);
    } else if (kind == "box") {
      MapReader m(one.child("box"), item_path + ".box", src);
      BoxObstacleConfig b;
      b.name = m.text("name", "box" + std::to_string(c.boxes.size()));
      b.box = readExtent(m, c, 2.0 * c.dx, "box");
      b.open_faces = m.textList("open_faces", {});
      for (const auto& f : b.open_faces) {
        const bool ok = f.size() == 2 && (f[0] == '-' || f[0] == '+') && f[1] >= 'x' && f[1] < 'x' + c.dim;
        if (!ok) m.fail("open_faces", "expected faces among -x, +x, -y, +y" + std::string(c.dim == 3 ? ", -z, +z" : "") + ", got '" + f + "'");
      }
      b.where.text = src.locate(item, item_path);
      if (uniqueName(c, b.name).empty()) m.fail("name", "another surface is already named '" + b.name + "'");
      m.finish();
      c.boxes.push_back(b);
    } else if (kind == "mesh") {
      MapReader m(one.child("mesh"), item_path + ".mesh", src);
      MeshConfig g = readMeshItem(m, c);
      m.finish();
      c.meshes.push_back(std::move(g));
    } else if (kind == "sphere" || kind == "cylinder") {
      MapReader m(one.child(kind), item_path + "." + kind, src);
      readPrimitive(m, kind, c);
    }
    one.finish();
  }
  if (c.water.empty()) top.fail("geometry", "the scene has no water block (add '- water: {lower: [...], upper: [...]}')");
  const bool has_walls = std::find(c.effects.begin(), c.effects.end(), "walls") != c.effects.end();
  const bool tank_particles = std::any_of(c.tanks.begin(), c.tanks.end(), [&](const TankConfig& t) { return c.hasWallParticles(t); });
  const bool surfaces = tank_particles || !c.boxes.empty() || !c.meshes.empty() || !c.circles.empty();
  if (!has_walls && surfaces) top.fail("effects", "the scene has tanks, boxes or meshes but 'walls' is not in its effects");
}

void readVelocityProbes(MapReader& top, SceneConfig& c) {
  forEachListEntry(top, "velocity_probes", "probes", [&](MapReader& m, std::size_t i) {
    VelocityProbeConfig p;
    p.name = m.text("name", "V" + std::to_string(i + 1));
    p.point = toTriple(m.vector("point", c.dim));
    p.min_fill = m.number("min_fill", p.min_fill);
    if (!(p.min_fill > 0.0 && p.min_fill < 1.0)) m.fail("min_fill", "expected a particle density in (0, 1) [-]");
    for (int a = 0; c.domain_given && a < c.dim; ++a)
      if (p.point[a] < c.domain.lower[a] || p.point[a] > c.domain.upper[a])
        m.fail("point", "the point is outside the scene's domain");
    m.finish();
    c.velocity_probes.push_back(p);
  });
}

// A box of grid points; the grid spacing defaults to fluid::kPackingSpacingPerDx dx (the
// reader's c.dx is set by now).
void readPackingProbes(MapReader& top, SceneConfig& c) {
  forEachListEntry(top, "packing_probes", "probes", [&](MapReader& m, std::size_t i) {
    PackingProbeConfig p;
    p.name = m.text("name", "pack" + std::to_string(i + 1));
    p.lower = toTriple(m.vector("lower", c.dim));
    p.upper = toTriple(m.vector("upper", c.dim));
    for (int a = 0; a < c.dim; ++a)
      if (!(p.upper[a] > p.lower[a])) m.fail("upper", "each coordinate must exceed lower's");
    p.spacing = m.number("spacing", p.spacing);
    if (p.spacing < 0.0) m.fail("spacing", "expected a grid spacing > 0 [m] (or 0 for 0.618 dx)");
    double points = 1.0;
    for (int a = 0; a < c.dim; ++a) points *= (p.upper[a] - p.lower[a]) / (p.spacing > 0.0 ? p.spacing : fluid::kPackingSpacingPerDx * c.dx);
    if (points > 1e7) m.fail("spacing", "the box holds more than 1e7 grid points; give a larger spacing");
    p.min_fill = m.number("min_fill", p.min_fill);
    if (!(p.min_fill > 0.0 && p.min_fill < 1.0)) m.fail("min_fill", "expected a particle density in (0, 1) [-]");
    p.warn_rise = m.positive("warn_rise", p.warn_rise, "rise of the mean xi the log notes [-] (0: never)", true);
    m.finish();
    c.packing_probes.push_back(p);
  });
}

void readSensors(MapReader& top, SceneConfig& c) {
  forEachListEntry(top, "gauges", "wave gauges", [&](MapReader& m, std::size_t i) {
    GaugeConfig g;
    g.name = m.text("name", "G" + std::to_string(i + 1));
    g.x = m.requiredNumber("x");
    g.z = c.dim == 3 ? m.requiredNumber("z") : 0.0;
    g.bottom = m.number("bottom", 0.0);
    g.top = m.requiredNumber("top");
    g.threshold = m.number("threshold", g.threshold);
    g.volume_edge = m.boolean("volume_edge", g.volume_edge);
    if (!(g.top > g.bottom)) m.fail("top", "expected top > bottom [m]");
    if (!(g.threshold > 0.0 && g.threshold < 1.0)) m.fail("threshold", "expected xi_t in (0, 1) (METHOD.md section 3: 0.8)");
    m.finish();
    c.gauges.push_back(g);
  });
  forEachListEntry(top, "pressure_probes", "probes", [&](MapReader& m, std::size_t i) {
    ProbeConfig p;
    p.name = m.text("name", "P" + std::to_string(i + 1));
    p.surface = m.requiredText("surface");
    p.point = toTriple(m.vector("point", c.dim));
    p.normal = toTriple(m.vector("normal", c.dim));
    p.radius = m.positive("radius", c.dx, "patch radius [m]");
    p.interpolation_offset = m.positive("interpolation_offset", 1.5 * c.dx, "distance in front of the wall [m]");
    p.moving_mean = m.positive("moving_mean", 0.0, "window of the trailing moving mean [s]", true);
    if (std::hypot(p.normal[0], p.normal[1], p.normal[2]) == 0.0) m.fail("normal", "expected a non-zero normal into the fluid");
    bool found = false;
    std::vector<std::string> names;
    const auto fixedSurfaces = [&](auto& list) {  // tanks, boxes, meshes, circles: track the one named
      for (auto& surface : list) {
        names.push_back(surface.name);
        if (surface.name == p.surface) found = surface.track_reaction = true;
      }
    };
    fixedSurfaces(c.tanks);
    fixedSurfaces(c.boxes);
    fixedSurfaces(c.meshes);
    fixedSurfaces(c.circles);
    for (const auto& b : c.bodies) {
      names.push_back(b.name);
      if (b.name == p.surface && !found) found = p.on_body = true;
    }
    if (!found) {
      const std::string guess = closestWord(p.surface, names);
      m.fail("surface", "no tank, box, mesh, sphere, cylinder or body is named '" + p.surface + "'" + (guess.empty() ? "" : " (did you mean '" + guess + "'?)"));
    }
    const double off = p.on_body ? distanceToBodySurface(c, p.surface, p.point) : distanceToSurface(c, p.surface, p.point);
    if (off > c.spacing()) {
      char msg[200];
      std::snprintf(msg, sizeof msg, "the point is %.3g m from the surface '%s': expected on it (within the boundary spacing %g m)",
                    off, p.surface.c_str(), c.spacing());
      m.fail("point", msg);
    }
    m.finish();
    c.probes.push_back(p);
  });
  readVelocityProbes(top, c);
  readPackingProbes(top, c);
}

}  // namespace moorsph::io::detail
