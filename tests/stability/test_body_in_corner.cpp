// Stability case 6: a body touching the tank floor and a wall corner, 2D. A heavy
// cylinder (R = 0.05 m, density ratio 2) sits in the bottom-left corner of a 0.6 m
// tank of water 0.4 m deep, half a spacing from the floor and from the left wall
// (dx = 0.01 m), held 0.2 s while the fluid settles, then released and run 0.6 s.
// Its weight less buoyancy, (2 - 1) rho g pi R^2 = 77 N/m, presses it into the corner.
// Asserted: the stability contract (stability_monitor.hpp; no fluid particle inside
// the cylinder or behind a wall, dt >= 0.2 dt_cfl, E - E0 <= E_wall(0) + 0.5% of the
// water's M g d/2), and the body stays in the corner: its surface never crosses the
// floor or the wall (centre >= R - dx/2 from each) and it moves less than 0.5 dx.
#include <gtest/gtest.h>

#include "cylinder_scene.hpp"

using namespace moorsph;

TEST(StabilityBodyInCorner, HeavyCylinderStaysInTheCorner) {
  stability::CylinderCase c;
  c.tank = fluid::Vec<2>(0.6, 0.6);
  c.depth = 0.4;
  c.density_ratio = 2.0;
  c.centre = fluid::Vec<2>(c.radius + 0.5 * c.dx, c.radius + 0.5 * c.dx);
  c.release_time = 0.2;
  auto co = stability::buildCylinderCase(c);
  stability::StabilityMonitor<2> monitor(co->fluid(), c.tank, false);
  double water = 0.0;
  for (double m : co->fluid().fluid().m) water += m;
  const double wall_energy = stability::wallForceEnergy(co->fluid());
  const auto track = stability::runCylinderCase(*co, c, monitor, c.release_time + 0.6);
  const double g = 9.81;
  const double allowance = wall_energy + 0.005 * water * g * c.depth / 2.0;
  std::printf("%s\nbody: lowest centre (%.5f, %.5f) m (start %.5f), highest (%.5f, %.5f), max speed %.4f m/s; "
              "E-E0 max %.4g J (allowance %.4g)\n",
              monitor.summary().c_str(), track.min_position[0], track.min_position[1], c.centre[1],
              track.max_position[0], track.max_position[1], track.max_speed, monitor.maxEnergyExcess(), allowance);
  ASSERT_TRUE(track.error.empty()) << track.error;
  EXPECT_EQ(monitor.nonFinite(), 0u);
  EXPECT_EQ(monitor.throughWall(), 0u);
  EXPECT_EQ(monitor.throughBody(), 0u);
  EXPECT_GE(monitor.minDtRatio(), 0.2);
  EXPECT_LE(monitor.maxEnergyExcess(), allowance);
  EXPECT_GE(track.min_position[0], c.radius - 0.5 * c.dx);
  EXPECT_GE(track.min_position[1], c.radius - 0.5 * c.dx);
  EXPECT_LT((track.max_position - track.min_position).norm(), 0.5 * c.dx);
}
