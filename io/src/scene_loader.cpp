#include <moorsph/io/scene_loader.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include "scene_sections.hpp"

namespace moorsph::io {
namespace {

using detail::MapReader;
using detail::YamlSource;

const std::vector<std::string> kUnsupportedEffects{};

/// Apply one "key.path=value" to the tree. Sequence entries are addressed by index
/// ("geometry[1]" or "geometry.1"); missing map keys are created.
void applyAssignment(YAML::Node& root, const std::string& assignment, YamlSource& source) {
  const auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0)
    throw SceneError("--set " + assignment, "", "expected key.path=value, e.g. resolution.dx=0.01");
  const std::string path = detail::dottedPath(assignment.substr(0, eq));
  YAML::Node value;
  try {
    value = YAML::Load(assignment.substr(eq + 1));
  } catch (const YAML::Exception& e) {
    throw SceneError("--set " + path, path, std::string("value is not valid YAML: ") + e.msg);
  }
  std::vector<std::string> parts;
  std::stringstream ss(path);
  for (std::string p; std::getline(ss, p, '.');) parts.push_back(p);
  // yaml-cpp nodes are handles: walking with a copy and assigning to it edits the tree.
  std::vector<YAML::Node> chain{root};
  for (std::size_t k = 0; k < parts.size(); ++k) {
    YAML::Node parent = chain.back();
    const bool last = k + 1 == parts.size();
    if (parent.IsSequence()) {
      std::size_t index = 0;
      try {
        index = std::stoul(parts[k]);
      } catch (...) {
        throw SceneError("--set " + path, path, "'" + parts[k] + "' must be an index into a list");
      }
      if (index >= parent.size()) throw SceneError("--set " + path, path, "index " + parts[k] + " is past the end of the list");
      if (last) parent[index] = value;
      else chain.push_back(parent[index]);
    } else {
      if (last) parent[parts[k]] = value;
      else {
        if (!parent[parts[k]].IsDefined()) parent[parts[k]] = YAML::Node(YAML::NodeType::Map);
        chain.push_back(parent[parts[k]]);
      }
    }
  }
  source.overridden.insert(path);
}

void readFluid(MapReader& top, SceneConfig& c) {
  if (!top.has("fluid")) {
    top.child("fluid");
    return;
  }
  MapReader f(top.child("fluid"), "fluid", top.source());
  c.rho0 = f.positive("density", c.rho0, "reference density rho0 [kg/m^3]");
  c.mu = f.positive("viscosity", c.mu, "dynamic viscosity [Pa s]", true);
  c.sound_speed = f.positive("sound_speed", 0.0, "speed of sound c_s [m/s]; leave out for 10 sqrt(2 g H)", true);
  const std::vector<double> down = c.dim == 2 ? std::vector<double>{0.0, -9.81} : std::vector<double>{0.0, -9.81, 0.0};
  c.gravity = detail::toTriple(f.vector("gravity", c.dim, down));
  c.hydrostatic_start = f.boolean("hydrostatic_start", c.hydrostatic_start);
  f.finish();
}

void readOutput(MapReader& top, SceneConfig& c) {
  if (!top.has("output")) {
    top.child("output");
    return;
  }
  MapReader o(top.child("output"), "output", top.source());
  c.output.interval = o.positive("interval", c.output.interval, "time between time-series rows [s]");
  c.output.particles_interval =
      o.positive("particles_interval", c.output.particles_interval, "time between particle snapshots [s], 0 for none", true);
  c.output.checkpoint_minutes = o.positive("checkpoint_minutes", c.output.checkpoint_minutes,
                                           "wall time between checkpoints [min], 0 for the end only", true);
  o.finish();
}

void readEffects(MapReader& top, SceneConfig& c) {
  const YAML::Node node = top.child("effects");
  if (!node.IsDefined() || node.IsNull()) return;
  c.effects = top.textList("effects", c.effects);
  for (std::size_t k = 0; k < c.effects.size(); ++k) {
    const std::string& e = c.effects[k];
    const std::string path = "effects[" + std::to_string(k) + "]";
    if (std::find(kUnsupportedEffects.begin(), kUnsupportedEffects.end(), e) != kUnsupportedEffects.end())
      top.source().fail(node[k], path, "effect '" + e + "' is not supported yet");
    if (std::find(knownEffects().begin(), knownEffects().end(), e) == knownEffects().end()) {
      const std::string guess = closestWord(e, knownEffects());
      std::string list;
      for (const auto& k2 : knownEffects()) list += (list.empty() ? "" : ", ") + k2;
      top.source().fail(node[k], path,
                        "unknown effect '" + e + "'" + (guess.empty() ? "" : " (did you mean '" + guess + "'?)") +
                            "; known: " + list);
    }
    if (std::count(c.effects.begin(), c.effects.end(), e) > 1) top.source().fail(node[k], path, "effect '" + e + "' is listed twice");
  }
  if (std::find(c.effects.begin(), c.effects.end(), "pressure") == c.effects.end())
    top.source().fail(node, "effects", "the list must contain 'pressure' (pressure force and continuity)");
  if (c.hasEffect("outflow") && !c.hasEffect("walls"))
    top.source().fail(node, "effects", "'outflow' removes spray that left over the walls: 'walls' must be listed too");
}

void readDomain(MapReader& top, SceneConfig& c) {
  if (!top.has("domain")) {
    top.child("domain");
    return;
  }
  MapReader d(top.child("domain"), "domain", top.source());
  c.domain_given = true;
  c.domain.lower = detail::toTriple(d.vector("lower", c.dim));
  c.domain.upper = detail::toTriple(d.vector("upper", c.dim));
  for (int k = 0; k < c.dim; ++k)
    if (!(c.domain.upper[k] > c.domain.lower[k])) d.fail("upper", "expected upper > lower along every axis [m]");
  const YAML::Node p = d.child("periodic");
  if (p.IsDefined() && !p.IsNull()) {
    if (!p.IsSequence() || p.size() != static_cast<std::size_t>(c.dim))
      d.fail("periodic", "expected a list of " + std::to_string(c.dim) + " true/false, one per axis");
    for (int k = 0; k < c.dim; ++k)
      if (!YAML::convert<bool>::decode(p[k], c.periodic[k]))
        top.source().fail(p[k], "domain.periodic[" + std::to_string(k) + "]", "expected true or false");
  }
  d.finish();
}

/// 'walls' listed where nothing has wall particles (a tank closed by mirror images
/// alone, no box, mesh, piston or body) would stop the run at its start.
void checkWallParticles(MapReader& top, const SceneConfig& c) {
  const bool tank_particles = std::any_of(c.tanks.begin(), c.tanks.end(), [&](const TankConfig& t) { return c.hasWallParticles(t); });
  const bool surfaces = tank_particles || !c.boxes.empty() || !c.meshes.empty() || !c.circles.empty() ||
                        !c.bodies.empty() || c.hasEffect("piston");
  if (c.hasEffect("walls") && !surfaces && !c.tanks.empty())
    top.fail("effects", "'walls' is listed but the tank is all mirror images and periodic seams (floor: mirror, "
                        "sides: mirror or spanning a periodic axis, no lid) and nothing else has wall particles: leave 'walls' out");
}

/// A tank key that makes mirror images (`key: mirror`) and its effect go together, for
/// one tank.
void checkMirror(MapReader& top, const SceneConfig& c, bool TankConfig::*mirrored_face, const std::string& key,
                 const std::string& effect) {
  const auto mirrored = std::count_if(c.tanks.begin(), c.tanks.end(), [&](const TankConfig& t) { return t.*mirrored_face; });
  const std::string tank_key = "'" + key + ": mirror'";
  if (mirrored > 1) top.fail("geometry", "only one tank may have " + tank_key);
  if (mirrored == 1 && !c.hasEffect(effect))
    top.fail("effects", "a tank has " + tank_key + " but '" + effect + "' is not in the effects");
  if (mirrored == 0 && c.hasEffect(effect))
    top.fail("effects", "'" + effect + "' is listed but no tank has " + tank_key);
}


SceneConfig readScene(const YAML::Node& root, const YamlSource& source) {
  SceneConfig c;
  c.file = source.file;
  if (!root.IsDefined() || root.IsNull()) throw SceneError(source.file, "", "the scene file is empty");
  MapReader top(root, "", source);
  top.rejectUnsupported({"cables"}, "mooring lines and cables are listed under 'moorings'");
  c.dim = top.integer("dim", 0);
  if (c.dim != 2 && c.dim != 3) {
    if (!top.has("dim")) top.fail("dim", "required key is missing (expected 2 or 3)");
    top.fail("dim", "expected 2 or 3, got " + detail::describeNode(root["dim"]));
  }
  c.name = top.text("name", "scene");
  c.end_time = top.requiredNumber("end_time");
  if (!(c.end_time > 0.0)) top.fail("end_time", "expected a simulated end time > 0 [s]");

  {
    if (!top.has("resolution")) top.fail("resolution", "required key is missing (expected a map with dx [m])");
    MapReader r(top.child("resolution"), "resolution", source);
    c.dx = r.requiredNumber("dx");
    if (!(c.dx > 0.0)) r.fail("dx", "expected a particle spacing > 0 [m], got " + detail::describeNode(r.node()["dx"]));
    c.boundary_spacing = r.positive("boundary_spacing", c.dx, "boundary particle spacing [m]");
    if (c.boundary_spacing > c.dx * (1.0 + 1e-9))
    {
      char msg[160];
      std::snprintf(msg, sizeof msg, "must not be coarser than the fluid spacing dx = %g m (fluid would leak through the walls)", c.dx);
      r.fail("boundary_spacing", msg);
    }
    r.finish();
  }
  readFluid(top, c);
  detail::readMethod(top, c);
  readEffects(top, c);
  readDomain(top, c);
  detail::readGeometry(top, c);
  // c_s must be at least 10x the largest expected flow speed (Mach <= 0.1, density
  // variations <= 1%): the water's free-fall speed over its own height.
  const double expected = c.expectedSpeed();
  if (c.sound_speed == 0.0) {
    c.sound_speed = 10.0 * expected;
  } else if (c.sound_speed < 10.0 * expected * (1.0 - 1e-9)) {
    char msg[200];
    std::snprintf(msg, sizeof msg,
                  "c_s = %g m/s is below 10 x sqrt(2 g H) = %g m/s for the water height H = %g m (density "
                  "errors would exceed 1%%); use at least %g",
                  c.sound_speed, 10.0 * expected, c.waterHeight(), std::ceil(10.0 * expected * 10.0) / 10.0);
    MapReader f(root["fluid"], "fluid", source);
    f.fail("sound_speed", msg);
  }
  detail::readWaveMakers(top, c);
  detail::readBodies(top, c);
  detail::readSensors(top, c);  // after the bodies: a probe may sit on one
  // The "bodies" effect runs exactly when the scene has bodies: added to the default
  // effect list, required in (and only in) an explicit one.
  if (!c.bodies.empty() && !c.hasEffect("bodies")) {
    if (root["effects"].IsDefined() && !root["effects"].IsNull())
      top.fail("effects", "the scene has bodies but 'bodies' is not in its effects");
    c.effects.push_back("bodies");
  }
  if (c.bodies.empty() && c.hasEffect("bodies"))
    top.fail("effects", "'bodies' is listed but the scene has no 'bodies' list");
  checkMirror(top, c, &TankConfig::mirror_floor, "floor", "mirror_floor");
  checkMirror(top, c, &TankConfig::mirror_sides, "sides", "mirror_walls");
  checkWallParticles(top, c);
  readOutput(top, c);
  top.finish();

  return c;
}

}  // namespace

const std::vector<std::string>& knownEffects() {
  static const std::vector<std::string> known{"pressure", "viscosity", "xsph",         "density_diffusion", "gravity",
                                              "walls",    "piston",    "damping_zone", "forcing_region", "bodies",
                                              "particle_shifting", "mirror_floor", "mirror_walls", "outflow"};
  return known;
}

double SceneConfig::waterHeight() const {
  double lo = 0.0, hi = 0.0;
  bool any = false;
  for (const auto& w : water) {
    lo = any ? std::min(lo, w.box.lower[1]) : w.box.lower[1];
    hi = any ? std::max(hi, w.box.upper[1]) : w.box.upper[1];
    any = true;
  }
  return any ? hi - lo : 0.0;
}

double SceneConfig::cflDt() const {
  const double h = method.h_factor * dx;
  return method.cfl * h / (sound_speed + 2.0 * method.viscosity_xi * mu / (h * rho0));
}

int SceneConfig::bodyIndex(const std::string& body) const {
  for (std::size_t k = 0; k < bodies.size(); ++k)
    if (bodies[k].name == body) return static_cast<int>(k);
  return -1;
}

bool SceneConfig::hasEffect(const std::string& e) const { return std::find(effects.begin(), effects.end(), e) != effects.end(); }

bool SceneConfig::spansPeriod(const BoxExtent& box, int axis) const {
  const double period = domain.upper[axis] - domain.lower[axis];
  return periodic[axis] && box.upper[axis] - box.lower[axis] >= period - 1e-9 * period;
}

bool SceneConfig::hasWallParticles(const TankConfig& t) const {
  if (t.lid || !t.mirror_floor) return true;
  for (int a = 0; a < dim; ++a)
    if (a != 1 && !t.mirror_sides && !spansPeriod(t.box, a)) return true;
  return false;
}

double SceneConfig::gravityMagnitude() const {
  return std::sqrt(gravity[0] * gravity[0] + gravity[1] * gravity[1] + gravity[2] * gravity[2]);
}

double SceneConfig::expectedSpeed() const { return std::sqrt(2.0 * gravityMagnitude() * waterHeight()); }

SceneConfig loadSceneText(const std::string& text, const std::string& name, const std::vector<std::string>& assignments) {
  YamlSource source;
  source.file = name;
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::ParserException& e) {
    throw SceneError(name + ":" + std::to_string(e.mark.line + 1) + ":" + std::to_string(e.mark.column + 1), "",
                     "not valid YAML: " + e.msg);
  }
  if (!root.IsDefined() || root.IsNull()) root = YAML::Node(YAML::NodeType::Map);
  for (const auto& a : assignments) applyAssignment(root, a, source);
  return readScene(root, source);
}

SceneConfig loadSceneFile(const std::string& path, const std::vector<std::string>& assignments) {
  std::ifstream in(path);
  if (!in) throw SceneError(path, "", "cannot open the scene file");
  std::stringstream text;
  text << in.rdbuf();
  return loadSceneText(text.str(), path, assignments);
}

}  // namespace moorsph::io
