// The wave makers of a scene (METHOD.md section 4), added to a built simulation.
#include <cmath>
#include <memory>
#include <moorsph/fluid/cubic_spline.hpp>
#include <moorsph/fluid/damping_zone.hpp>
#include <moorsph/fluid/forcing_region.hpp>
#include <moorsph/fluid/piston.hpp>
#include <moorsph/fluid/waves/piston_signal.hpp>
#include <moorsph/fluid/waves/stokes2_wave.hpp>
#include <moorsph/io/scene_builder.hpp>

namespace moorsph::io {
namespace {

/// Regular-wave piston motion in closed form: X(t) = r(t) (S/2) sin(omega t) with the
/// stroke S of the linear transfer function (fluid/waves) and a half-cosine ramp
/// r(t) = (1 - cos(pi t / t_r)) / 2 over the first t_r seconds.
struct RegularPistonMotion {
  double half_stroke, omega, ramp;
  double ramp_value(double t) const { return t >= ramp ? 1.0 : 0.5 * (1.0 - std::cos(M_PI * t / ramp)); }
  double ramp_rate(double t) const { return t >= ramp ? 0.0 : 0.5 * M_PI / ramp * std::sin(M_PI * t / ramp); }
  double x(double t) const { return t <= 0.0 ? 0.0 : ramp_value(t) * half_stroke * std::sin(omega * t); }
  double v(double t) const {
    if (t <= 0.0) return 0.0;
    return half_stroke * (ramp_rate(t) * std::sin(omega * t) + ramp_value(t) * omega * std::cos(omega * t));
  }
};

/// The breather piston's motion sampled at 1/50 of the carrier period, through a cubic
/// spline (the plate's velocity is its derivative).
std::shared_ptr<fluid::CubicSpline> breatherSpline(const PistonConfig& p, double g) {
  fluid::waves::BreatherMakerSpec spec;
  spec.order = p.order;
  spec.a0 = p.a0;
  spec.k0 = p.k0;
  spec.focusDistance = p.focus_distance;
  spec.focusTime = p.focus_time;
  spec.depth = p.depth;
  spec.still = p.still;
  spec.ramp = p.ramp_up;
  spec.rampDown = p.ramp_down;
  spec.duration = p.duration;
  spec.finiteDepthCorrection = p.finite_depth_correction;
  spec.dt = 2.0 * M_PI / std::sqrt(g * p.k0) / 50.0;
  const auto x = fluid::waves::breatherMakerSignal(spec, g);
  std::vector<double> t(x.values.size());
  for (std::size_t i = 0; i < t.size(); ++i) t[i] = x.time(i);
  return std::make_shared<fluid::CubicSpline>(t, x.values);
}

}  // namespace

template <int D>
void addSceneEffects(fluid::FluidSimulation<D>& sim, const SceneConfig& c, const BuiltScene<D>& built) {
  const double g = c.gravityMagnitude();
  if (c.piston.present) {
    const auto& p = c.piston;
    typename fluid::Piston<D>::Signal x, v;
    if (p.signal == "regular") {
      RegularPistonMotion m{0.5 * fluid::waves::pistonStroke(p.wave_height, p.period, p.depth, g), 2.0 * M_PI / p.period,
                            p.ramp_up};
      x = [m](double t) { return m.x(t); };
      v = [m](double t) { return m.v(t); };
    } else if (p.signal == "breather") {
      const auto spline = breatherSpline(p, g);
      x = [spline](double t) { return spline->value(t); };
      v = [spline](double t) { return spline->derivative(t); };
    } else {
      auto spline = std::make_shared<fluid::CubicSpline>(p.table_t, p.table_x);
      x = [spline](double t) { return spline->value(t); };
      v = [spline](double t) { return spline->derivative(t); };
    }
    sim.addEffect(std::make_unique<fluid::Piston<D>>(sim.updWalls(), built.piston_surface, x, v));
  }
  for (const auto& z : c.damping_zones)
    sim.addEffect(std::make_unique<fluid::DampingZone<D>>(z.x_start, z.x_end, z.k_max, sim.cflDt()));
  if (c.forcing.present) {
    const auto& f = c.forcing;
    fluid::ForcingRegionSpec spec;
    spec.x_start = f.x_start;
    spec.length = f.length;
    spec.floor = f.floor;
    spec.bottom_gap = f.bottom_gap;
    spec.still_level = f.still_level;
    spec.kappa = f.kappa;
    spec.mu = c.mu;
    spec.ramp_up = f.ramp_up;
    spec.end_time = f.end_time;
    spec.gain = f.gain;
    const double depth = f.still_level - f.floor;
    typename fluid::ForcingRegion<D>::TargetField target;
    if (f.theory == "stokes2") {
      const auto wave = std::make_shared<fluid::waves::Stokes2Wave>(f.amplitude, f.period, depth, g);
      target = [wave](double x, double y, double t) { return wave->velocity(x, y, t); };
    } else {
      const auto wave = std::make_shared<fluid::waves::AiryWave>(f.amplitude, f.period, depth, g);
      target = [wave](double x, double y, double t) { return wave->velocity(x, y, t); };
    }
    sim.addEffect(std::make_unique<fluid::ForcingRegion<D>>(spec, target, sim.cflDt()));
  }
}

template void addSceneEffects<2>(fluid::FluidSimulation<2>&, const SceneConfig&, const BuiltScene<2>&);
template void addSceneEffects<3>(fluid::FluidSimulation<3>&, const SceneConfig&, const BuiltScene<3>&);

}  // namespace moorsph::io
