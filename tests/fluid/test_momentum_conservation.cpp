// In a fully periodic box with no walls and no gravity, the pair forces are
// antisymmetric, so total linear momentum is conserved to round-off
// (METHOD.md section 1). The fluid starts from a random velocity field.
#include <gtest/gtest.h>

#include <random>
#include <moorsph/fluid/box_geometry.hpp>
#include <moorsph/fluid/fluid_simulation.hpp>

using namespace moorsph::fluid;

namespace {

template <int D>
void expectMomentumConserved(const std::vector<std::string>& effects) {
  FluidSetup<D> s;
  s.dx = 0.01;
  s.sound_speed = 10.0;
  s.mu = 1e-2;
  s.effects = effects;
  s.domain.lower = Vec<D>::Zero();
  s.domain.upper = Vec<D>::Constant(0.1);
  s.domain.periodic.fill(true);
  FluidParticles<D> f;
  fillBox<D>(f, s.domain.lower, s.domain.upper, s.dx, TaitEos(s.rho0, s.sound_speed), 0.0, 0.0);
  std::mt19937 gen(42);
  std::normal_distribution<double> noise(0.0, 0.3);
  for (std::size_t i = 0; i < f.size(); ++i) {
    for (int k = 0; k < D; ++k) f.v[i][k] = noise(gen);
    f.rho[i] *= 1.0 + 0.002 * noise(gen);
  }
  FluidSimulation<D> sim(s, f);
  auto momentum = [&] {
    Vec<D> p = Vec<D>::Zero();
    double scale = 0.0;
    for (std::size_t i = 0; i < sim.fluid().size(); ++i) {
      p += sim.fluid().m[i] * sim.fluid().v[i];
      scale += sim.fluid().m[i] * sim.fluid().v[i].norm();
    }
    return std::make_pair(p, scale);
  };
  const auto [p0, scale] = momentum();
  for (int n = 0; n < 50; ++n) sim.step();
  const auto [p1, unused] = momentum();
  (void)unused;
  // Round-off: relative to the sum of |m v|, a few ulps per particle-step.
  EXPECT_LT((p1 - p0).norm(), 1e-12 * scale) << "p0 = " << p0.transpose() << ", p1 = " << p1.transpose();
  EXPECT_GT(sim.lastInteractions(), 10u * sim.fluid().size());
}

}  // namespace

TEST(MomentumConservation, PeriodicBox2DPressureOnly) { expectMomentumConserved<2>({"pressure"}); }
TEST(MomentumConservation, PeriodicBox2DAllPairTerms) {
  expectMomentumConserved<2>({"pressure", "viscosity", "xsph", "density_diffusion"});
}
TEST(MomentumConservation, PeriodicBox3DAllPairTerms) {
  expectMomentumConserved<3>({"pressure", "viscosity", "xsph", "density_diffusion"});
}
