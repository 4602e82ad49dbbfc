// Runtime guard for bodies (issue 8, item 4): a coupled body that leaves the fluid
// domain stops the co-simulation with a SimulationError naming the body, the time
// and the likely cause.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <moorsph/coupling/co_simulation.hpp>
#include <moorsph/fluid/box_geometry.hpp>
#include <moorsph/fluid/tank_scene.hpp>

using namespace moorsph;

namespace {

/// A 0.4 m x 0.4 m open tank with 0.1 m of water and a 0.06 m square body in the air
/// near the right wall, thrown sideways at `speed`. Without body-wall contact it flies
/// through the wall and out of the domain.
coupling::CoSimulation<2> thrownBody(double speed, bool contact) {
  fluid::TankSpec<2> spec;
  spec.size = fluid::Vec<2>(0.4, 0.4);
  spec.water_upper = fluid::Vec<2>(0.4, 0.1);
  spec.dx = 0.02;
  spec.fluid.sound_speed = 20.0;
  auto scene = fluid::buildTankScene<2>(spec);
  const fluid::Vec<2> centre(0.33, 0.3), half(0.03, 0.03);
  scene.boundary.addSurface(fluid::sampleBoxSurface<2>(centre - half, centre + half, spec.dx, fluid::allFaces<2>(),
                                                       fluid::NormalSide::Outward),
                            fluid::SurfaceInfo{"crate", true, true, Eigen::Vector3d(centre[0], centre[1], 0.0), true});
  auto system = std::make_unique<bodies::MultibodySystem>();
  bodies::RigidBodySpec body;
  body.name = "crate";
  body.mass = 1.8;  // density ratio 0.5 per metre of span
  body.mobilizer = bodies::Mobilizer::Planar;
  body.inertiaAboutCom = Eigen::Matrix3d::Identity() * body.mass * 0.06 * 0.06 / 6.0;
  body.initial.position = Eigen::Vector3d(centre[0], centre[1], 0.0);
  body.initial.velocity = Eigen::Vector3d(speed, 0.0, 0.0);
  system->addBody(body);
  system->initialize();
  return coupling::CoSimulation<2>(std::make_unique<fluid::FluidSimulation<2>>(scene.setup, scene.fluid, scene.boundary),
                                   std::move(system), {{0, 1}}, {0.0, 0.0, contact});
}

std::string runUntilError(coupling::CoSimulation<2>& co, double end) {
  try {
    co.advanceTo(end);
  } catch (const fluid::SimulationError& e) {
    return e.what();
  }
  return "";
}

bool has(const std::string& message, const std::string& part) { return message.find(part) != std::string::npos; }

}  // namespace

// At 1 m/s (c_s/20) with contact off: the cause named is the missing contact.
TEST(BodyGuard, BodyThroughWallIsNamed) {
  auto co = thrownBody(1.0, false);
  const std::string msg = runUntilError(co, 0.3);
  std::printf("%s\n", msg.c_str());
  EXPECT_TRUE(has(msg, "a coupled body left the domain")) << msg;
  EXPECT_TRUE(has(msg, "body 'crate' (body 0)")) << msg;
  EXPECT_TRUE(has(msg, "at t = ")) << msg;
  EXPECT_TRUE(has(msg, "contact is off")) << msg;
  // The right face starts at x = 0.36 m and moves at 1 m/s; the run stops at the first
  // step after it crosses the domain's edge (the tank's wall plus the domain margin).
  const double edge = co.fluid().setup().domain.upper[0];
  EXPECT_NEAR(co.time(), edge - 0.36, 2.0 * co.fluid().cflDt());
}

// At 5 m/s (c_s/4) the cause named is the speed.
TEST(BodyGuard, FastBodyBlamesSpeed) {
  auto co = thrownBody(5.0, false);
  const std::string msg = runUntilError(co, 0.1);
  EXPECT_TRUE(has(msg, "a coupled body left the domain")) << msg;
  EXPECT_TRUE(has(msg, "faster than c_s/10")) << msg;
}

// With body-wall contact (the default) the same body thrown at 1 m/s bounces off the
// wall: it stays in the domain, its surface does not cross the wall by more than the
// wall law's offset, and it comes back at a similar speed (the contact law is
// conservative; nothing else acts in the air but gravity, which is vertical). The
// face reaches the wall at 0.04 s; by 0.12 s the body has fallen 0.07 m, still in air.
TEST(BodyGuard, WallContactBouncesTheBodyBack) {
  auto co = thrownBody(1.0, true);
  double max_x = 0.0;
  std::string msg;
  try {
    while (co.time() < 0.12) {
      co.step();
      max_x = std::max(max_x, co.bodies().kinematics(0).position[0]);
    }
  } catch (const fluid::SimulationError& e) {
    msg = e.what();
  }
  EXPECT_EQ(msg, "");
  const double vx = co.bodies().kinematics(0).velocity[0];
  std::printf("closest approach: right face at x = %.4f m (wall at 0.4); velocity after %.3f m/s\n", max_x + 0.03, vx);
  EXPECT_LT(max_x + 0.03, 0.4);
  EXPECT_LT(vx, -0.8);
  EXPECT_GT(vx, -1.05);
}
