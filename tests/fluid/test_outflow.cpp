// The "outflow" effect (fluid/outflow.hpp): water that goes over the walls of an open
// tank is removed and tallied; everything else that leaves the domain still stops the
// run (a leak, a particle flung near the sound speed).
//
// Checks against numbers from outside the code:
//  - a droplet thrown over a wall flies ballistically: it is removed when it passes the
//    wall's plane, at t = (x_wall - x0) / u, and carries out the energy it was given,
//    m (u^2/2 + g y0), since a free flight conserves it;
//  - mass is conserved exactly (what is left plus what was removed);
//  - a column collapsing in a tank with low walls spills over them: the run finishes,
//    and the energy left plus the energy carried out never exceeds the start's (the
//    flow only dissipates).
#include <gtest/gtest.h>

#include <numeric>
#include <moorsph/fluid/fluid_simulation.hpp>
#include <moorsph/fluid/tank_scene.hpp>

using namespace moorsph::fluid;

namespace {

constexpr double kDx = 0.005;
constexpr double kG = 9.81;

/// 0.2 x 0.1 m open tank, 5 cm of water (its walls' top is at y = 0.1 m).
Scene<2> openTank(bool outflow) {
  TankSpec<2> spec;
  spec.size = Vec<2>(0.2, 0.1);
  spec.water_upper = Vec<2>(0.2, 0.05);
  spec.dx = kDx;
  spec.fluid.effects = {"pressure", "gravity", "walls"};
  if (outflow) spec.fluid.effects.push_back("outflow");
  return buildTankScene<2>(spec);
}

/// Add a 2 x 2 droplet with lower-left particle at `corner`, moving at `u`.
void addDroplet(Scene<2>& scene, const Vec<2>& corner, const Vec<2>& u) {
  const double m = scene.fluid.m[0];
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) scene.fluid.add(corner + kDx * Vec<2>(i, j), u, scene.setup.rho0, m);
}

/// The same boundary less the particles where `drop(r)` holds (e.g. to lower one wall).
template <class Drop>
BoundaryGeometry<2> withoutParticles(const BoundaryGeometry<2>& in, Drop drop) {
  BoundaryGeometry<2> out;
  out.surfaces = in.surfaces;
  const BoundaryParticles<2>& b = in.particles;
  for (std::size_t k = 0; k < b.size(); ++k) {
    if (drop(b.r[k])) continue;
    const std::vector<Vec<2>> normals(b.normals.begin() + b.normal_begin[k], b.normals.begin() + b.normal_begin[k + 1]);
    out.particles.add(b.r[k], normals, b.surface[k]);
  }
  return out;
}

double totalMass(const FluidParticles<2>& f) { return std::accumulate(f.m.begin(), f.m.end(), 0.0); }

}  // namespace

TEST(Outflow, DropletOverTheWallLeavesOnTimeWithItsEnergy) {
  Scene<2> scene = openTank(true);
  const std::size_t tank_particles = scene.fluid.size();
  const Vec<2> corner(0.185, 0.13), u(1.5, 0.5);
  addDroplet(scene, corner, u);
  const double m = scene.fluid.m[0];
  const double mass0 = totalMass(scene.fluid);
  // Energy the droplet carries: kinetic + potential (rho0: no elastic energy).
  double droplet_energy = 0.0;
  for (std::size_t i = tank_particles; i < scene.fluid.size(); ++i)
    droplet_energy += m * (0.5 * u.squaredNorm() + kG * scene.fluid.r[i][1]);

  FluidSimulation<2> sim(scene.setup, scene.fluid, scene.boundary);
  ASSERT_NE(sim.outflow(), nullptr);
  EXPECT_NEAR(sim.outflow()->wallTop(), 0.1, 1e-12);
  sim.advanceTo(0.03);  // without outflow the droplet would leave the domain at ~0.015 s

  const OutflowTally& t = sim.outflow()->tally();
  EXPECT_EQ(t.particles, 4u);
  EXPECT_EQ(sim.fluid().size(), tank_particles);
  EXPECT_NEAR(t.mass, 4 * m, 1e-15);
  EXPECT_NEAR(totalMass(sim.fluid()) + t.mass, mass0, 1e-12 * mass0);
  // The right column (x0 = 0.19) reaches the wall plane x = 0.2 first: t = 0.01/1.5.
  const double t_cross = (0.2 - (corner[0] + kDx)) / u[0];
  EXPECT_NEAR(t.first_time, t_cross, 2.0 * sim.cflDt());
  EXPECT_NEAR(t.energy, droplet_energy, 1e-3 * droplet_energy);
  std::printf("droplet: removed at t = %.5f s (ballistic %.5f s), energy %.6f J/m (thrown with %.6f J/m)\n",
              t.first_time, t_cross, t.energy, droplet_energy);
}

TEST(Outflow, WithoutTheEffectTheDropletStopsTheRun) {
  Scene<2> scene = openTank(false);
  addDroplet(scene, Vec<2>(0.185, 0.13), Vec<2>(1.5, 0.5));
  FluidSimulation<2> sim(scene.setup, scene.fluid, scene.boundary);
  EXPECT_EQ(sim.outflow(), nullptr);
  try {
    sim.advanceTo(0.03);
    FAIL() << "the droplet left the domain and the run went on";
  } catch (const SimulationError& e) {
    EXPECT_NE(std::string(e.what()).find("left the domain"), std::string::npos) << e.what();
  }
}

TEST(Outflow, ALeakBelowTheWallTopStillStopsTheRun) {
  Scene<2> scene = openTank(true);
  // Behind the right wall, below its top, just outside the domain.
  const Vec<2> behind(scene.setup.domain.upper[0] + 0.002, 0.04);
  scene.fluid.add(behind, Vec<2>(0.5, 0.0), scene.setup.rho0, scene.fluid.m[0]);
  FluidSimulation<2> sim(scene.setup, scene.fluid, scene.boundary);
  EXPECT_THROW(sim.advanceTo(0.01), SimulationError);
  EXPECT_EQ(sim.outflow()->tally().particles, 0u);
}

TEST(Outflow, AParticleFlungNearTheSoundSpeedStillStopsTheRun) {
  Scene<2> scene = openTank(true);
  const double fast = 0.6 * scene.setup.sound_speed;  // above the c_s/2 limit
  addDroplet(scene, Vec<2>(0.185, 0.13), Vec<2>(fast, 0.0));
  FluidSimulation<2> sim(scene.setup, scene.fluid, scene.boundary);
  EXPECT_THROW(sim.advanceTo(0.01), SimulationError);
  EXPECT_EQ(sim.outflow()->tally().particles, 0u);
}

TEST(Outflow, NeedsAStaticWall) {
  Scene<2> scene = openTank(true);
  scene.setup.effects = {"pressure", "gravity", "outflow"};
  EXPECT_THROW(FluidSimulation<2>(scene.setup, scene.fluid, BoundaryGeometry<2>{}), std::invalid_argument);
}

TEST(Outflow, ASurgeSpillsOverALowWallWithMassAndEnergyAccountedFor) {
  // A column 0.1 m wide and 0.2 m high in a 0.3 m tank whose far wall is cut down to
  // 0.06 m: the surge reaches it at about Ritter's 2 sqrt(g H) = 2.8 m/s and spills over.
  constexpr double H = 0.2, wall = 0.06;
  TankSpec<2> spec;
  spec.size = Vec<2>(0.3, H);
  spec.water_upper = Vec<2>(0.1, H);
  spec.dx = kDx;
  spec.fluid.sound_speed = 10.0 * 2.0 * std::sqrt(kG * H);  // 10 x the Ritter front speed
  spec.fluid.effects = {"pressure", "viscosity", "gravity", "walls", "outflow"};
  Scene<2> scene = buildTankScene<2>(spec);
  scene.boundary = withoutParticles(scene.boundary, [&](const Vec<2>& r) { return r[0] > 0.3 - 1e-9 && r[1] > wall; });
  const double mass0 = totalMass(scene.fluid);
  FluidSimulation<2> sim(scene.setup, scene.fluid, scene.boundary);
  EXPECT_NEAR(sim.outflow()->wallTop(), H, 1e-12);  // the left wall still stands 0.2 m high
  const double e0 = sim.calcEnergy().total();
  const double scale = mass0 * kG * H;  // M g H: the column's potential energy scale
  double worst = -1e300, balance = 0.0;
  for (double t = 0.02; t <= 0.8 + 1e-9; t += 0.02) {
    sim.advanceTo(t);
    balance = sim.calcEnergy().total() + sim.outflow()->tally().energy - e0;
    worst = std::max(worst, balance);
  }
  const OutflowTally& tally = sim.outflow()->tally();
  std::printf("spill: %zu of %zu particles over the wall by t = 0.8 s (first at %.3f s), %.3f of the mass; "
              "(E + E_out - E0) / (M g H): largest %.2e, at the end %.2e\n",
              tally.particles, tally.particles + sim.fluid().size(), tally.first_time, tally.mass / mass0,
              worst / scale, balance / scale);
  EXPECT_GT(tally.particles, 20u) << "the surge should spill over the far wall";
  EXPECT_NEAR(totalMass(sim.fluid()) + tally.mass, mass0, 1e-12 * mass0);
  EXPECT_LT(worst, 0.02 * scale);
  EXPECT_LT(balance, 0.0);
}
