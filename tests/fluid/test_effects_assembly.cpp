// Effects are built from the list a scene names and nothing else (DESIGN.md §5):
// an effect not named is never constructed; unknown or inconsistent lists are
// rejected before anything runs.
#include <gtest/gtest.h>

#include <moorsph/fluid/fluid_simulation.hpp>
#include <moorsph/fluid/gravity.hpp>
#include <moorsph/fluid/pair_terms.hpp>
#include <moorsph/fluid/tank_scene.hpp>

using namespace moorsph::fluid;

namespace {
Scene<2> smallTank(const std::vector<std::string>& effects) {
  TankSpec<2> spec;
  spec.size = Vec<2>(0.1, 0.1);
  spec.water_upper = Vec<2>(0.1, 0.05);
  spec.dx = 0.005;
  spec.fluid.effects = effects;
  return buildTankScene<2>(spec);
}
}  // namespace

TEST(EffectsAssembly, EffectNotNamedIsNeverConstructed) {
  const long viscosity = ViscosityTerm::constructed(), xsph = XsphTerm::constructed();
  const long diffusion = DensityDiffusionTerm<2>::constructed(), gravity = Gravity<2>::constructed();
  auto scene = smallTank({"pressure", "walls"});
  FluidSimulation<2> sim(scene.setup, scene.fluid, scene.boundary);
  for (int n = 0; n < 5; ++n) sim.step();
  EXPECT_EQ(ViscosityTerm::constructed(), viscosity);
  EXPECT_EQ(XsphTerm::constructed(), xsph);
  EXPECT_EQ(DensityDiffusionTerm<2>::constructed(), diffusion);
  EXPECT_EQ(Gravity<2>::constructed(), gravity);
  EXPECT_EQ(sim.effectNames(), (std::vector<std::string>{"pressure", "walls"}));
}

TEST(EffectsAssembly, NamedEffectsAreConstructed) {
  const long viscosity = ViscosityTerm::constructed(), diffusion = DensityDiffusionTerm<2>::constructed();
  auto scene = smallTank({"pressure", "viscosity", "density_diffusion", "gravity", "walls"});
  FluidSimulation<2> sim(scene.setup, scene.fluid, scene.boundary);
  EXPECT_GT(ViscosityTerm::constructed(), viscosity);
  EXPECT_GT(DensityDiffusionTerm<2>::constructed(), diffusion);
  EXPECT_EQ(sim.effectNames(),
            (std::vector<std::string>{"pressure", "viscosity", "density_diffusion", "gravity", "walls"}));
}

TEST(EffectsAssembly, RejectsUnknownMissingAndInconsistentEffects) {
  auto scene = smallTank({"pressure", "viscosty", "walls"});
  EXPECT_THROW(FluidSimulation<2>(scene.setup, scene.fluid, scene.boundary), std::invalid_argument);
  scene = smallTank({"gravity", "walls"});  // no pressure
  EXPECT_THROW(FluidSimulation<2>(scene.setup, scene.fluid, scene.boundary), std::invalid_argument);
  scene = smallTank({"pressure", "gravity"});  // boundary surfaces but no walls
  EXPECT_THROW(FluidSimulation<2>(scene.setup, scene.fluid, scene.boundary), std::invalid_argument);
  scene = smallTank({"pressure", "walls"});
  EXPECT_THROW(FluidSimulation<2>(scene.setup, scene.fluid, BoundaryGeometry<2>{}), std::invalid_argument);
}
