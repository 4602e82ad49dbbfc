// A run restored from a copy of its state taken right after a requested neighbour
// rebuild continues bit-identically (same thread count): the basis of checkpoints.
#include <gtest/gtest.h>

#include <moorsph/cases/dam_break.hpp>
#include <moorsph/fluid/fluid_simulation.hpp>

using namespace moorsph;

TEST(Restart, ContinuesBitIdenticallyAfterRequestedRebuild) {
  cases::DamBreakSpec<2> spec;
  spec.dx = 0.01;
  spec.effects.push_back("density_diffusion");
  auto scene = cases::buildDamBreak<2>(spec);
  fluid::FluidSimulation<2> straight(scene.setup, scene.fluid, scene.boundary);
  for (int n = 0; n < 300; ++n) straight.step();
  straight.requestNeighbourRebuild();
  straight.step();

  // "Checkpoint": the state arrays in their current (sorted) order and the clock.
  fluid::FluidParticles<2> saved;
  const auto& f = straight.fluid();
  saved.r = f.r;
  saved.v = f.v;
  saved.rho = f.rho;
  saved.m = f.m;
  saved.id = f.id;
  fluid::FluidSimulation<2> restarted(scene.setup, saved, scene.boundary);
  restarted.restoreClock(straight.time(), straight.stepCount(), straight.lastDt());

  for (int n = 0; n < 200; ++n) {
    straight.step();
    restarted.step();
  }
  ASSERT_EQ(straight.time(), restarted.time());
  ASSERT_EQ(straight.stepCount(), restarted.stepCount());
  const auto& a = straight.fluid();
  const auto& b = restarted.fluid();
  ASSERT_EQ(a.size(), b.size());
  std::size_t differing = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a.id[i] != b.id[i] || a.r[i] != b.r[i] || a.v[i] != b.v[i] || a.rho[i] != b.rho[i]) ++differing;
  EXPECT_EQ(differing, 0u);
  // The flow has moved on since the checkpoint, so the comparison is not trivial.
  double moved = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) moved = std::max(moved, a.v[i].norm());
  EXPECT_GT(moved, 0.5);
}
