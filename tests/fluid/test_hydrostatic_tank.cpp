// A tank of still water under gravity settles to hydrostatic equilibrium
// (METHOD.md sections 1-2): pressure against depth within 5% of rho0 g depth,
// density variation below 1%, kinetic energy decaying, no particle through a wall.
// The water starts at uniform density rho0, so the solver itself must build the
// hydrostatic pressure field.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <moorsph/fluid/fluid_simulation.hpp>
#include <moorsph/fluid/tank_scene.hpp>

using namespace moorsph::fluid;

namespace {

template <int D>
void expectHydrostatic(const Vec<D>& tank, double depth, double dx, double duration) {
  TankSpec<D> spec;
  spec.size = tank;
  spec.water_upper = tank;
  spec.water_upper[1] = depth;
  spec.dx = dx;
  spec.hydrostatic_start = false;
  spec.fluid.sound_speed = 10.0 * std::sqrt(2.0 * 9.81 * depth);
  spec.fluid.effects = {"pressure", "viscosity", "xsph", "gravity", "walls"};
  auto scene = buildTankScene<D>(spec);
  FluidSimulation<D> sim(scene.setup, scene.fluid, scene.boundary);

  const double rho0 = scene.setup.rho0, g = 9.81;
  const int bins = 5;
  std::vector<double> p_sum(bins, 0.0), depth_sum(bins, 0.0);
  std::vector<long> count(bins, 0);
  double ke_peak = 0.0, ke_late = 0.0;
  long late_samples = 0;
  double max_density_error = 0.0;
  std::size_t escaped = 0;
  while (sim.time() < duration) {
    sim.step();
    const auto& f = sim.fluid();
    const double ke = sim.calcEnergy().kinetic;
    ke_peak = std::max(ke_peak, ke);
    for (std::size_t i = 0; i < f.size(); ++i)
      for (int k = 0; k < D; ++k)
        if (f.r[i][k] < 0.0 || f.r[i][k] > tank[k]) ++escaped;
    if (sim.time() > 0.7 * duration) {  // average the settled state
      ke_late += ke;
      ++late_samples;
      for (std::size_t i = 0; i < f.size(); ++i) {
        max_density_error = std::max(max_density_error, std::abs(f.rho[i] / rho0 - 1.0));
        const double d = depth - f.r[i][1];
        const int b = std::clamp(static_cast<int>(d / depth * bins), 0, bins - 1);
        p_sum[b] += f.p[i];
        depth_sum[b] += d;
        ++count[b];
      }
    }
  }
  // Skip the top bin: there rho0 g depth is small and the free surface's kernel
  // truncation dominates the relative error.
  for (int b = 1; b < bins; ++b) {
    const double p = p_sum[b] / count[b], d = depth_sum[b] / count[b];
    EXPECT_NEAR(p, rho0 * g * d, 0.05 * rho0 * g * d) << "depth bin " << b << " at " << d << " m";
  }
  EXPECT_LT(max_density_error, 0.01);
  EXPECT_LT(ke_late / late_samples, 0.1 * ke_peak) << "kinetic energy did not decay";
  EXPECT_EQ(escaped, 0u);
}

}  // namespace

TEST(HydrostaticTank, Settles2D) { expectHydrostatic<2>(Vec<2>(0.4, 0.3), 0.2, 0.005, 1.5); }

TEST(HydrostaticTank, Settles3D) { expectHydrostatic<3>(Vec<3>(0.12, 0.3, 0.12), 0.16, 0.01, 1.0); }
