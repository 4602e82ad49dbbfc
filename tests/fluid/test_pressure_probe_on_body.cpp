// A pressure probe on a movable surface moves with it. A held box in still water
// carries a probe on its top face; after the box is turned by 180 degrees about its
// centre (its particles land where the bottom face's were, so the water is not
// disturbed) the probe sits on the underside and must read the hydrostatic pressure
// there, rho0 g (0.04 m) = 392 Pa more than before. Its point and normal follow the
// motion exactly.
#include <gtest/gtest.h>

#include <cmath>
#include <moorsph/fluid/pressure_probe.hpp>
#include <moorsph/fluid/tank_scene.hpp>

using namespace moorsph::fluid;

TEST(PressureProbeOnBody, FollowsTheSurfaceAndReadsTheNewDepth) {
  const double dx = 0.01, level = 0.3;
  TankSpec<2> spec;
  spec.size = Vec<2>(0.4, 0.4);
  spec.water_upper = Vec<2>(0.4, level);
  spec.dx = dx;
  spec.fluid.mu = 0.05;  // damps the start-up settling
  spec.fluid.effects = {"pressure", "viscosity", "xsph", "density_diffusion", "gravity", "walls"};
  auto scene = buildTankScene<2>(spec);
  const Vec<2> lower(0.15, 0.13), upper(0.25, 0.17), centre = 0.5 * (lower + upper);
  FluidParticles<2> water;
  for (std::size_t i = 0; i < scene.fluid.size(); ++i) {
    const Vec<2>& r = scene.fluid.r[i];
    const bool inside = (r.array() > lower.array() - 0.5 * dx).all() && (r.array() < upper.array() + 0.5 * dx).all();
    if (!inside) water.add(r, scene.fluid.v[i], scene.fluid.rho[i], scene.fluid.m[i]);
  }
  const auto box = scene.boundary.addSurface(sampleBoxSurface<2>(lower, upper, dx, allFaces<2>(), NormalSide::Outward),
                                             SurfaceInfo{"box", true, true, Eigen::Vector3d(centre[0], centre[1], 0.0)});
  FluidSimulation<2> sim(scene.setup, water, scene.boundary);
  PressureProbeSpec<2> p;
  p.surface = box;
  p.point = Vec<2>(centre[0], upper[1]);
  p.normal = Vec<2>(0.0, 1.0);
  p.radius = 1.5 * dx;
  p.boundary_spacing = dx;
  p.interpolation_offset = 1.5 * dx;
  const PressureProbe<2> probe(p, *sim.walls());

  auto average = [&](double until) {
    double reaction = 0.0, interpolated = 0.0;
    int n = 0;
    const double from = sim.time();
    while (sim.time() < until) {
      sim.step();
      if (sim.time() > from + 0.5 * (until - from)) {
        reaction += probe.readReaction(sim);
        interpolated += probe.readInterpolated(sim);
        ++n;
      }
    }
    return std::make_pair(reaction / n, interpolated / n);
  };
  const double rho_g = 1000.0 * 9.81;
  const auto [top_reaction, top_interp] = average(0.6);

  RigidMotion<2> turned = sim.walls()->surfaceMotion(box);
  turned.rotation << -1.0, 0.0, 0.0, -1.0;  // 180 degrees about the box centre
  sim.updWalls()->setSurfaceMotion(box, turned);
  const Vec<2> point = probe.currentPoint(*sim.walls()), normal = probe.currentNormal(*sim.walls());
  EXPECT_LT((point - Vec<2>(centre[0], lower[1])).norm(), 1e-12);
  EXPECT_LT((normal - Vec<2>(0.0, -1.0)).norm(), 1e-12);
  sim.requestNeighbourRebuild();
  const auto [bottom_reaction, bottom_interp] = average(0.8);

  const double expected_jump = rho_g * (upper[1] - lower[1]);
  std::printf("top: reaction %.1f Pa, interpolated %.1f Pa (hydrostatic %.1f); turned: reaction %.1f, interpolated %.1f "
              "(hydrostatic %.1f); jump %.1f / %.1f Pa (expected %.1f)\n",
              top_reaction, top_interp, rho_g * (level - upper[1]), bottom_reaction, bottom_interp,
              rho_g * (level - lower[1]), bottom_reaction - top_reaction, bottom_interp - top_interp, expected_jump);
  // The reaction estimate reads hydrostatics within 5% on both faces (measured 2.7% and
  // 1.9% low); the interpolated one reads 15-17% high beside a wall at this resolution
  // (the wall force compresses the first layer), so only its jump is checked.
  EXPECT_NEAR(top_reaction, rho_g * (level - upper[1]), 0.05 * rho_g * (level - upper[1]));
  EXPECT_NEAR(bottom_reaction, rho_g * (level - lower[1]), 0.05 * rho_g * (level - lower[1]));
  EXPECT_NEAR(bottom_reaction - top_reaction, expected_jump, 0.1 * expected_jump);
  EXPECT_NEAR(bottom_interp - top_interp, expected_jump, 0.25 * expected_jump);
}
