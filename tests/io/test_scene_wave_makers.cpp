// Wave makers in scene files: the piston plate follows the closed-form regular-wave
// motion (stroke from the linear transfer function) or a table through a spline;
// damping zones and the forcing region are built; each inconsistency between the
// effect list and the sections, and each out-of-range value, is rejected.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <string>
#include <moorsph/fluid/waves/piston_signal.hpp>
#include <moorsph/io/scene_builder.hpp>
#include <moorsph/io/scene_loader.hpp>

using namespace moorsph;

namespace {

std::string sourceDir() {
  const char* dir = std::getenv("MOORSPH_SOURCE_DIR");
  return dir ? dir : ".";
}

const char* const kFlume = R"(dim: 2
end_time: 1.0
resolution: {dx: 0.02}
effects: [pressure, gravity, walls, piston, damping_zone]
geometry:
  - tank: {name: flume, lower: [0, 0], upper: [2, 0.5]}
  - water: {lower: [0.1, 0], upper: [2, 0.3]}
piston:
  x: 0.1
  bottom: 0
  top: 0.4
  signal: {type: regular, wave_height: 0.04, period: 1.0, ramp_up: 0.5}
damping_zones:
  - {x_start: 1.5, x_end: 2.0, k_max: 5}
)";

std::string errorOf(const std::string& text) {
  try {
    io::loadSceneText(text, "w.yaml");
  } catch (const io::SceneError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(SceneWaveMakers, PistonFollowsTheRegularWaveMotion) {
  const auto c = io::loadSceneText(kFlume, "w.yaml");
  EXPECT_DOUBLE_EQ(c.piston.depth, 0.3);  // default: the water height
  auto built = io::buildScene<2>(c);
  fluid::FluidSimulation<2> sim(built.scene.setup, built.scene.fluid, built.scene.boundary);
  io::addSceneEffects(sim, c, built);
  const auto names = sim.effectNames();
  EXPECT_EQ(names[names.size() - 2], "piston");
  EXPECT_EQ(names.back(), "damping_zone");
  const double half_stroke = 0.5 * fluid::waves::pistonStroke(0.04, 1.0, 0.3, 9.81);
  const auto [first, last] = sim.walls()->surfaceRange(built.piston_surface);
  ASSERT_GT(last, first);
  while (sim.time() < 0.7) sim.step();
  // After the ramp (0.5 s): X(t) = (S/2) sin(2 pi t / T), the plate placed at time().
  const double expected = 0.1 + half_stroke * std::sin(2.0 * M_PI * sim.time());
  for (std::size_t k = first; k < last; ++k) ASSERT_NEAR(sim.walls()->particles().r[k][0], expected, 1e-12);
}

TEST(SceneWaveMakers, TableSignalAndForcingRegion) {
  const std::string dir = testing::TempDir();
  std::ofstream(dir + "/signal.csv") << "t [s],X [m]\n0,0\n0.5,0.01\n1.0,0.0\n1.5,-0.01\n2.0,0\n";
  std::string text = kFlume;
  text.replace(text.find("{type: regular, wave_height: 0.04, period: 1.0, ramp_up: 0.5}"),
               std::string("{type: regular, wave_height: 0.04, period: 1.0, ramp_up: 0.5}").size(),
               "{type: table, file: " + dir + "/signal.csv}");
  const auto c = io::loadSceneText(text, "w.yaml");
  ASSERT_EQ(c.piston.table_t.size(), 5u);
  EXPECT_EQ(c.piston.table_x[1], 0.01);

  const std::string forcing = R"(dim: 2
end_time: 1.0
resolution: {dx: 0.02}
effects: [pressure, gravity, walls, forcing_region]
geometry:
  - tank: {lower: [0, 0], upper: [2, 0.5]}
  - water: {lower: [0, 0], upper: [2, 0.3]}
forcing_region: {x_start: 0.1, length: 0.5, bottom_gap: 0.02, wave: {theory: stokes2, amplitude: 0.01, period: 1.0}}
)";
  const auto f = io::loadSceneText(forcing, "f.yaml");
  EXPECT_DOUBLE_EQ(f.forcing.still_level, 0.3);
  auto built = io::buildScene<2>(f);
  fluid::FluidSimulation<2> sim(built.scene.setup, built.scene.fluid, built.scene.boundary);
  io::addSceneEffects(sim, f, built);
  EXPECT_EQ(sim.effectNames().back(), "forcing_region");
  for (int n = 0; n < 5; ++n) sim.step();
  // The resolved scene keeps every wave-maker key.
  const auto again = io::loadSceneText(io::resolvedSceneYaml(f), "r.yaml");
  EXPECT_EQ(again.forcing.theory, "stokes2");
  EXPECT_EQ(io::resolvedSceneYaml(again), io::resolvedSceneYaml(f));
}

TEST(SceneWaveMakers, Errors) {
  std::string unnamed = kFlume;
  unnamed.replace(unnamed.find(", piston, damping_zone"), 22, ", damping_zone");
  EXPECT_NE(errorOf(unnamed).find("'piston': the scene gives 'piston' but 'effects' does not list 'piston'"),
            std::string::npos) << errorOf(unnamed);
  std::string missing = kFlume;
  missing.erase(missing.find("damping_zones:"));
  EXPECT_NE(errorOf(missing).find("'effects' lists 'damping_zone' but the scene has no 'damping_zones' section"),
            std::string::npos) << errorOf(missing);
  std::string stiff = kFlume;
  stiff.replace(stiff.find("k_max: 5"), 8, "k_max: 5000");
  const std::string s = errorOf(stiff);
  EXPECT_NE(s.find("w.yaml:14:39: 'damping_zones[0].k_max'"), std::string::npos) << s;
  EXPECT_NE(s.find("k_max dt must stay below 1"), std::string::npos) << s;
  std::string behind = kFlume;
  behind.replace(behind.find("x: 0.1"), 6, "x: 0.3");
  EXPECT_NE(errorOf(behind).find("behind the piston face"), std::string::npos) << errorOf(behind);
  std::string kind = kFlume;
  kind.replace(kind.find("type: regular"), 13, "type: sine");
  EXPECT_NE(errorOf(kind).find("'piston.signal.type': expected 'regular'"), std::string::npos) << errorOf(kind);
  EXPECT_NE(errorOf(std::string(kFlume) + "moorings: []\n").find("mooring lines need bodies"), std::string::npos);
}

TEST(SceneWaveMakers, FlumeExampleLoads) {
  const auto c = io::loadSceneFile(sourceDir() + "/cases/piston_flume_2d.yaml");
  EXPECT_TRUE(c.piston.present);
  EXPECT_EQ(c.damping_zones.size(), 1u);
}
