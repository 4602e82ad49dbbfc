// Stability case 3: a slack cable that snaps taut, 2D. A cylinder (R = 0.05 m, density
// ratio 0.5) held 0.15 m above the floor in water 0.4 m deep is tied to the floor
// below by a tension-only spring (METHOD.md section 5) of stiffness k = 2000 N/m and
// rest length 0.05 m longer than the distance: slack. Released at 0.2 s, it rises
// under its net buoyancy F = (1 - 0.5) rho g pi R^2 = 38.5 N/m, the cable snaps taut at
// about 0.6 m/s and the body rebounds. Run to 0.9 s.
// Outside numbers for the bounds: work-energy with no losses, F (s + x) = k x^2 / 2,
// gives the largest stretch x_max = F/k + sqrt((F/k)^2 + 2 F s/k) = 0.067 m for slack
// s = 0.05 m, hence a rise <= s + x_max = 0.117 m and a tension <= k x_max = 134 N.
// The fluid only removes energy (drag, radiated waves), so any excess is instability.
// Also asserted: the stability contract (stability_monitor.hpp), with the energy of
// the coupled ledger (fluid + body + line elastic + line damping) never above E0 by
// more than E_wall(0) + 0.5% of the water's M g d/2 (E_wall(0): the wall-force
// energy of the initial lattice, which the ledger omits; stability_monitor.hpp).
#include <gtest/gtest.h>

#include "cylinder_scene.hpp"

using namespace moorsph;

TEST(StabilitySlackCable, SnapLoadBoundedByWorkEnergy) {
  stability::CylinderCase c;
  c.tank = fluid::Vec<2>(0.6, 0.6);
  c.depth = 0.4;
  c.centre = fluid::Vec<2>(0.3, 0.2);
  c.release_time = 0.2;
  c.spring_stiffness = 2000.0;
  c.spring_slack = 0.05;
  auto co = stability::buildCylinderCase(c);
  stability::StabilityMonitor<2> monitor(co->fluid(), c.tank, false);
  double water = 0.0;
  for (double m : co->fluid().fluid().m) water += m;
  const double wall_energy = stability::wallForceEnergy(co->fluid());
  const auto track = stability::runCylinderCase(*co, c, monitor, 0.9);
  ASSERT_TRUE(track.error.empty()) << track.error;
  const double g = 9.81, pi = std::acos(-1.0);
  const double f = (1.0 - c.density_ratio) * 1000.0 * g * pi * c.radius * c.radius, k = c.spring_stiffness;
  const double x_max = f / k + std::sqrt(f * f / (k * k) + 2.0 * f * c.spring_slack / k);
  const double rise = track.max_position[1] - c.centre[1];
  const double allowance = wall_energy + 0.005 * water * g * c.depth / 2.0;
  std::printf("%s\nrise %.4f m (bound %.4f), max tension %.2f N (bound %.2f), max speed %.3f m/s; "
              "E-E0 max %.4g J (allowance %.4g)\n",
              monitor.summary().c_str(), rise, c.spring_slack + x_max, track.max_tension, k * x_max, track.max_speed,
              monitor.maxEnergyExcess(), allowance);
  EXPECT_EQ(monitor.nonFinite(), 0u);
  EXPECT_EQ(monitor.throughWall(), 0u);
  EXPECT_EQ(monitor.throughBody(), 0u);
  EXPECT_GE(monitor.minDtRatio(), 0.2);
  EXPECT_LE(monitor.maxEnergyExcess(), allowance);
  EXPECT_GT(track.max_tension, 0.0) << "the cable never went taut";
  EXPECT_LE(rise, c.spring_slack + x_max);
  EXPECT_LE(track.max_tension, k * x_max);
}
