// The velocity probe (fluid/velocity_probe.hpp) against fields given to the particles:
// a uniform stream is read exactly, the Airy orbital velocity under a wave (a smooth
// field, the kernel full) to second order in h, a point above the water reads NaN, and
// the cell-grid path after a step gives the brute-force Shepard average.
#include <gtest/gtest.h>

#include <cmath>
#include <moorsph/fluid/tank_scene.hpp>
#include <moorsph/fluid/velocity_probe.hpp>
#include <moorsph/fluid/waves/airy_wave.hpp>

using namespace moorsph;
using fluid::Vec;

namespace {

/// A 2D tank one wavelength (1 m) long with water 0.25 m deep at dx = 5 mm.
fluid::Scene<2> tank() {
  fluid::TankSpec<2> spec;
  spec.size = Vec<2>(1.0, 0.4);
  spec.water_upper = Vec<2>(1.0, 0.25);
  spec.dx = 0.005;
  spec.fluid.sound_speed = 10.0 * std::sqrt(2.0 * 9.81 * 0.25);
  spec.fluid.effects = {"pressure", "gravity", "walls"};
  return fluid::buildTankScene<2>(spec);
}

fluid::VelocityProbe<2> probeAt(double x, double y) {
  fluid::VelocityProbeSpec<2> s;
  s.point = Vec<2>(x, y);
  return fluid::VelocityProbe<2>(s);
}

}  // namespace

TEST(VelocityProbe, ReadsAUniformStreamExactly) {
  auto scene = tank();
  for (auto& v : scene.fluid.v) v = Vec<2>(0.3, -0.1);
  fluid::FluidSimulation<2> sim(scene.setup, scene.fluid, scene.boundary);
  for (const auto& p : {Vec<2>(0.5, 0.1), Vec<2>(0.0121, 0.2437), Vec<2>(0.9, 0.003)}) {
    const Vec<2> v = probeAt(p[0], p[1]).read(sim);
    EXPECT_NEAR(v[0], 0.3, 1e-13);
    EXPECT_NEAR(v[1], -0.1, 1e-13);
  }
  // Above the water (xi = 0) and in the air just over the top row (xi < 0.5): dry.
  EXPECT_TRUE(std::isnan(probeAt(0.5, 0.35).read(sim)[0]));
  EXPECT_TRUE(std::isnan(probeAt(0.5, 0.2575).read(sim)[1]));
}

// Airy orbital velocity, a = 0.02 m, T = 0.836 s on d = 0.25 m (lambda = 1.00 m, k h =
// 0.038). Where the kernel is full the Shepard average of a smooth field errs by
// ~h^2 of its Laplacian (the lattice's first moments vanish), which is zero for a
// potential flow; measured 1e-6 of a omega.
TEST(VelocityProbe, ReadsTheAiryOrbitalVelocity) {
  auto scene = tank();
  const fluid::waves::AiryWave wave(0.02, 0.836, 0.25, 9.81);
  for (std::size_t i = 0; i < scene.fluid.size(); ++i) {
    const Eigen::Vector2d u = wave.velocity(scene.fluid.r[i][0], scene.fluid.r[i][1], 0.0);
    scene.fluid.v[i] = Vec<2>(u[0], u[1]);
  }
  fluid::FluidSimulation<2> sim(scene.setup, scene.fluid, scene.boundary);
  const double scale = wave.amplitude() * 2.0 * M_PI / 0.836;  // a omega, the surface orbital speed
  double worst = 0.0;
  for (double x : {0.2, 0.37, 0.5, 0.81})
    for (double y : {0.05, 0.12, 0.2}) {
      const Vec<2> v = probeAt(x, y).read(sim);
      const Eigen::Vector2d u = wave.velocity(x, y, 0.0);
      worst = std::max({worst, std::abs(v[0] - u[0]), std::abs(v[1] - u[1])});
    }
  std::printf("Airy orbital velocity: largest probe error %.2e m/s = %.2e of a omega\n", worst, worst / scale);
  EXPECT_LT(worst, 1e-4 * scale);
}

// After a step the probe finds the particles through the cell grid: the same average as
// a scan of every particle.
TEST(VelocityProbe, GridPathMatchesAScanOfEveryParticle) {
  auto scene = tank();
  fluid::FluidSimulation<2> sim(scene.setup, scene.fluid, scene.boundary);
  for (int n = 0; n < 20; ++n) sim.step();  // the start-up sloshing gives every particle a velocity
  const Vec<2> point(0.4321, 0.1234);
  const Vec<2> v = probeAt(point[0], point[1]).read(sim);
  Vec<2> sum = Vec<2>::Zero();
  double fill = 0.0;
  const auto& f = sim.fluid();
  for (std::size_t j = 0; j < f.size(); ++j) {
    const double w = sim.kernel().value((f.r[j] - point).norm()) * f.m[j] / f.rho[j];
    sum += w * f.v[j];
    fill += w;
  }
  ASSERT_GT(sum.norm(), 0.0);
  EXPECT_NEAR(v[0], sum[0] / fill, 1e-15);
  EXPECT_NEAR(v[1], sum[1] / fill, 1e-15);
}
