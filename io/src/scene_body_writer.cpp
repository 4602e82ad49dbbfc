// scene.resolved.yaml: the bodies, moorings and coupling sections with every value
// written out (angles back in degrees, as the scene file gives them).
#include <cmath>
#include <filesystem>
#include "scene_sections.hpp"

namespace moorsph::io::detail {
namespace {

void vec(YAML::Emitter& e, const char* key, const Triple& t, int dim) {
  e << YAML::Key << key << YAML::Value << YAML::Flow << YAML::BeginSeq;
  for (int k = 0; k < dim; ++k) e << t[k];
  e << YAML::EndSeq;
}

void number(YAML::Emitter& e, const char* key, double v) {
  if (!std::isnan(v)) e << YAML::Key << key << YAML::Value << v;
}

void end(YAML::Emitter& e, const char* key, const LineEndConfig& p, int dim) {
  e << YAML::Key << key << YAML::Value << YAML::Flow << YAML::BeginMap;
  if (!p.body.empty()) e << YAML::Key << "body" << YAML::Value << p.body;
  vec(e, "point", p.point, dim);
  e << YAML::EndMap;
}

void shape(YAML::Emitter& e, const BodyShapeConfig& s, int dim) {
  e << YAML::Key << "shape" << YAML::Value << YAML::BeginMap << YAML::Key << s.kind << YAML::Value << YAML::BeginMap;
  if (s.kind == "mesh") {
    e << YAML::Key << "file" << YAML::Value << std::filesystem::absolute(s.path).string();
    e << YAML::Key << "scale" << YAML::Value << s.scale;
    vec(e, "translate", s.translate, 3);
  } else {
    vec(e, "centre", s.centre, dim);
    if (s.kind == "box") vec(e, "size", s.size, dim);
    else e << YAML::Key << "radius" << YAML::Value << s.radius;
    if (s.kind == "sphere" && dim == 3) e << YAML::Key << "sampling" << YAML::Value << s.sampling;
    if (s.kind == "cylinder" && dim == 3)
      e << YAML::Key << "length" << YAML::Value << s.length << YAML::Key << "axis" << YAML::Value
        << std::string(1, static_cast<char>('x' + s.axis));
  }
  e << YAML::EndMap << YAML::EndMap;
}

void body(YAML::Emitter& e, const BodyConfig& b, int dim) {
  const double deg = 180.0 / 3.14159265358979323846;
  e << YAML::BeginMap << YAML::Key << "name" << YAML::Value << b.name << YAML::Key << "mass" << YAML::Value << b.mass;
  vec(e, "centre_of_mass", b.centre_of_mass, dim);
  if (dim == 2) {
    e << YAML::Key << "inertia" << YAML::Value << b.inertia[2][2];
  } else {
    e << YAML::Key << "inertia" << YAML::Value << YAML::Flow << YAML::BeginSeq << b.inertia[0][0] << b.inertia[1][1]
      << b.inertia[2][2] << b.inertia[0][1] << b.inertia[0][2] << b.inertia[1][2] << YAML::EndSeq;
  }
  static const char* const dofs[] = {"x", "y", "z", "rx", "ry", "rz"};
  e << YAML::Key << "fixed" << YAML::Value << YAML::Flow << YAML::BeginSeq;
  for (int k = 0; k < 6; ++k)
    if (b.fixed[k]) e << dofs[k];
  e << YAML::EndSeq;
  vec(e, "position", b.position, dim);
  if (dim == 2) e << YAML::Key << "orientation_deg" << YAML::Value << b.orientation[1] * deg;
  else vec(e, "orientation_deg", Triple{b.orientation[0] * deg, b.orientation[1] * deg, b.orientation[2] * deg}, 3);
  vec(e, "offset", b.offset, dim);
  vec(e, "velocity", b.velocity, dim);
  shape(e, b.shape, dim);
  if (!b.points.empty()) {
    e << YAML::Key << "points" << YAML::Value << YAML::BeginMap;
    for (const auto& [name, p] : b.points) vec(e, name.c_str(), p, dim);
    e << YAML::EndMap;
  }
  if (b.green_water) {
    e << YAML::Key << "green_water" << YAML::Value << YAML::Flow << YAML::BeginMap;
    e << YAML::Key << "deck_height" << YAML::Value << b.deck_height;
    if (dim == 3) e << YAML::Key << "outline_file" << YAML::Value << std::filesystem::absolute(b.deck_outline_file).string();
    else vec(e, "x_range", Triple{b.deck_outline[0][0], b.deck_outline[1][0], 0.0}, 2);
    e << YAML::EndMap;
  }
  e << YAML::EndMap;
}

void line(YAML::Emitter& e, const MooringConfig& l, int dim) {
  e << YAML::BeginMap << YAML::Key << "name" << YAML::Value << l.name << YAML::Key << "model" << YAML::Value << l.model;
  end(e, "fairlead", l.fairlead, dim);
  end(e, "anchor", l.anchor, dim);
  if (!l.via_points.empty()) {
    e << YAML::Key << "via_points" << YAML::Value << YAML::BeginSeq;
    for (const auto& p : l.via_points) {
      e << YAML::Flow << YAML::BeginMap;
      if (!p.body.empty()) e << YAML::Key << "body" << YAML::Value << p.body;
      vec(e, "point", p.point, dim);
      e << YAML::EndMap;
    }
    e << YAML::EndSeq;
  }
  number(e, "stiffness", l.stiffness);
  number(e, "rest_length", l.rest_length);
  number(e, "pretension", l.pretension);
  number(e, "damping", l.damping);
  number(e, "dissipation", l.dissipation);
  number(e, "length", l.length);
  number(e, "axial_stiffness", l.axial_stiffness);
  number(e, "mass_per_length", l.mass_per_length);
  number(e, "bending_stiffness", l.bending_stiffness);
  number(e, "diameter", l.diameter);
  number(e, "seabed_friction", l.seabed_friction);
  e << YAML::Key << "anchor_on_seabed" << YAML::Value << l.anchor_on_seabed;
  e << YAML::Key << "segments" << YAML::Value << l.segments;
  number(e, "internal_damping_ratio", l.internal_damping_ratio);
  number(e, "cd_normal", l.cd_normal);
  number(e, "cd_axial", l.cd_axial);
  number(e, "ca_normal", l.ca_normal);
  number(e, "ca_axial", l.ca_axial);
  number(e, "time_step", l.time_step);
  number(e, "relaxation_time", l.relaxation_time);
  if (std::isfinite(l.breaking_load)) number(e, "breaking_load", l.breaking_load);
  e << YAML::EndMap;
}

}  // namespace

void writeBodySections(YAML::Emitter& e, const SceneConfig& c) {
  if (c.bodies.empty()) return;
  e << YAML::Key << "bodies" << YAML::Value << YAML::BeginSeq;
  for (const auto& b : c.bodies) body(e, b, c.dim);
  e << YAML::EndSeq;
  if (!c.moorings.empty()) {
    e << YAML::Key << "moorings" << YAML::Value << YAML::BeginSeq;
    for (const auto& l : c.moorings) line(e, l, c.dim);
    e << YAML::EndSeq;
  }
  e << YAML::Key << "coupling" << YAML::Value << YAML::BeginMap;
  e << YAML::Key << "release_time" << YAML::Value << c.coupling.release_time;
  e << YAML::Key << "ramp_time" << YAML::Value << c.coupling.ramp_time;
  e << YAML::Key << "max_body_step" << YAML::Value << c.coupling.max_step;
  e << YAML::EndMap;
}

}  // namespace moorsph::io::detail
