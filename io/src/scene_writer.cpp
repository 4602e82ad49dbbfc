// scene.resolved.yaml: the scene with every default written out, so a run directory
// records exactly what ran (and can be re-run with `moorsph run scene.resolved.yaml`).
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <filesystem>

#include <moorsph/io/scene_loader.hpp>
#include "scene_sections.hpp"

namespace moorsph::io {
namespace {

void vec(YAML::Emitter& e, const char* key, const Triple& t, int dim) {
  e << YAML::Key << key << YAML::Value << YAML::Flow << YAML::BeginSeq;
  for (int k = 0; k < dim; ++k) e << t[k];
  e << YAML::EndSeq;
}

void extent(YAML::Emitter& e, const BoxExtent& b, int dim) {
  vec(e, "lower", b.lower, dim);
  vec(e, "upper", b.upper, dim);
}

}  // namespace

std::string resolvedSceneYaml(const SceneConfig& c) {
  YAML::Emitter e;
  e.SetDoublePrecision(17);  // round-trips every double
  e << YAML::BeginMap;
  e << YAML::Key << "dim" << YAML::Value << c.dim;
  e << YAML::Key << "name" << YAML::Value << c.name;
  e << YAML::Key << "end_time" << YAML::Value << c.end_time;
  e << YAML::Key << "resolution" << YAML::Value << YAML::BeginMap;
  e << YAML::Key << "dx" << YAML::Value << c.dx << YAML::Key << "boundary_spacing" << YAML::Value << c.spacing();
  e << YAML::EndMap;
  e << YAML::Key << "fluid" << YAML::Value << YAML::BeginMap;
  e << YAML::Key << "density" << YAML::Value << c.rho0 << YAML::Key << "viscosity" << YAML::Value << c.mu;
  e << YAML::Key << "sound_speed" << YAML::Value << c.sound_speed;
  vec(e, "gravity", c.gravity, c.dim);
  e << YAML::Key << "hydrostatic_start" << YAML::Value << c.hydrostatic_start;
  e << YAML::EndMap;
  const auto& m = c.method;
  e << YAML::Key << "method" << YAML::Value << YAML::BeginMap;
  e << YAML::Key << "preset" << YAML::Value << "reference";
  e << YAML::Key << "h_factor" << YAML::Value << m.h_factor << YAML::Key << "cfl" << YAML::Value << m.cfl;
  e << YAML::Key << "integrator" << YAML::Value << fluid::optionName(fluid::kIntegratorNames, m.integrator);
  if (m.integrator == fluid::Integrator::PredictorCorrector)
    e << YAML::Key << "predictor_fraction" << YAML::Value << m.predictor_fraction;
  e << YAML::Key << "force_dt_factor" << YAML::Value << m.force_dt_factor << YAML::Key << "gamma" << YAML::Value << m.gamma;
  e << YAML::Key << "xsph_eps" << YAML::Value << m.xsph_eps;
  e << YAML::Key << "xsph_form" << YAML::Value << fluid::optionName(fluid::kXsphFormNames, m.xsph_form);
  e << YAML::Key << "viscosity_xi" << YAML::Value << m.viscosity_xi;
  e << YAML::Key << "viscosity_beta_factor" << YAML::Value << m.viscosity_beta_factor;
  e << YAML::Key << "b_off" << YAML::Value << m.boundary_offset;
  e << YAML::Key << "boundary_strength" << YAML::Value << m.boundary_strength;
  if (m.boundary_h_factor > 0.0) e << YAML::Key << "boundary_h_factor" << YAML::Value << m.boundary_h_factor;
  e << YAML::Key << "boundary_force" << YAML::Value << fluid::optionName(fluid::kBoundaryForceFormNames, m.boundary_force_form);
  e << YAML::Key << "skin_factor" << YAML::Value << m.skin_factor;
  e << YAML::Key << "density_diffusion" << YAML::Value << YAML::BeginMap;
  e << YAML::Key << "form" << YAML::Value << fluid::optionName(fluid::kDensityDiffusionFormNames, m.density_diffusion_form);
  e << YAML::Key << "delta" << YAML::Value << m.density_diffusion_delta << YAML::EndMap;
  e << YAML::Key << "particle_shifting" << YAML::Value << YAML::BeginMap;
  e << YAML::Key << "coefficient" << YAML::Value << m.shifting.coefficient;
  e << YAML::Key << "anti_clustering" << YAML::Value << m.shifting.anti_clustering;
  e << YAML::Key << "cap" << YAML::Value << m.shifting.cap << YAML::EndMap;
  e << YAML::Key << "min_dt_fraction" << YAML::Value << m.min_dt_fraction;
  e << YAML::Key << "max_speed_fraction" << YAML::Value << m.max_speed_fraction;
  e << YAML::Key << "max_leak_depth" << YAML::Value << m.max_leak_depth;
  e << YAML::EndMap;
  e << YAML::Key << "effects" << YAML::Value << YAML::Flow << c.effects;
  if (c.domain_given) {
    e << YAML::Key << "domain" << YAML::Value << YAML::BeginMap;
    extent(e, c.domain, c.dim);
    e << YAML::Key << "periodic" << YAML::Value << YAML::Flow << YAML::BeginSeq;
    for (int k = 0; k < c.dim; ++k) e << c.periodic[k];
    e << YAML::EndSeq << YAML::EndMap;
  }
  e << YAML::Key << "geometry" << YAML::Value << YAML::BeginSeq;
  for (const auto& t : c.tanks) {
    e << YAML::BeginMap << YAML::Key << "tank" << YAML::Value << YAML::BeginMap;
    e << YAML::Key << "name" << YAML::Value << t.name;
    extent(e, t.box, c.dim);
    e << YAML::Key << "lid" << YAML::Value << t.lid;
    if (t.mirror_floor) e << YAML::Key << "floor" << YAML::Value << "mirror";
    if (t.mirror_sides) e << YAML::Key << "sides" << YAML::Value << "mirror";
    e << YAML::EndMap << YAML::EndMap;
  }
  for (const auto& w : c.water) {
    e << YAML::BeginMap << YAML::Key << "water" << YAML::Value << YAML::BeginMap;
    extent(e, w.box, c.dim);
    if (w.packed) {
      e << YAML::Key << "packed" << YAML::Value << true;
      e << YAML::Key << "packing_iterations" << YAML::Value << w.packing_iterations;
    }
    e << YAML::EndMap << YAML::EndMap;
  }
  for (const auto& b : c.boxes) {
    e << YAML::BeginMap << YAML::Key << "box" << YAML::Value << YAML::BeginMap;
    e << YAML::Key << "name" << YAML::Value << b.name;
    extent(e, b.box, c.dim);
    e << YAML::Key << "open_faces" << YAML::Value << YAML::Flow << b.open_faces;
    e << YAML::EndMap << YAML::EndMap;
  }
  for (const auto& g : c.meshes) {
    if (g.shape != "file") {
      e << YAML::BeginMap << YAML::Key << g.shape << YAML::Value << YAML::BeginMap;
      e << YAML::Key << "name" << YAML::Value << g.name;
      vec(e, "centre", g.centre, 3);
      e << YAML::Key << "radius" << YAML::Value << g.radius;
      if (g.shape == "cylinder") {
        e << YAML::Key << "length" << YAML::Value << g.length;
        e << YAML::Key << "axis" << YAML::Value << std::string(1, static_cast<char>('x' + g.axis));
      }
      e << YAML::EndMap << YAML::EndMap;
      continue;
    }
    e << YAML::BeginMap << YAML::Key << "mesh" << YAML::Value << YAML::BeginMap;
    e << YAML::Key << "name" << YAML::Value << g.name;
    e << YAML::Key << "file" << YAML::Value << std::filesystem::absolute(g.path).string();
    e << YAML::Key << "scale" << YAML::Value << g.scale;
    vec(e, "translate", g.translate, 3);
    e << YAML::Key << "normals" << YAML::Value << (g.inward ? "inward" : "outward");
    e << YAML::EndMap << YAML::EndMap;
  }
  for (const auto& k : c.circles) {
    e << YAML::BeginMap << YAML::Key << "cylinder" << YAML::Value << YAML::BeginMap;
    e << YAML::Key << "name" << YAML::Value << k.name;
    vec(e, "centre", Triple{k.x, k.y, 0.0}, 2);
    e << YAML::Key << "radius" << YAML::Value << k.radius << YAML::EndMap << YAML::EndMap;
  }
  e << YAML::EndSeq;
  if (c.piston.present) {
    const auto& p = c.piston;
    e << YAML::Key << "piston" << YAML::Value << YAML::BeginMap;
    e << YAML::Key << "name" << YAML::Value << p.name << YAML::Key << "x" << YAML::Value << p.x;
    e << YAML::Key << "bottom" << YAML::Value << p.bottom << YAML::Key << "top" << YAML::Value << p.top;
    if (c.dim == 3) e << YAML::Key << "z" << YAML::Value << YAML::Flow << YAML::BeginSeq << p.z_lower << p.z_upper << YAML::EndSeq;
    e << YAML::Key << "signal" << YAML::Value << YAML::BeginMap << YAML::Key << "type" << YAML::Value << p.signal;
    if (p.signal == "regular") {
      e << YAML::Key << "wave_height" << YAML::Value << p.wave_height << YAML::Key << "period" << YAML::Value << p.period;
      e << YAML::Key << "depth" << YAML::Value << p.depth << YAML::Key << "ramp_up" << YAML::Value << p.ramp_up;
    } else if (p.signal == "breather") {
      e << YAML::Key << "order" << YAML::Value << p.order << YAML::Key << "a0" << YAML::Value << p.a0;
      e << YAML::Key << "k0" << YAML::Value << p.k0 << YAML::Key << "focus_distance" << YAML::Value << p.focus_distance;
      e << YAML::Key << "focus_time" << YAML::Value << p.focus_time << YAML::Key << "depth" << YAML::Value << p.depth;
      e << YAML::Key << "still" << YAML::Value << p.still << YAML::Key << "ramp_up" << YAML::Value << p.ramp_up;
      e << YAML::Key << "ramp_down" << YAML::Value << p.ramp_down << YAML::Key << "duration" << YAML::Value << p.duration;
      e << YAML::Key << "finite_depth_correction" << YAML::Value << p.finite_depth_correction;
    } else {
      e << YAML::Key << "file" << YAML::Value << std::filesystem::absolute(p.table).string();
    }
    e << YAML::EndMap << YAML::EndMap;
  }
  if (!c.damping_zones.empty()) {
    e << YAML::Key << "damping_zones" << YAML::Value << YAML::BeginSeq;
    for (const auto& z : c.damping_zones)
      e << YAML::Flow << YAML::BeginMap << YAML::Key << "x_start" << YAML::Value << z.x_start << YAML::Key << "x_end"
        << YAML::Value << z.x_end << YAML::Key << "k_max" << YAML::Value << z.k_max << YAML::EndMap;
    e << YAML::EndSeq;
  }
  if (c.forcing.present) {
    const auto& f = c.forcing;
    e << YAML::Key << "forcing_region" << YAML::Value << YAML::BeginMap;
    e << YAML::Key << "x_start" << YAML::Value << f.x_start << YAML::Key << "length" << YAML::Value << f.length;
    e << YAML::Key << "floor" << YAML::Value << f.floor << YAML::Key << "bottom_gap" << YAML::Value << f.bottom_gap;
    e << YAML::Key << "still_level" << YAML::Value << f.still_level << YAML::Key << "kappa" << YAML::Value << f.kappa;
    e << YAML::Key << "ramp_up" << YAML::Value << f.ramp_up << YAML::Key << "gain" << YAML::Value << f.gain;
    if (std::isfinite(f.end_time)) e << YAML::Key << "end_time" << YAML::Value << f.end_time;
    e << YAML::Key << "wave" << YAML::Value << YAML::Flow << YAML::BeginMap << YAML::Key << "theory" << YAML::Value
      << f.theory << YAML::Key << "amplitude" << YAML::Value << f.amplitude << YAML::Key << "period" << YAML::Value
      << f.period << YAML::EndMap;
    e << YAML::EndMap;
  }
  if (!c.gauges.empty()) {
    e << YAML::Key << "gauges" << YAML::Value << YAML::BeginSeq;
    for (const auto& g : c.gauges) {
      e << YAML::Flow << YAML::BeginMap << YAML::Key << "name" << YAML::Value << g.name;
      e << YAML::Key << "x" << YAML::Value << g.x;
      if (c.dim == 3) e << YAML::Key << "z" << YAML::Value << g.z;
      e << YAML::Key << "bottom" << YAML::Value << g.bottom << YAML::Key << "top" << YAML::Value << g.top;
      e << YAML::Key << "threshold" << YAML::Value << g.threshold;
      e << YAML::Key << "volume_edge" << YAML::Value << g.volume_edge << YAML::EndMap;
    }
    e << YAML::EndSeq;
  }
  if (!c.probes.empty()) {
    e << YAML::Key << "pressure_probes" << YAML::Value << YAML::BeginSeq;
    for (const auto& p : c.probes) {
      e << YAML::BeginMap << YAML::Key << "name" << YAML::Value << p.name;
      e << YAML::Key << "surface" << YAML::Value << p.surface;
      vec(e, "point", p.point, c.dim);
      vec(e, "normal", p.normal, c.dim);
      e << YAML::Key << "radius" << YAML::Value << p.radius;
      e << YAML::Key << "interpolation_offset" << YAML::Value << p.interpolation_offset;
      e << YAML::Key << "moving_mean" << YAML::Value << p.moving_mean << YAML::EndMap;
    }
    e << YAML::EndSeq;
  }
  if (!c.velocity_probes.empty()) {
    e << YAML::Key << "velocity_probes" << YAML::Value << YAML::BeginSeq;
    for (const auto& p : c.velocity_probes) {
      e << YAML::BeginMap << YAML::Key << "name" << YAML::Value << p.name;
      vec(e, "point", p.point, c.dim);
      e << YAML::Key << "min_fill" << YAML::Value << p.min_fill << YAML::EndMap;
    }
    e << YAML::EndSeq;
  }
  if (!c.packing_probes.empty()) {
    e << YAML::Key << "packing_probes" << YAML::Value << YAML::BeginSeq;
    for (const auto& p : c.packing_probes) {
      e << YAML::BeginMap << YAML::Key << "name" << YAML::Value << p.name;
      vec(e, "lower", p.lower, c.dim);
      vec(e, "upper", p.upper, c.dim);
      e << YAML::Key << "spacing" << YAML::Value << p.spacing;
      e << YAML::Key << "min_fill" << YAML::Value << p.min_fill;
      e << YAML::Key << "warn_rise" << YAML::Value << p.warn_rise << YAML::EndMap;
    }
    e << YAML::EndSeq;
  }
  detail::writeBodySections(e, c);
  e << YAML::Key << "output" << YAML::Value << YAML::BeginMap;
  e << YAML::Key << "interval" << YAML::Value << c.output.interval;
  e << YAML::Key << "particles_interval" << YAML::Value << c.output.particles_interval;
  e << YAML::Key << "checkpoint_minutes" << YAML::Value << c.output.checkpoint_minutes;
  e << YAML::EndMap;
  e << YAML::EndMap;
  return std::string("# Resolved scene: every default written out (moorsph, docs/scene-reference.md)\n") + e.c_str() + "\n";
}

}  // namespace moorsph::io
