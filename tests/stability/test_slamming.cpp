// Stability case 2: a cylinder dropped into water from a height (slamming), 2D.
// A cylinder of radius R = 0.05 m and density ratio 0.5 starts at rest with its
// bottom 0.15 m above still water 0.3 m deep (0.8 m tank, dx = 0.01 m, reference
// method); it hits the surface at sqrt(2 g 0.15) = 1.72 m/s at t = 0.175 s, throws
// up splash sheets, sinks and bobs back. Run to 1.0 s. Asserted (stability_monitor.hpp):
//  - no NaN/Inf; no fluid particle through a wall or inside the cylinder;
//  - dt >= 0.2 dt_cfl;
//  - E(t) - E0 <= E_wall(0) + 0.5% of the water's M g d/2 (coupled ledger: fluid, body;
//    nothing injects work; E_wall(0) is the wall-force energy of the initial lattice,
//    which the ledger omits, stability_monitor.hpp);
//  - body motion bounded: its speed never exceeds the free-fall impact speed by more
//    than 10%, its centre stays above the floor by R and inside the tank.
#include <gtest/gtest.h>

#include "cylinder_scene.hpp"

using namespace moorsph;

TEST(StabilitySlamming, DroppedCylinderStaysBounded) {
  stability::CylinderCase c;
  c.tank = fluid::Vec<2>(0.8, 0.6);
  c.depth = 0.3;
  const double drop = 0.15, g = 9.81;
  c.centre = fluid::Vec<2>(0.4, c.depth + drop + c.radius);
  auto co = stability::buildCylinderCase(c);
  stability::StabilityMonitor<2> monitor(co->fluid(), c.tank, false);
  double water = 0.0;
  for (double m : co->fluid().fluid().m) water += m;
  const double wall_energy = stability::wallForceEnergy(co->fluid());
  const auto track = stability::runCylinderCase(*co, c, monitor, 1.0);
  ASSERT_TRUE(track.error.empty()) << track.error;
  const double impact_speed = std::sqrt(2.0 * g * drop);
  const double allowance = wall_energy + 0.005 * water * g * c.depth / 2.0;
  std::printf("%s\nbody: max speed %.3f m/s (impact %.3f), lowest centre y %.4f m, x range %.4f..%.4f m; "
              "E-E0 max %.4g J, allowance %.4g J\n",
              monitor.summary().c_str(), track.max_speed, impact_speed, track.min_position[1], track.min_position[0],
              track.max_position[0], monitor.maxEnergyExcess(), allowance);
  EXPECT_EQ(monitor.nonFinite(), 0u);
  EXPECT_EQ(monitor.throughWall(), 0u);
  EXPECT_EQ(monitor.throughBody(), 0u);
  EXPECT_GE(monitor.minDtRatio(), 0.2);
  EXPECT_LE(monitor.maxEnergyExcess(), allowance);
  EXPECT_LE(track.max_speed, 1.1 * impact_speed);
  EXPECT_GT(track.min_position[1], c.radius);
  EXPECT_GT(track.min_position[0], c.radius);
  EXPECT_LT(track.max_position[0], c.tank[0] - c.radius);
}
