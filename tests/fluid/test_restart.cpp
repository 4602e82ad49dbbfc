// A run restored from a copy of its state continues bit-identically (same thread count):
// the basis of checkpoints. Two ways to get the same neighbour lists on restart: the run
// rebuilds right before the copy (the restart builds from the same sorted positions), or
// the copy carries the positions of the run's last build and the restart rebuilds its
// lists from those (NeighbourSearch::restore), which costs the run nothing.
#include <gtest/gtest.h>

#include <algorithm>

#include <moorsph/cases/dam_break.hpp>
#include <moorsph/fluid/fluid_simulation.hpp>

using namespace moorsph;

namespace {

fluid::Scene<2> scene() {
  cases::DamBreakSpec<2> spec;
  spec.dx = 0.01;
  spec.effects.push_back("density_diffusion");
  return cases::buildDamBreak<2>(spec);
}

/// "Checkpoint": the state arrays in their current (sorted) order.
fluid::FluidParticles<2> saveState(const fluid::FluidSimulation<2>& sim) {
  fluid::FluidParticles<2> saved;
  const auto& f = sim.fluid();
  saved.r = f.r;
  saved.v = f.v;
  saved.rho = f.rho;
  saved.m = f.m;
  saved.id = f.id;
  return saved;
}

/// Steps both 200 times; returns how many particles then differ in any bit.
std::size_t differingAfter(fluid::FluidSimulation<2>& straight, fluid::FluidSimulation<2>& restarted) {
  for (int n = 0; n < 200; ++n) {
    straight.step();
    restarted.step();
  }
  EXPECT_EQ(straight.time(), restarted.time());
  EXPECT_EQ(straight.stepCount(), restarted.stepCount());
  const auto& a = straight.fluid();
  const auto& b = restarted.fluid();
  EXPECT_EQ(a.size(), b.size());
  std::size_t differing = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a.id[i] != b.id[i] || a.r[i] != b.r[i] || a.v[i] != b.v[i] || a.rho[i] != b.rho[i]) ++differing;
  // The flow has moved on since the checkpoint, so the comparison is not trivial.
  double moved = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) moved = std::max(moved, a.v[i].norm());
  EXPECT_GT(moved, 0.5);
  return differing;
}

}  // namespace

TEST(Restart, ContinuesBitIdenticallyAfterRequestedRebuild) {
  const auto s = scene();
  fluid::FluidSimulation<2> straight(s.setup, s.fluid, s.boundary);
  for (int n = 0; n < 300; ++n) straight.step();
  straight.requestNeighbourRebuild();
  straight.step();
  fluid::FluidSimulation<2> restarted(s.setup, saveState(straight), s.boundary);
  restarted.restoreClock(straight.time(), straight.stepCount(), straight.lastDt());
  EXPECT_EQ(differingAfter(straight, restarted), 0u);
}

TEST(Restart, ContinuesBitIdenticallyFromTheSavedBuildPositions) {
  const auto s = scene();
  fluid::FluidSimulation<2> straight(s.setup, s.fluid, s.boundary);
  for (int n = 0; n < 300; ++n) straight.step();
  // Step on until the last build is some steps old, so that positions have moved since.
  std::size_t builds = straight.neighbours().rebuildCount();
  for (int since = 0; since < 5;) {
    straight.step();
    since = straight.neighbours().rebuildCount() == builds ? since + 1 : 0;
    builds = straight.neighbours().rebuildCount();
  }
  const auto at_build = straight.neighbours().fluidAtBuild();
  const auto boundary_at_build = straight.neighbours().boundaryAtBuild();
  ASSERT_NE(at_build, straight.fluid().r);

  fluid::FluidSimulation<2> restarted(s.setup, saveState(straight), s.boundary);
  restarted.restoreClock(straight.time(), straight.stepCount(), straight.lastDt());
  restarted.restoreNeighbourLists(at_build, boundary_at_build);
  // Without the saved positions the restart builds other lists (sorted by the positions
  // now) and drifts from the straight run in the last bits: what the restore prevents.
  fluid::FluidSimulation<2> fresh(s.setup, saveState(straight), s.boundary);
  fresh.restoreClock(straight.time(), straight.stepCount(), straight.lastDt());
  fluid::FluidSimulation<2> restored_again(s.setup, saveState(straight), s.boundary);
  restored_again.restoreClock(straight.time(), straight.stepCount(), straight.lastDt());
  restored_again.restoreNeighbourLists(at_build, boundary_at_build);

  EXPECT_EQ(differingAfter(straight, restarted), 0u);
  EXPECT_GT(differingAfter(restored_again, fresh), 0u);
}

TEST(Restart, RestoreRefusesBuildPositionsOfAnotherOrder) {
  const auto s = scene();
  fluid::FluidSimulation<2> sim(s.setup, s.fluid, s.boundary);
  for (int n = 0; n < 50; ++n) sim.step();
  auto at_build = sim.neighbours().fluidAtBuild();
  std::reverse(at_build.begin(), at_build.end());  // no longer in cell order
  fluid::FluidSimulation<2> restarted(s.setup, saveState(sim), s.boundary);
  EXPECT_THROW(restarted.restoreNeighbourLists(at_build, sim.neighbours().boundaryAtBuild()), std::invalid_argument);
  at_build.pop_back();
  EXPECT_THROW(restarted.restoreNeighbourLists(at_build, sim.neighbours().boundaryAtBuild()), std::invalid_argument);
}
