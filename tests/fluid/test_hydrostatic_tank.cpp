// A tank of still water under gravity settles to hydrostatic equilibrium
// (METHOD.md sections 1-2): time-averaged pressure against depth within 5% of
// rho0 g depth, density variation below 1%, kinetic energy decaying, no particle
// through a wall. The water starts at hydrostatic density on a lattice; the wall
// force does not depend on pressure, so the near-wall particles must first move to
// their equilibrium distance: that start-up transient is what has to settle.
// Water's own viscosity (1e-3 Pa s) barely damps it at these resolutions, so the
// scenes raise mu (METHOD.md section 1 allows it), and 3D adds density diffusion.
//
// Pressure is compared in the fluid beyond one kernel support (2h) from every wall
// and from the free surface. Closer, a particle's kernel is cut by the wall, the first moment of its kernel
// gradient falls well below 1 and it carries a steeper pressure gradient (measured:
// averaging all particles gives +3..7% in 2D and +8..14% in 3D, where a 20-particle
// wide tank has ~40% of its particles that close to a side wall). The interior
// reading still carries the lattice moment of the kernel gradient at h = 1.2 dx
// (M = 0.964 in 2D, 0.983 in 3D, measured on the settled particles): +1.7..3.7%.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <moorsph/fluid/fluid_simulation.hpp>
#include <moorsph/fluid/tank_scene.hpp>

using namespace moorsph::fluid;

namespace {

template <int D>
void expectHydrostatic(const Vec<D>& tank, double depth, double dx, double duration, double mu,
                       std::vector<std::string> effects, double pressure_tolerance) {
  TankSpec<D> spec;
  spec.size = tank;
  spec.water_upper = tank;
  spec.water_upper[1] = depth;
  spec.dx = dx;
  spec.fluid.sound_speed = 12.0 * std::sqrt(2.0 * 9.81 * depth);  // >= 10x the free-fall speed (METHOD.md)
  spec.fluid.mu = mu;
  spec.fluid.effects = effects;
  auto scene = buildTankScene<D>(spec);
  FluidSimulation<D> sim(scene.setup, scene.fluid, scene.boundary);

  const double rho0 = scene.setup.rho0, g = 9.81, h = scene.setup.h();
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
    if (sim.time() > 0.5 * duration) {  // average the settled state over several slosh periods
      ke_late += ke;
      ++late_samples;
      for (std::size_t i = 0; i < f.size(); ++i) {
        bool near_wall = f.r[i][1] < 2.0 * h;
        for (int k = 0; k < D; ++k)
          if (k != 1) near_wall = near_wall || f.r[i][k] < 2.0 * h || f.r[i][k] > tank[k] - 2.0 * h;
        const double d = depth - f.r[i][1];
        if (near_wall || d < 2.0 * h) continue;
        const int b = std::clamp(static_cast<int>((d - 2.0 * h) / (depth - 4.0 * h) * bins), 0, bins - 1);
        p_sum[b] += f.p[i];
        depth_sum[b] += d;
        ++count[b];
      }
    }
  }
  // Least-squares line p = a + b d through the bins: the gradient b must be rho0 g
  // within the tolerance and p must vanish within half a spacing of the surface.
  double sw = 0, sd = 0, sp = 0, sdd = 0, sdp = 0;
  for (int b = 0; b < bins; ++b) {
    ASSERT_GT(count[b], 0) << "no particles in depth bin " << b;
    const double p = p_sum[b] / count[b], d = depth_sum[b] / count[b];
    std::printf("depth %.4f m: p = %.1f Pa, rho0 g d = %.1f Pa, ratio %.3f\n", d, p, rho0 * g * d, p / (rho0 * g * d));
    sw += 1;
    sd += d;
    sp += p;
    sdd += d * d;
    sdp += d * p;
  }
  const double gradient = (sw * sdp - sd * sp) / (sw * sdd - sd * sd);
  const double zero_depth = -(sp - gradient * sd) / sw / gradient;  // depth where p = 0 (negative: above H)
  std::printf("dp/d(depth) = %.1f Pa/m (rho0 g = %.1f, ratio %.4f); p = 0 at %.2f dx above the initial surface\n",
              gradient, rho0 * g, gradient / (rho0 * g), -zero_depth / dx);
  EXPECT_NEAR(gradient, rho0 * g, pressure_tolerance * rho0 * g);
  EXPECT_LT(std::abs(zero_depth), 0.5 * dx);
  const double ke_end = sim.calcEnergy().kinetic;
  for (double rho : sim.fluid().rho) max_density_error = std::max(max_density_error, std::abs(rho / rho0 - 1.0));
  std::printf("kinetic energy: peak %.3e J, mean over the second half %.3e J, final %.3e J; max |rho/rho0 - 1| = %.4f\n",
              ke_peak, ke_late / late_samples, ke_end, max_density_error);
  EXPECT_LT(ke_late / late_samples, 0.6 * ke_peak) << "kinetic energy did not decay";
  EXPECT_LT(ke_end, 0.5 * ke_peak) << "kinetic energy did not decay";
  EXPECT_LT(max_density_error, 0.01);
  EXPECT_EQ(escaped, 0u);
}

}  // namespace

TEST(HydrostaticTank, Settles2DReferenceMethod) {
  expectHydrostatic<2>(Vec<2>(0.4, 0.3), 0.2, 0.005, 1.5, 0.02, {"pressure", "viscosity", "xsph", "gravity", "walls"}, 0.05);
}

TEST(HydrostaticTank, Settles3DWithDensityDiffusion) {
  expectHydrostatic<3>(Vec<3>(0.2, 0.25, 0.2), 0.12, 0.01, 1.2, 0.01,
                       {"pressure", "viscosity", "xsph", "density_diffusion", "gravity", "walls"}, 0.05);
}
