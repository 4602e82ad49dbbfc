// The method section of a scene file: the reference preset with options on top.
#include <cstdio>
#include "scene_sections.hpp"

namespace moorsph::io::detail {

namespace {

// method.particle_shifting: the parameters of the particle_shifting effect.
void readShifting(MapReader& m, MapReader& top, fluid::MethodParameters& p) {
  if (!m.has("particle_shifting")) {
    m.child("particle_shifting");
    return;
  }
  MapReader s(m.child("particle_shifting"), "method.particle_shifting", top.source());
  fluid::ShiftingParameters& q = p.shifting;
  q.coefficient = s.positive("coefficient", q.coefficient, "shift coefficient A (shift velocity = -A h |v| grad C)");
  q.anti_clustering = s.positive("anti_clustering", q.anti_clustering, "anti-clustering factor R", true);
  q.cap = s.positive("cap", q.cap, "largest shift as a fraction of |v|");
  if (q.cap > 1.0) s.fail("cap", "expected a fraction of the particle speed in (0, 1] (default 0.5)");
  s.finish();
}

}  // namespace

void readMethod(MapReader& top, SceneConfig& c) {
  if (!top.has("method")) {
    top.child("method");
    return;
  }
  MapReader m(top.child("method"), "method", top.source());
  const std::string preset = m.text("preset", "reference");
  if (preset != "reference") m.fail("preset", "unknown preset '" + preset + "' (known: reference)");
  fluid::MethodParameters& p = c.method;
  p = fluid::MethodParameters::reference();
  p.h_factor = m.positive("h_factor", p.h_factor, "smoothing length h / dx");
  if (p.h_factor < 1.0 || p.h_factor > 3.0) m.fail("h_factor", "expected h / dx in [1, 3] (reference 1.2)");
  p.cfl = m.positive("cfl", p.cfl, "CFL number");
  if (p.cfl > 1.0) m.fail("cfl", "expected a CFL number in (0, 1] (reference 0.5)");
  p.predictor_fraction = m.positive("predictor_fraction", p.predictor_fraction, "fraction of dt the predictor advances");
  if (p.predictor_fraction > 1.0) m.fail("predictor_fraction", "expected a value in (0, 1] (reference 1, midpoint 0.5)");
  const std::string integrator = m.text("integrator", fluid::optionName(fluid::kIntegratorNames, p.integrator));
  if (!fluid::optionFromName(fluid::kIntegratorNames, integrator, p.integrator))
    m.fail("integrator", "expected " + fluid::optionNames(fluid::kIntegratorNames) + ", got '" + integrator + "'");
  if (p.integrator == fluid::Integrator::Symplectic && m.has("predictor_fraction") && p.predictor_fraction != 0.5)
    m.fail("predictor_fraction", "the symplectic integrator's predictor advances dt/2: leave predictor_fraction out or set 0.5");
  p.force_dt_factor = m.positive("force_dt_factor", p.force_dt_factor, "factor of the force time-step bound");
  p.gamma = m.positive("gamma", p.gamma, "Tait exponent");
  p.xsph_eps = m.positive("xsph_eps", p.xsph_eps, "XSPH epsilon", true);
  if (p.xsph_eps > 1.0) m.fail("xsph_eps", "expected a value in [0, 1] (reference 0.5)");
  const std::string form = m.text("xsph_form", fluid::optionName(fluid::kXsphFormNames, p.xsph_form));
  if (!fluid::optionFromName(fluid::kXsphFormNames, form, p.xsph_form))
    m.fail("xsph_form", "expected " + fluid::optionNames(fluid::kXsphFormNames) + ", got '" + form + "'");
  p.viscosity_xi = m.positive("viscosity_xi", p.viscosity_xi, "Cleary xi");
  p.viscosity_beta_factor = m.positive("viscosity_beta_factor", p.viscosity_beta_factor, "beta / dx", true);
  p.boundary_h_factor = m.positive("boundary_h_factor", p.h_factor, "wall law length h_w / dx");
  if (p.boundary_h_factor > p.h_factor * (1.0 + 1e-12))
    m.fail("boundary_h_factor", "expected at most h_factor (the neighbour lists reach 2h)");
  if (p.boundary_h_factor == p.h_factor) p.boundary_h_factor = 0.0;  // follows h
  const double wall_h = p.boundary_h_factor > 0.0 ? p.boundary_h_factor : p.h_factor;
  p.boundary_offset = m.positive("b_off", p.boundary_offset, "wall offset in units of dx", true);
  // The wall law acts out to r_perp = h_w - b_off dx (METHOD.md section 2).
  if (p.boundary_offset >= wall_h - 0.25) {
    char msg[160];
    std::snprintf(msg, sizeof msg, "expected a wall offset below h_w/dx - 0.25 = %g (reference 0.5), got %g",
                  wall_h - 0.25, p.boundary_offset);
    m.fail("b_off", msg);
  }
  p.boundary_strength = m.positive("boundary_strength", p.boundary_strength, "wall force scale");
  const std::string wall_law = m.text("boundary_force", fluid::optionName(fluid::kBoundaryForceFormNames, p.boundary_force_form));
  if (!fluid::optionFromName(fluid::kBoundaryForceFormNames, wall_law, p.boundary_force_form))
    m.fail("boundary_force", "expected " + fluid::optionNames(fluid::kBoundaryForceFormNames) + ", got '" + wall_law + "'");
  p.skin_factor = m.positive("skin_factor", p.skin_factor, "Verlet skin / 2h");
  if (m.has("density_diffusion")) {
    MapReader d(m.child("density_diffusion"), "method.density_diffusion", top.source());
    p.density_diffusion_delta = d.positive("delta", p.density_diffusion_delta, "delta-SPH coefficient");
    const std::string f = d.text("form", fluid::optionName(fluid::kDensityDiffusionFormNames, p.density_diffusion_form));
    if (!fluid::optionFromName(fluid::kDensityDiffusionFormNames, f, p.density_diffusion_form))
      d.fail("form", "expected " + fluid::optionNames(fluid::kDensityDiffusionFormNames) + ", got '" + f + "'");
    d.finish();
  } else {
    m.child("density_diffusion");
  }
  readShifting(m, top, p);
  // A run guard, not part of the method: it does not make the method "reference+options".
  p.min_dt_fraction = m.positive("min_dt_fraction", p.min_dt_fraction, "smallest time step / CFL step before the run stops", true);
  if (p.min_dt_fraction >= 1.0) m.fail("min_dt_fraction", "expected a fraction in [0, 1) (0 disables the guard; default 1e-3)");
  p.max_speed_fraction = m.positive("max_speed_fraction", p.max_speed_fraction, "largest fluid speed / c_s before the run stops", true);
  p.max_leak_depth = m.positive("max_leak_depth", p.max_leak_depth, "depth inside a closed surface, in dx, before the run stops", true);
  const bool changed = m.has("particle_shifting") || m.has("h_factor") || m.has("cfl") || m.has("predictor_fraction") || m.has("integrator") || m.has("xsph_form") ||
                       m.has("b_off") || m.has("density_diffusion") || m.has("force_dt_factor") || m.has("gamma") ||
                       m.has("xsph_eps") || m.has("viscosity_xi") || m.has("viscosity_beta_factor") ||
                       m.has("boundary_strength") || m.has("skin_factor") ||
                       m.has("boundary_h_factor") || m.has("boundary_force");
  p.name = changed ? "reference+options" : "reference";
  m.finish();
}

}  // namespace moorsph::io::detail
