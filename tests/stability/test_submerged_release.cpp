// Stability case 4: a light body (density ratio 0.2) and a heavy one (2.0) released
// from rest under water, 2D (the geometry of cases/floating_box/submerged_release:
// cylinder R = 0.05 m at mid-depth of water 0.5 m deep, 0.6 m tank, dx = 0.01 m,
// held 0.2 s while the fluid settles). The light one is the explicit-coupling hard
// case: its added mass (C_a = 1, potential flow) is five times its own.
// Potential flow gives the acceleration from rest a0 = (1 - r)/(r + C_a) g; viscous
// drag and the free surface only slow the body, so its speed after release must stay
// below a0 t (+10%: the SPH added mass is not exact). Run 0.25 s after release. Also
// asserted: the stability contract (stability_monitor.hpp), energy allowance E_wall(0)
// + 0.5% of the water's M g d/2.
#include <gtest/gtest.h>

#include "cylinder_scene.hpp"

using namespace moorsph;

namespace {

void releaseAndCheck(double ratio) {
  stability::CylinderCase c;
  c.tank = fluid::Vec<2>(0.6, 0.6);
  c.depth = 0.5;
  c.centre = fluid::Vec<2>(0.3, 0.3);
  c.density_ratio = ratio;
  c.release_time = 0.2;
  const double free_time = 0.25, g = 9.81;
  auto co = stability::buildCylinderCase(c);
  stability::StabilityMonitor<2> monitor(co->fluid(), c.tank, false);
  double water = 0.0;
  for (double m : co->fluid().fluid().m) water += m;
  const double wall_energy = stability::wallForceEnergy(co->fluid());
  const auto track = stability::runCylinderCase(*co, c, monitor, c.release_time + free_time);
  ASSERT_TRUE(track.error.empty()) << track.error;
  const double a0 = std::abs(1.0 - ratio) / (ratio + 1.0) * g;
  const double allowance = wall_energy + 0.005 * water * g * c.depth / 2.0;
  std::printf("ratio %.1f: %s\nmax speed %.3f m/s (potential-flow bound a0 t = %.3f), y range %.4f..%.4f m, "
              "x range %.4f..%.4f m; E-E0 max %.4g J (allowance %.4g)\n",
              ratio, monitor.summary().c_str(), track.max_speed, a0 * free_time, track.min_position[1],
              track.max_position[1], track.min_position[0], track.max_position[0], monitor.maxEnergyExcess(),
              allowance);
  EXPECT_EQ(monitor.nonFinite(), 0u);
  EXPECT_EQ(monitor.throughWall(), 0u);
  EXPECT_EQ(monitor.throughBody(), 0u);
  EXPECT_GE(monitor.minDtRatio(), 0.2);
  EXPECT_LE(monitor.maxEnergyExcess(), allowance);
  EXPECT_LE(track.max_speed, 1.1 * a0 * free_time);
  // It moves the right way, and sideways by less than a radius (symmetric flow).
  if (ratio < 1.0) EXPECT_GT(track.max_position[1], c.centre[1] + 0.05);
  else EXPECT_LT(track.min_position[1], c.centre[1] - 0.05);
  EXPECT_LT(track.max_position[0] - track.min_position[0], c.radius);
}

}  // namespace

TEST(StabilitySubmergedRelease, LightBodyRatio02) { releaseAndCheck(0.2); }
TEST(StabilitySubmergedRelease, HeavyBodyRatio2) { releaseAndCheck(2.0); }
