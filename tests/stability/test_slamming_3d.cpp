// Stability case 2, 3D (label slow): a sphere dropped into water from a height. A
// sphere of radius R = 0.05 m and density ratio 0.5 starts at rest with its bottom
// 0.1 m above still water 0.2 m deep (0.3 m x 0.3 m open tank, dx = 0.01 m, 18000
// particles, reference method); it hits the surface at sqrt(2 g 0.1) = 1.40 m/s at
// t = 0.143 s. Run to 0.5 s. Asserted as in the 2D case (test_slamming.cpp): the
// stability contract (stability_monitor.hpp; no particle inside the sphere or out of
// the tank, dt >= 0.2 dt_cfl, E - E0 <= E_wall(0) + 0.5% of the water's M g d/2), body
// speed <= 1.1 x the impact speed, centre above the floor by R and inside the tank.
#include <gtest/gtest.h>

#include <cmath>
#include <moorsph/coupling/co_simulation.hpp>
#include <moorsph/fluid/shape_sampling.hpp>
#include <moorsph/fluid/tank_scene.hpp>

#include "stability_monitor.hpp"

using namespace moorsph;

TEST(StabilitySlamming3D, DroppedSphereStaysBounded) {
  const double depth = 0.2, dx = 0.01, radius = 0.05, drop = 0.1, ratio = 0.5, g = 9.81;
  fluid::TankSpec<3> spec;
  spec.size = fluid::Vec<3>(0.3, 0.4, 0.3);
  spec.water_upper = fluid::Vec<3>(0.3, depth, 0.3);
  spec.dx = dx;
  spec.fluid.sound_speed = 10.0 * std::sqrt(2.0 * g * depth);
  spec.fluid.mu = 0.01;
  spec.fluid.effects = {"pressure", "viscosity", "xsph", "gravity", "walls"};
  auto scene = fluid::buildTankScene<3>(spec);
  const fluid::Vec<3> centre(0.15, depth + drop + radius, 0.15);
  const Eigen::Vector3d origin = centre;
  scene.boundary.addSurface(fluid::sampleSphere<3>(centre, radius, dx), fluid::SurfaceInfo{"sphere", true, true, origin, true});
  auto system = std::make_unique<bodies::MultibodySystem>();
  bodies::RigidBodySpec body;
  body.name = "sphere";
  body.mass = ratio * 1000.0 * 4.0 / 3.0 * std::acos(-1.0) * std::pow(radius, 3);
  body.mobilizer = bodies::Mobilizer::Free;
  for (int k = 3; k < 6; ++k) body.fixedDofs[k] = true;
  body.inertiaAboutCom = Eigen::Matrix3d::Identity() * 0.4 * body.mass * radius * radius;
  body.initial.position = origin;
  system->addBody(body);
  system->initialize();
  coupling::CoSimulation<3> co(std::make_unique<fluid::FluidSimulation<3>>(scene.setup, scene.fluid, scene.boundary),
                               std::move(system), {{0, 1}}, {0.0, 0.0});
  stability::StabilityMonitor<3> monitor(co.fluid(), spec.size, false);
  monitor.addBody("sphere", [&co, radius](const fluid::Vec<3>& p) {
    return (p - co.bodies().kinematics(0).position).norm() - radius;
  });
  double water = 0.0;
  for (double m : co.fluid().fluid().m) water += m;
  const double wall_energy = stability::wallForceEnergy(co.fluid());
  monitor.sample(co.calcEnergy().total(), 0.0);
  Eigen::Vector3d lo = origin, hi = origin;
  double max_speed = 0.0;
  ASSERT_NO_THROW({
    while (co.time() < 0.5) {
      co.step();
      monitor.sample(co.calcEnergy().total(), 0.0);
      const auto k = co.bodies().kinematics(0);
      lo = lo.cwiseMin(k.position);
      hi = hi.cwiseMax(k.position);
      max_speed = std::max(max_speed, k.velocity.norm());
    }
  });
  const double impact_speed = std::sqrt(2.0 * g * drop);
  const double allowance = wall_energy + 0.005 * water * g * depth / 2.0;
  std::printf("%s\nbody: max speed %.3f m/s (impact %.3f), lowest centre y %.4f m, sideways range %.4f m; "
              "E-E0 max %.4g J, allowance %.4g J (E_wall %.4g)\n",
              monitor.summary().c_str(), max_speed, impact_speed, lo[1], (hi - lo).cwiseAbs()[0] + (hi - lo)[2],
              monitor.maxEnergyExcess(), allowance, wall_energy);
  EXPECT_EQ(monitor.nonFinite(), 0u);
  EXPECT_EQ(monitor.throughWall(), 0u);
  EXPECT_EQ(monitor.throughBody(), 0u);
  EXPECT_GE(monitor.minDtRatio(), 0.2);
  EXPECT_LE(monitor.maxEnergyExcess(), allowance);
  EXPECT_LE(max_speed, 1.1 * impact_speed);
  EXPECT_GT(lo[1], radius);
  EXPECT_LT((hi - lo)[0] + (hi - lo)[2], radius);
}
