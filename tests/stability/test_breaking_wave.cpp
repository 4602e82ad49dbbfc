// Stability case 5: a very steep, breaking wave from the piston, 2D. Water d = 0.2 m
// deep in a 2 m flume (dx = 0.01 m, 3900 particles, reference method, c_s = 25 m/s),
// driven by a piston plate (METHOD.md section 4b) at rest position x = 0.1 m with
// X(t) = A sin(omega t), A = 0.06 m, T = 0.8 s, ramped in over one period. Outside
// numbers: linear dispersion gives k = 7.05 1/m (L = 0.89 m, kd = 1.41); Biesel's
// piston transfer H/(2A) = 2 (cosh 2kd - 1)/(sinh 2kd + 2kd) = 1.33 gives H = 0.16 m,
// H/L = 0.18, above Miche's breaking limit 0.142 tanh(kd) = 0.126: the waves break.
// Run 3 s (the first crests reach the far wall and reflect). Asserted (stability_monitor.hpp):
//  - no NaN/Inf; no particle through a tank wall or behind the piston plate;
//  - dt >= 0.2 dt_cfl;
//  - E(t) - E0 <= W_piston(t) + E_wall(0) + 5% of max W_piston, where W_piston is the
//    work the plate does on the water, sum over steps of dt (-F_x) X'(t) with F the
//    fluid's force on the plate at the state the corrector used (the injected work;
//    the 5% covers this first-order quadrature of an oscillating work, up to 53 J in
//    and 19 J back out);
//  - the flow stays below 1.5 c_s/10.
// Method: the reference, except CFL = 0.4. At the reference CFL 0.5 the same run flings
// particles at 6.3 m/s = 0.25 c_s near the piston at 2.76 s, dt drops to 0.67 dt_cfl,
// and E - E0 - W exceeds E_wall by 1.1% of M g d/2 (4.2 J); at CFL 0.4 max |v| is
// 2.6 m/s and dt never leaves dt_cfl: the two-step instability of docs/stability.md.
#include <gtest/gtest.h>

#include <cmath>
#include <moorsph/fluid/box_geometry.hpp>
#include <moorsph/fluid/piston.hpp>
#include <moorsph/fluid/tank_scene.hpp>

#include "stability_monitor.hpp"

using namespace moorsph;


TEST(StabilityBreakingWave, SteepPistonWavesBreakWithoutBlowUp) {
  const double depth = 0.2, dx = 0.01, g = 9.81, x0 = 0.1;
  const double amplitude = 0.06, period = 0.8, omega = 2.0 * M_PI / period;
  fluid::TankSpec<2> spec;
  spec.size = fluid::Vec<2>(2.0, 0.5);
  spec.water_lower = fluid::Vec<2>(x0, 0.0);
  spec.water_upper = fluid::Vec<2>(2.0, depth);
  spec.dx = dx;
  spec.fluid.sound_speed = 25.0;
  spec.fluid.effects = {"pressure", "viscosity", "xsph", "gravity", "walls"};
  spec.fluid.method.cfl = 0.4;  // see the header comment
  auto scene = fluid::buildTankScene<2>(spec);
  const auto plate = fluid::sampleBoxSurface<2>(fluid::Vec<2>(x0 - 0.04, 0.0), fluid::Vec<2>(x0, 0.5), dx,
                                                {false, true, false, false}, fluid::NormalSide::Outward);
  const auto surface = scene.boundary.addSurface(plate, fluid::SurfaceInfo{"piston", true, true, Eigen::Vector3d(x0, 0, 0)});
  fluid::FluidSimulation<2> sim(scene.setup, scene.fluid, scene.boundary);
  // Half-cosine ramp over the first period: X = r(t) A sin(omega t).
  auto ramp = [&](double t) { return t >= period ? 1.0 : 0.5 * (1.0 - std::cos(M_PI * t / period)); };
  auto ramp_rate = [&](double t) { return t >= period ? 0.0 : 0.5 * M_PI / period * std::sin(M_PI * t / period); };
  fluid::Piston<2>::Signal X = [=](double t) { return ramp(t) * amplitude * std::sin(omega * t); };
  fluid::Piston<2>::Signal V = [=](double t) {
    return ramp_rate(t) * amplitude * std::sin(omega * t) + ramp(t) * amplitude * omega * std::cos(omega * t);
  };
  auto piston = std::make_unique<fluid::Piston<2>>(sim.updWalls(), surface, X, V);
  const fluid::Piston<2>* work = piston.get();  // sums the plate's work on the water
  sim.addEffect(std::move(piston));

  stability::StabilityMonitor<2> monitor(sim, spec.size, false);
  monitor.addBody("piston", [&sim, &X, x0](const fluid::Vec<2>& r) { return r[0] - (x0 + X(sim.time())); });
  double mass = 0.0;
  for (double m : sim.fluid().m) mass += m;
  const double wall_energy = stability::wallForceEnergy(sim);
  monitor.sample(sim.calcEnergy().total(), 0.0);
  double max_crest = 0.0, max_work = 0.0;
  ASSERT_NO_THROW({
    while (sim.time() < 3.0) {
      sim.step();
      monitor.sample(sim.calcEnergy().total(), work->work());
      max_work = std::max(max_work, work->work());
      for (const auto& r : sim.fluid().r) max_crest = std::max(max_crest, r[1]);
    }
  });
  const double scale = mass * g * depth / 2.0;
  std::printf("%s\npiston work %.3f J (max %.3f J), highest particle %.3f m (%.2f d), E-E0-W max %.4g J (E_wall %.4g J "
              "+ %.3g of max W = %.3g of M g d/2)\n",
              monitor.summary().c_str(), work->work(), max_work, max_crest, max_crest / depth, monitor.maxEnergyExcess(),
              wall_energy, (monitor.maxEnergyExcess() - wall_energy) / max_work,
              (monitor.maxEnergyExcess() - wall_energy) / scale);
  EXPECT_EQ(monitor.nonFinite(), 0u);
  EXPECT_EQ(monitor.throughWall(), 0u);
  EXPECT_EQ(monitor.throughBody(), 0u) << "fluid behind the piston plate";
  EXPECT_GE(monitor.minDtRatio(), 0.2);
  EXPECT_GT(work->work(), 0.0);
  EXPECT_LE(monitor.maxEnergyExcess(), wall_energy + 0.05 * max_work);
  EXPECT_LE(monitor.maxSpeed(), 1.5 * 0.1 * spec.fluid.sound_speed);
  // The crests are steep: the highest particle rises well above still water.
  EXPECT_GT(max_crest, depth + 0.05);
}
