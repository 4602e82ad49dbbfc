#pragma once
// A still-water run for stability case 7 (test_still_water.cpp, test_still_water_3d.cpp):
// the tank of `spec`, an optional settling damping of 2 1/s until `settle`, then free to
// `end`, measured after every step from the end of the settling on.
#include <cmath>
#include <cstdio>
#include <string>
#include <moorsph/fluid/settling_damping.hpp>
#include <moorsph/fluid/tank_scene.hpp>
#include "stability_monitor.hpp"

namespace moorsph::stability {

template <int D>
fluid::Vec<D> centreOfMass(const fluid::FluidParticles<D>& f) {
  fluid::Vec<D> c = fluid::Vec<D>::Zero();
  double m = 0.0;
  for (std::size_t i = 0; i < f.size(); ++i) {
    c += f.m[i] * f.r[i];
    m += f.m[i];
  }
  return c / m;
}

/// What a still-water run measured, from the end of the settling on (all of it when
/// there is none). Lengths in dx, speeds in sqrt(g d).
struct StillWaterRun {
  std::string monitor;
  unsigned non_finite = 0, through_wall = 0;
  double min_dt_ratio = 0.0, energy_excess = 0.0, energy_allowance = 0.0;
  double max_speed = 0.0, max_rms = 0.0, rms_first = 0.0, rms_last = 0.0;
  double sideways = 0.0, rise = 0.0, fall = 0.0;
};

template <int D>
StillWaterRun runStillWater(const fluid::TankSpec<D>& spec, double depth, double settle, double end) {
  const double g = 9.81, scale_v = std::sqrt(g * depth);
  auto scene = fluid::buildTankScene<D>(spec);
  fluid::FluidSimulation<D> sim(scene.setup, scene.fluid, scene.boundary);
  if (settle > 0.0) sim.addEffect(std::make_unique<fluid::SettlingDamping<D>>(2.0, settle));
  stability::StabilityMonitor<D> monitor(sim, spec.size, false);
  double mass = 0.0;
  for (double m : sim.fluid().m) mass += m;
  StillWaterRun out;
  out.energy_allowance = stability::wallForceEnergy(sim) + 0.005 * mass * g * depth / 2.0;
  monitor.sample(sim.calcEnergy().total(), 0.0);
  const fluid::Vec<D> c0 = centreOfMass(sim.fluid());
  fluid::Vec<D> c_settled = c0;
  bool started = false;
  int n_first = 0, n_last = 0;
  while (sim.time() < end) {
    sim.step();
    monitor.sample(sim.calcEnergy().total(), 0.0);
    if (sim.time() < settle) continue;
    if (!started) c_settled = centreOfMass(sim.fluid()), started = true;
    double sum2 = 0.0;
    for (const auto& v : sim.fluid().v) {
      out.max_speed = std::max(out.max_speed, v.norm() / scale_v);
      sum2 += v.squaredNorm();
    }
    const double ms = sum2 / static_cast<double>(sim.fluid().size());
    out.max_rms = std::max(out.max_rms, std::sqrt(ms) / scale_v);
    if (sim.time() < settle + 0.5) out.rms_first += ms, ++n_first;
    if (sim.time() > end - 0.5) out.rms_last += ms, ++n_last;
    const fluid::Vec<D> c = centreOfMass(sim.fluid());
    for (int a = 0; a < D; ++a)
      if (a != 1) out.sideways = std::max(out.sideways, std::abs(c[a] - c_settled[a]) / spec.dx);
    out.rise = std::max(out.rise, (c[1] - c_settled[1]) / spec.dx);
    out.fall = std::max(out.fall, (c_settled[1] - c[1]) / spec.dx);
  }
  out.rms_first = std::sqrt(out.rms_first / n_first) / scale_v;
  out.rms_last = std::sqrt(out.rms_last / n_last) / scale_v;
  out.monitor = monitor.summary();
  out.non_finite = monitor.nonFinite();
  out.through_wall = monitor.throughWall();
  out.min_dt_ratio = monitor.minDtRatio();
  out.energy_excess = monitor.maxEnergyExcess();
  std::printf("%s\n%dD after %.1f s of settling: max |v| %.4f sqrt(g d), max rms %.4f sqrt(g d), rms first/last 0.5 s "
              "%.4f / %.4f sqrt(g d); centre of mass: sideways %.3f dx, rise %.3f dx, fall %.3f dx; E-E0 max %.4g J "
              "(allowed %.4g J)\n",
              out.monitor.c_str(), D, settle, out.max_speed, out.max_rms, out.rms_first, out.rms_last, out.sideways,
              out.rise, out.fall, out.energy_excess, out.energy_allowance);
  return out;
}


}  // namespace moorsph::stability
