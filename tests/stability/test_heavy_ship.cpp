// Stability case: the ship at +100% mass in the coarse rogue wave (issue 8 item 3), reduced
// to cases/ship/ship_tiny_heavy.yaml: the METHOD.md 6.5 hull and cables at dx = 4 m in a
// 340 m x 40 m tank with periodic sides, the ship made twice as heavy (104,392 t) while it
// sits at the base ship's equilibrium, released at 1 s into steep regular piston waves
// (H = 8 m, T = 8 s, k d = 2.6, close to the ship's heave period). It sinks about 7 m
// (0.137 m per 1000 t) while the crests run along it: a step load on a large, lightly damped
// body, a freeboard cut from 11 m to 4 m, and waves at resonance with its heave.
//
// Outside numbers: the heavy ship's still-water equilibrium from the mesh's exact
// hydrostatics and the spring law (test_ship_equilibrium.hpp), and the step-load bound of
// a linear oscillator: released from rest a distance s above its new equilibrium, a body
// cannot go further than s below it (damping only shortens the swing).
//
// Asserted (stability_monitor.hpp's contract):
//  - no NaN/Inf; no fluid particle below the floor, past the far wall, behind the piston
//    plate, or inside the hull (checked every 10 steps, io::meshContains);
//  - dt >= 0.2 dt_cfl; the flow stays below 1.5 c_s/10;
//  - E(t) - E0 <= W_piston(t) + E_wall(0) + 5% of max W_piston (E: fluid kinetic, potential
//    and elastic, ship kinetic and potential, cable elastic and dissipated: the coupled
//    ledger; W_piston: the plate's work on the water, as in the breaking-wave case);
//  - body motion bounded: the lowest heave no deeper than the new equilibrium less the
//    step-load swing s less the wave amplitude H/2 less the SPH draught tolerance of the
//    tiny ship test (0.88 m); the ship stays upright (roll, pitch < 10 deg) and on its
//    cables (surge within their span's give, 10 m).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include <moorsph/fluid/piston.hpp>
#include <moorsph/io/mesh_sampling.hpp>
#include <moorsph/io/scene_builder.hpp>
#include <moorsph/io/scene_loader.hpp>
#include "../io/ship_scene_hull.hpp"
#include "run/scene_bodies.hpp"
#include "stability_monitor.hpp"

using namespace moorsph;

namespace {

/// Fluid particles inside the hull now (body-frame test after a bounding-box cut).
int particlesInsideHull(const fluid::FluidParticles<3>& f, const io::TriangleMesh& hull, const Eigen::Vector3d& lo,
                        const Eigen::Vector3d& hi, const bodies::BodyKinematics& k) {
  int inside = 0;
  for (const auto& r : f.r) {
    const Eigen::Vector3d p = k.orientation.inverse() * (r - k.position);
    if ((p.array() < lo.array()).any() || (p.array() > hi.array()).any()) continue;
    inside += io::meshContains(hull, p);
  }
  return inside;
}

}  // namespace

TEST(StabilityHeavyShip, HeavierShipSinksIntoSteepWavesWithoutBlowUp) {
  const char* root = std::getenv("MOORSPH_SOURCE_DIR");
  if (!root) GTEST_SKIP() << "MOORSPH_SOURCE_DIR not set";
  const io::SceneConfig config = io::loadSceneFile(std::string(root) + "/cases/ship/ship_tiny_heavy.yaml");
  const auto built = io::buildScene<3>(config);
  auto co = app::makeCoSimulation<3>(config, built, built.scene.fluid, {});
  fluid::FluidSimulation<3>& sim = co->updFluid();
  const fluid::Piston<3>* work = sim.findEffect<fluid::Piston<3>>();  // sums the plate's work on the water
  ASSERT_NE(work, nullptr);

  // The heavy ship's equilibrium and the step it is released from.
  const test::MooredHull hull = test::mooredHull(config);
  const test::HullPose start = test::scenePose(config);
  const test::HullPose heavy = test::solveHullEquilibrium(hull, start);
  // Heave is measured at the hull's centre of flotation (x = 143.79 m aft of the bow keel),
  // which the trim does not move.
  const Eigen::Vector3d lcf(143.79, 0.0, 0.0);
  const double start_y = start.toGround(lcf, hull.z).y(), heavy_y = heavy.toGround(lcf, hull.z).y();
  const double step = start_y - heavy_y, wave_amplitude = 0.5 * config.piston.wave_height;
  const double lowest_allowed = heavy_y - step - wave_amplitude - 0.88;
  const Eigen::Vector3d box_lo = hull.mesh.lower(), box_hi = hull.mesh.upper();

  const double tank_length = 340.0, width = config.domain.upper[2];
  stability::StabilityMonitor<3> monitor(sim, fluid::Vec<3>(tank_length, 0.0, width), false);
  monitor.setLowerCorner(fluid::Vec<3>(config.domain.lower[0], 0.0, 0.0));
  const auto& walls = *sim.walls();
  const std::size_t plate = built.piston_surface;
  monitor.addBody("piston plate", [&walls, plate](const fluid::Vec<3>& r) {
    return r[0] - walls.surfaceMotion(plate).position[0];
  });
  const double wall_energy = stability::wallForceEnergy(sim);
  monitor.sample(co->calcEnergy().total(), 0.0);
  int inside_hull = 0;
  double max_work = 0.0, lowest = start_y, highest = start_y, max_tilt = 0.0, max_surge = 0.0;
  ASSERT_NO_THROW({
    while (sim.time() < config.end_time) {
      co->step();
      monitor.sample(co->calcEnergy().total(), work->work());
      max_work = std::max(max_work, work->work());
      const auto k = co->bodies().kinematics(0);
      const double y = (k.position + k.orientation * lcf).y();
      lowest = std::min(lowest, y);
      highest = std::max(highest, y);
      max_surge = std::max(max_surge, std::abs(k.position.x() - start.x));
      const Eigen::Vector3d rpy = app::rollPitchYaw(k.orientation);
      max_tilt = std::max({max_tilt, std::abs(rpy[0]), std::abs(rpy[1] - start.theta)});
      if (sim.stepCount() % 10 == 0) inside_hull = std::max(inside_hull, particlesInsideHull(sim.fluid(), hull.mesh, box_lo, box_hi, k));
    }
  });
  std::printf("%s\nheavy ship: equilibrium %.2f m below the base pose at the LCF; heave there from %.2f to %.2f m (allowed down to %.2f); "
              "max tilt %.2f deg, max surge %.2f m; most particles inside the hull %d; piston work %.4g J (max %.4g), "
              "E-E0-W max %.4g J (E_wall %.4g J)\n",
              monitor.summary().c_str(), step, lowest - start_y, highest - start_y, lowest_allowed - start_y,
              max_tilt * 180.0 / M_PI, max_surge, inside_hull, work->work(), max_work, monitor.maxEnergyExcess(),
              wall_energy);
  EXPECT_EQ(monitor.nonFinite(), 0u);
  EXPECT_EQ(monitor.throughWall(), 0u);
  EXPECT_EQ(monitor.throughBody(), 0u) << "fluid behind the piston plate";
  EXPECT_EQ(inside_hull, 0) << "fluid particles inside the hull";
  EXPECT_GE(monitor.minDtRatio(), 0.2);
  EXPECT_GT(work->work(), 0.0);
  EXPECT_LE(monitor.maxEnergyExcess(), wall_energy + 0.05 * max_work);
  EXPECT_LE(monitor.maxSpeed(), 0.15 * sim.setup().sound_speed);
  // The heavier ship sinks (it is 7 m out of balance) but no further than the step-load swing.
  EXPECT_GT(step, 5.0);
  EXPECT_LT(lowest, heavy_y + 0.88);
  EXPECT_GT(lowest, lowest_allowed);
  EXPECT_LT(highest, start_y + wave_amplitude + 0.88);
  EXPECT_LT(max_tilt, 10.0 * M_PI / 180.0);
  EXPECT_LT(max_surge, 10.0);
}
