// The `moorings` section of a scene file (docs/scene-reference.md): known model words,
// each model's required parameters (bodies/include/moorsph/bodies/mooring_factory.hpp),
// line ends on known bodies and apart from each other.
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <moorsph/io/body_geometry.hpp>
#include "scene_sections.hpp"

namespace moorsph::io::detail {
namespace {

const double kNaN = std::numeric_limits<double>::quiet_NaN();

const std::vector<std::string>& modelWords() {
  static const std::vector<std::string> words{"tension_only_spring", "cable_path", "elastic_catenary", "lumped_mass"};
  return words;
}

/// An optional number that must be > 0 (>= 0 with allow_zero) when given; NaN when absent.
double optionalPositive(MapReader& m, const std::string& key, const std::string& what, bool allow_zero = false) {
  if (!m.has(key)) {
    m.child(key);
    return kNaN;
  }
  return m.positive(key, 0.0, what, allow_zero);
}

LineEndConfig readEnd(MapReader& line, const std::string& key, const SceneConfig& c, bool body_required) {
  if (!line.has(key))
    line.fail(key, std::string("required key is missing (expected {") + (body_required ? "body: NAME, " : "") +
                       "point: [...]})");
  MapReader m(line.child(key), line.childPath(key), line.source());
  LineEndConfig end;
  end.body = body_required ? m.requiredText("body") : m.text("body", "");
  if (!end.body.empty() && c.bodyIndex(end.body) < 0) {
    std::vector<std::string> names;
    for (const auto& b : c.bodies) names.push_back(b.name);
    const std::string guess = closestWord(end.body, names);
    m.fail("body", "no body is named '" + end.body + "'" + (guess.empty() ? "" : " (did you mean '" + guess + "'?)"));
  }
  end.point = toTriple(m.vector("point", c.dim));
  m.finish();
  return end;
}

/// Ground position of a line end in the scene's initial pose.
Eigen::Vector3d groundPoint(const LineEndConfig& e, const SceneConfig& c) {
  const Eigen::Vector3d p(e.point[0], e.point[1], e.point[2]);
  if (e.body.empty()) return p;
  const BodyConfig& b = c.bodies[c.bodyIndex(e.body)];
  const Triple s = b.start();
  return Eigen::Vector3d(s[0], s[1], s[2]) + bodyRotation(b) * p;
}

void readLineParameters(MapReader& m, MooringConfig& l) {
  l.stiffness = optionalPositive(m, "stiffness", "spring stiffness k [N/m]");
  l.rest_length = optionalPositive(m, "rest_length", "unstretched length L0 [m]");
  l.pretension = optionalPositive(m, "pretension", "tension at the rest pose [N]", true);
  l.damping = m.positive("damping", 0.0, "dashpot coefficient [N s/m]", true);
  l.dissipation = m.positive("dissipation", 0.0, "cable_path dissipation coefficient [s/m]", true);
  l.length = optionalPositive(m, "length", "unstretched line length [m]");
  l.axial_stiffness = optionalPositive(m, "axial_stiffness", "EA [N]");
  l.mass_per_length = optionalPositive(m, "mass_per_length", "mass per unit length in air [kg/m]");
  l.bending_stiffness = m.positive("bending_stiffness", 0.0, "EI [N m^2]", true);
  l.diameter = m.positive("diameter", 0.0, "volumetric diameter [m]", true);
  l.seabed_friction = m.positive("seabed_friction", 0.0, "seabed friction coefficient [-]", true);
  l.anchor_on_seabed = m.boolean("anchor_on_seabed", true);
  l.segments = m.integer("segments", l.segments);
  if (l.segments < 1) m.fail("segments", "expected at least 1 segment");
  l.internal_damping_ratio = m.positive("internal_damping_ratio", 1.0, "axial damping ratio [-]", true);
  l.cd_normal = m.positive("cd_normal", l.cd_normal, "normal drag coefficient [-]", true);
  l.cd_axial = m.positive("cd_axial", l.cd_axial, "axial drag coefficient [-]", true);
  l.ca_normal = m.positive("ca_normal", l.ca_normal, "normal added-mass coefficient [-]", true);
  l.ca_axial = m.positive("ca_axial", l.ca_axial, "axial added-mass coefficient [-]", true);
  l.time_step = m.positive("time_step", 0.0, "lumped_mass internal step [s], 0 for automatic", true);
  l.relaxation_time = m.positive("relaxation_time", 0.0, "lumped_mass static relaxation before the run [s]", true);
  if (m.has("breaking_load")) l.breaking_load = m.positive("breaking_load", 0.0, "tension at which the line breaks [N]");
  else m.child("breaking_load");
}

/// Each model's required parameters (mooring_factory.hpp): a spring needs k and a
/// rest length (or a pretension), or the line description EA and L they derive from.
void checkModelParameters(MapReader& m, const MooringConfig& l) {
  const bool line = !std::isnan(l.length) && !std::isnan(l.axial_stiffness);
  if (l.model == "tension_only_spring" || l.model == "cable_path") {
    if (std::isnan(l.stiffness) && !line)
      m.fail("stiffness", "required key is missing for model " + l.model + " (expected k [N/m], or length and axial_stiffness)");
    if (!std::isnan(l.rest_length) && !std::isnan(l.pretension))
      m.fail("pretension", "give rest_length or pretension, not both (the pretension sets the rest length)");
    if (std::isnan(l.rest_length) && std::isnan(l.pretension) && std::isnan(l.length))
      m.fail("rest_length", "required key is missing for model " + l.model + " (expected rest_length [m] or pretension [N])");
  } else {
    for (const char* key : {"length", "axial_stiffness", "mass_per_length"}) {
      const double v = std::string(key) == "length" ? l.length : std::string(key) == "axial_stiffness" ? l.axial_stiffness : l.mass_per_length;
      if (std::isnan(v))
        m.fail(key, "required key is missing for model " + l.model + " (" +
                        (std::string(key) == "length" ? "unstretched length [m]" : std::string(key) == "axial_stiffness" ? "EA [N]" : "mass per length in air [kg/m]") +
                        ")");
    }
  }
}

}  // namespace

MooringConfig readMooring(MapReader& m, const SceneConfig& c, std::size_t index) {
  MooringConfig l;
  l.name = m.text("name", "line" + std::to_string(index));
  for (const auto& other : c.moorings)
    if (other.name == l.name) m.fail("name", "another line is already named '" + l.name + "'");
  l.model = m.requiredText("model");
  if (std::find(modelWords().begin(), modelWords().end(), l.model) == modelWords().end()) {
    const std::string guess = closestWord(l.model, modelWords());
    m.fail("model", "unknown mooring model '" + l.model + "'" + (guess.empty() ? "" : " (did you mean '" + guess + "'?)") +
                        "; known: tension_only_spring, cable_path, elastic_catenary, lumped_mass");
  }
  l.fairlead = readEnd(m, "fairlead", c, true);
  l.anchor = readEnd(m, "anchor", c, false);
  if (l.anchor.body == l.fairlead.body) m.fail("anchor", "the anchor is on the fairlead's own body: the line would do nothing");
  const double span = (groundPoint(l.fairlead, c) - groundPoint(l.anchor, c)).norm();
  if (span < 1e-6) m.fail("anchor", "the anchor coincides with the fairlead (the line has no direction)");
  const YAML::Node via = m.child("via_points");
  if (via.IsDefined() && !via.IsNull()) {
    if (!via.IsSequence()) m.fail("via_points", "expected a list of {body: NAME (optional), point: [...]} [m]");
    for (std::size_t k = 0; k < via.size(); ++k) {
      MapReader p(via[k], m.childPath("via_points") + "." + std::to_string(k), m.source());
      LineEndConfig e;
      e.body = p.text("body", "");
      if (!e.body.empty() && c.bodyIndex(e.body) < 0) p.fail("body", "no body is named '" + e.body + "'");
      e.point = toTriple(p.vector("point", c.dim));
      p.finish();
      l.via_points.push_back(e);
    }
  }
  readLineParameters(m, l);
  checkModelParameters(m, l);
  if (!std::isnan(l.stiffness) && !std::isnan(l.pretension) && l.model == "tension_only_spring") {
    // rest length = span - T/k must stay positive.
    if (l.pretension / l.stiffness >= span) {
      char msg[200];
      std::snprintf(msg, sizeof msg, "a pretension of %g N stretches the %g m line by %g m: the rest length would be <= 0",
                    l.pretension, span, l.pretension / l.stiffness);
      m.fail("pretension", msg);
    }
  }
  l.where.text = m.source().locate(m.node(), m.path());
  m.finish();
  return l;
}

}  // namespace moorsph::io::detail
