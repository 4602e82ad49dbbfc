// Wave makers, damping zone and gauges in short 2D runs, against theory (issue 6
// item 4; METHOD.md sections 3, 4a, 4b). Tanks from cases/wave_propagation.
//
// - Gauge in still water: reads the surface of the settled water (its top row + dx/2)
//   within 0.1 dx, that surface being within 0.1 dx of the nominal still level N_rows dx;
//   and the kernel constant s(xi_t) it adds is the
//   half-space integral of the Wendland kernel (numpy, outside this code:
//   s(0.8) = 0.4532 h in 2D, 0.4461 h in 3D; s(1/2) = 0; s(0.2) = -s(0.8)).
// - Forcing region (periodic tank of one wavelength, region over half of it, Airy
//   target): the trough-to-crest height averaged over six gauges spread along the
//   wavelength is within 10% of the requested 2a.
// - Initial wave (periodic tank started with an Airy wave, no maker): at t = 0
//   the gauges read the theory's elevation, and 2.25 periods later the wave is still there
//   with its height (within 10%) and phase (rms misfit to the theory's elevation at that
//   time below a fifth of the amplitude): it travels the right way at the right speed.
// - Damping zone: a piston flume's incident and reflected waves are separated from
//   twelve gauges (Mansard & Funke least squares with a decay rate); the reflection
//   coefficient at the zone's start, which equals the standing-wave envelope ratio
//   (H_max - H_min) / (H_max + H_min) there, is below 10%.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <moorsph/fluid/tank_scene.hpp>
#include <moorsph/fluid/waves/dispersion.hpp>
#include <moorsph/fluid/waves/airy_wave.hpp>
#include "wave_tanks.hpp"

using namespace moorsph;
using moorsph::fluid::Vec;

TEST(WaveGauge, HalfSpaceThresholdDepthIsAKernelIntegral) {
  EXPECT_NEAR(fluid::halfSpaceThresholdDepth<2>(0.8), 0.4532, 2e-4);
  EXPECT_NEAR(fluid::halfSpaceThresholdDepth<3>(0.8), 0.4461, 2e-4);
  EXPECT_NEAR(fluid::halfSpaceThresholdDepth<2>(0.5), 0.0, 1e-4);
  EXPECT_NEAR(fluid::halfSpaceThresholdDepth<2>(0.2), -fluid::halfSpaceThresholdDepth<2>(0.8), 1e-4);
  EXPECT_THROW(fluid::halfSpaceThresholdDepth<2>(1.0), std::invalid_argument);
}

TEST(WaveGauge, ReadsStillLevelInSettledWater) {
  fluid::TankSpec<2> spec;
  spec.size = Vec<2>(0.6, 0.4);
  spec.water_upper = Vec<2>(0.6, 0.2);
  spec.dx = 0.01;
  spec.fluid.sound_speed = 10.0 * std::sqrt(2.0 * 9.81 * 0.2);
  spec.fluid.effects = {"pressure", "viscosity", "xsph", "gravity", "walls"};
  auto scene = fluid::buildTankScene<2>(spec);
  fluid::FluidSimulation<2> sim(scene.setup, scene.fluid, scene.boundary);
  std::vector<fluid::WaveGauge<2>> gauges;
  for (double x : {0.15, 0.233, 0.3, 0.412, 0.45}) {
    fluid::WaveGaugeSpec<2> g;
    g.position = Vec<2>(x, 0.0);
    g.top = 0.4;
    gauges.emplace_back(g);
  }
  double sum = 0.0;
  int count = 0;
  while (sim.time() < 1.0) {
    sim.step();
    if (sim.time() > 0.5 && sim.stepCount() % 20 == 0)
      for (const auto& g : gauges) {
        sum += g.read(sim);  // single readings swing +-0.4 dx with the start-up sloshing
        ++count;
      }
  }
  const double mean = sum / count;
  // Where the water's rows sit after settling (the walls' b_off sets the bottom row's
  // height): mean y of the lowest and highest rows, away from the side walls.
  double bottom = 0.0, top = 0.0;
  int nb = 0, nt = 0;
  for (const auto& r : sim.fluid().r) {
    if (r[0] < 0.1 || r[0] > 0.5) continue;
    if (r[1] < spec.dx) { bottom += r[1]; ++nb; }
    if (r[1] > 0.2 - spec.dx) { top += r[1]; ++nt; }
  }
  std::printf("still level read %.4f m (%+.3f dx from the still level); bottom row at %.3f dx, top row at "
              "still level %+.3f dx\n", mean, (mean - 0.2) / spec.dx, bottom / nb / spec.dx, (top / nt - 0.2) / spec.dx);
  // The gauge against the surface of the water as it stands (top row + dx/2): 0.1 dx.
  // Measured +0.03 dx. Against the nominal level N_rows dx the reading is +0.11 dx,
  // of which +0.08 dx is real: the bottom row settles 0.056 dx above the b_off = 0.5
  // position (the wall force balances the column's weight there, METHOD.md 2) and the
  // water expands slightly as its density relaxes. The plain xi_t crossing (the
  // reference reading, volume_edge = false) is s(0.8) = 0.54 dx lower: -0.44 dx.
  const double surface = top / nt + 0.5 * spec.dx;
  EXPECT_NEAR(mean, surface, 0.1 * spec.dx);
  EXPECT_NEAR(surface, 0.2, 0.1 * spec.dx);
}

TEST(ForcingRegion, MakesTheRequestedAmplitude) {
  cases::PeriodicWaveTankSpec spec;  // T = 0.836 s, depth 0.25 m: lambda = 1.0 m, kd = 1.57
  spec.fluid.dx = 0.0125;            // adjusted to 0.0139 m by METHOD.md 4a
  spec.amplitude = 0.025;            // 3.6 particles per wave height
  spec.maker_length = 0.5;
  spec.ramp_up = 1.0;
  spec.gauges = {0.05, 0.25, 0.45, 0.6, 0.75, 0.9};
  auto tank = cases::buildPeriodicWaveTank(spec);
  const double end = 5.0;
  const auto rec = cases::runAndRecord(tank, end, tank.period / 50.0);
  double sum = 0.0;
  for (std::size_t g = 0; g < rec.eta.size(); ++g) {
    const double H = cases::meanWaveHeight(rec.t, rec.eta[g], tank.period, end - 3.0 * tank.period, end);
    std::printf("x = %.2f m: H = %.4f m (%.3f of requested)\n", spec.gauges[g], H, H / (2.0 * spec.amplitude));
    sum += H;
  }
  const double ratio = sum / rec.eta.size() / (2.0 * spec.amplitude);
  std::printf("generated / requested height: %.3f\n", ratio);
  EXPECT_NEAR(ratio, 1.0, 0.10);
}

TEST(PeriodicWaveTank, InitialWaveTravelsAtThePhaseSpeed) {
  cases::PeriodicWaveTankSpec spec;  // lambda = 1.0 m, kd = 1.57, H/lambda = 0.05
  spec.fluid = cases::lowDissipationWaveFluid(0.0125);  // 4 particles per height
  spec.floor = "mirror";
  spec.amplitude = 0.025;
  spec.initial_wave = true;
  auto tank = cases::buildPeriodicWaveTank(spec);
  const fluid::waves::AiryWave theory(spec.amplitude, tank.period, tank.depth, 9.81);
  // A quarter period past two periods: there a wave going the wrong way, or a standing
  // one, would be a quarter wavelength off (at whole periods it would look right).
  const double end = 2.25 * tank.period;
  const auto rec = cases::runAndRecord(tank, end, tank.period / 50.0);
  const auto misfit = [&](std::size_t k) {  // rms of gauge minus theory at sample k
    double sum = 0.0;
    for (std::size_t g = 0; g < rec.eta.size(); ++g) {
      const double e = rec.eta[g][k] - theory.elevation(tank.gauges[g].spec().position[0], rec.t[k]);
      sum += e * e;
    }
    return std::sqrt(sum / rec.eta.size());
  };
  double height = 0.0;
  for (const auto& eta : rec.eta) height += cases::meanWaveHeight(rec.t, eta, tank.period, end - tank.period, end);
  height /= rec.eta.size();
  std::printf("misfit to theory: %.4f m at t = 0, %.4f m at t = %.2f s; height over the last period %.4f m "
              "(%.3f of 2a)\n", misfit(0), misfit(rec.t.size() - 1), rec.t.back(), height,
              height / (2.0 * spec.amplitude));
  EXPECT_LT(misfit(0), 0.1 * spec.amplitude);
  EXPECT_LT(misfit(rec.t.size() - 1), 0.2 * spec.amplitude);
  EXPECT_NEAR(height / (2.0 * spec.amplitude), 1.0, 0.10);
}

TEST(DampingZone, ReflectsLessThanTenPercent) {
  cases::PistonFlumeSpec spec;  // T = 0.836 s, depth 0.26 m (13 rows), lambda = 1.01 m
  spec.fluid.dx = 0.02;
  // With density diffusion (as every wave scene has): without it, this flume at two
  // particles per height is so noisy that a change of round-off alone (the compiler's
  // fused multiply-adds in the pair loop) moved the fitted R from 0.033 to 0.166 and the
  // incident height by 14% (session 20); with it both builds give the same heights to
  // five digits.
  spec.fluid.effects.push_back("density_diffusion");
  spec.height = 0.04;
  spec.length = 3.0;
  spec.damping_start = 1.75;    // 1.25 m = 1.2 lambda of damping
  spec.damping_k_max = 10.0;
  for (double x = 0.7; x < 1.71; x += 0.1) spec.gauges.push_back(x);
  auto tank = cases::buildPistonFlume(spec);
  const double end = 11.0;
  const auto rec = cases::runAndRecord(tank, end, tank.period / 40.0);
  const double omega = 2.0 * M_PI / tank.period, k = 2.0 * M_PI / tank.wavelength;
  const auto sep = cases::separateIncidentReflected(rec, spec.gauges, omega, k, end - 4.0 * tank.period, end,
                                                    spec.damping_start);
  std::printf("incident %.4f m, reflected %.4f m at the zone's start: R = %.3f; decay %.2f 1/m, fit residual %.2f\n",
              sep.incident, sep.reflected, sep.reflection(), sep.alpha, sep.residual);
  EXPECT_LT(sep.reflection(), 0.10);
  EXPECT_LT(sep.residual, 0.25);
}
