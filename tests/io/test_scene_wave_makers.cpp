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

// A still 2D tank for the forcing region (its section is appended).
const char* const kForcingTank = R"(dim: 2
end_time: 1.0
resolution: {dx: 0.02}
effects: [pressure, gravity, walls, forcing_region]
geometry:
  - tank: {lower: [0, 0], upper: [2, 0.5]}
  - water: {lower: [0, 0], upper: [2, 0.3]}
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

  const std::string forcing = std::string(kForcingTank) +
                              "forcing_region: {x_start: 0.1, length: 0.5, bottom_gap: 0.02, wave: {theory: stokes2, "
                              "amplitude: 0.01, period: 1.0}}\n";
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

// A breather piston (METHOD.md 4c) from the scene's numbers alone: defaults from the
// carrier period, the keys written back, the plate at rest through `still`, then on the
// motion of fluid::waves::breatherMakerSignal, whose forward transfer gives back the
// breather at the piston (away from the ramps; the cut below half the carrier frequency
// takes 2.7% of a0 here, docs/wave-theory.md).
TEST(SceneWaveMakers, BreatherSignalFromTheScene) {
  std::string text = kFlume;
  const std::string regular = "{type: regular, wave_height: 0.04, period: 1.0, ramp_up: 0.5}";
  text.replace(text.find(regular), regular.size(),
               "{type: breather, order: 1, a0: 0.01, k0: 6.0, focus_distance: 2.0, focus_time: 20.0, still: 0.05}");
  const auto c = io::loadSceneText(text, "w.yaml");
  const double period = 2.0 * M_PI / std::sqrt(9.81 * 6.0);  // carrier, 0.819 s
  EXPECT_EQ(c.piston.signal, "breather");
  EXPECT_NEAR(c.piston.ramp_up, 4.0 * period, 1e-12);
  EXPECT_NEAR(c.piston.ramp_down, 2.0 * period, 1e-12);
  EXPECT_DOUBLE_EQ(c.piston.duration, 40.0);
  EXPECT_DOUBLE_EQ(c.piston.depth, 0.3);
  EXPECT_EQ(io::resolvedSceneYaml(io::loadSceneText(io::resolvedSceneYaml(c), "r.yaml")), io::resolvedSceneYaml(c));
  EXPECT_FALSE(c.piston.finite_depth_correction);
  const auto corrected = io::loadSceneText(text, "w.yaml", {"piston.signal.finite_depth_correction=true"});
  EXPECT_TRUE(corrected.piston.finite_depth_correction);
  EXPECT_TRUE(io::loadSceneText(io::resolvedSceneYaml(corrected), "r.yaml").piston.finite_depth_correction);

  fluid::waves::BreatherMakerSpec spec;
  spec.order = 1;
  spec.a0 = 0.01;
  spec.k0 = 6.0;
  spec.focusDistance = 2.0;
  spec.focusTime = 20.0;
  spec.depth = 0.3;
  spec.still = 0.05;
  spec.ramp = c.piston.ramp_up;
  spec.rampDown = c.piston.ramp_down;
  spec.duration = 40.0;
  spec.dt = period / 50.0;
  const auto x = fluid::waves::breatherMakerSignal(spec);
  const auto eta = fluid::waves::breatherElevationAtPiston(fluid::waves::PeregrineBreather(1, 0.01, 6.0), 2.0, 20.0,
                                                           40.0, spec.dt);
  const auto back = fluid::waves::elevationFromPistonDisplacement(x, 0.3);
  double worst = 0.0, largest = 0.0;
  for (std::size_t i = 0; i < x.values.size(); ++i) {
    largest = std::max(largest, std::abs(x.values[i]));
    if (x.time(i) > 0.05 + spec.ramp + 2.0 && x.time(i) < 35.0) worst = std::max(worst, std::abs(back.values[i] - eta.values[i]));
  }
  EXPECT_LT(worst, 0.04 * spec.a0);  // measured 0.027 a0

  auto built = io::buildScene<2>(c);
  fluid::FluidSimulation<2> sim(built.scene.setup, built.scene.fluid, built.scene.boundary);
  io::addSceneEffects(sim, c, built);
  const auto [first, last] = sim.walls()->surfaceRange(built.piston_surface);
  ASSERT_GT(last, first);
  bool moved = false;
  while (sim.time() < 0.12) {
    sim.step();
    // Between samples the spline departs from the straight line by ~(omega dt)^2/8 of X.
    const double u = sim.time() / spec.dt;
    const std::size_t i = static_cast<std::size_t>(u);
    const double linear = x.values[i] + (u - i) * (x.values[i + 1] - x.values[i]);
    const double plate = sim.walls()->particles().r[first][0] - 0.1;
    if (sim.time() <= 0.05) {
      ASSERT_NEAR(plate, 0.0, 1e-9) << "t = " << sim.time();
    }
    ASSERT_NEAR(plate, linear, 3e-3 * largest) << "t = " << sim.time();
    moved = moved || plate != 0.0;
  }
  EXPECT_TRUE(moved);
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
  const auto breather = [](const std::string& keys) {
    std::string text = kFlume;
    const std::string regular = "{type: regular, wave_height: 0.04, period: 1.0, ramp_up: 0.5}";
    return text.replace(text.find(regular), regular.size(),
                        "{type: breather, a0: 0.01, k0: 6.0, focus_distance: 2.0, " + keys + "}");
  };
  EXPECT_TRUE(errorOf(breather("focus_time: 20")).empty()) << errorOf(breather("focus_time: 20"));
  EXPECT_NE(errorOf(breather("focus_time: 20, order: 3")).find("'piston.signal.order': expected 1 or 2"),
            std::string::npos);
  EXPECT_NE(errorOf(breather("focus_time: 3")).find("'piston.signal.focus_time': expected focus_time > still + ramp_up"),
            std::string::npos) << errorOf(breather("focus_time: 3"));
  EXPECT_NE(errorOf(breather("focus_time: 20, duration: 21")).find("'piston.signal.duration'"), std::string::npos);
  EXPECT_NE(errorOf(std::string(kFlume) + "moorings: []\n").find("mooring lines need bodies"), std::string::npos);
}

TEST(SceneWaveMakers, FlumeExampleLoads) {
  const auto c = io::loadSceneFile(sourceDir() + "/cases/piston_flume_2d.yaml");
  EXPECT_TRUE(c.piston.present);
  EXPECT_EQ(c.damping_zones.size(), 1u);
}

// forcing_region.gain, ramp_up and end_time reach the effect: in the linear start-up
// the velocity the region drives is proportional to the gain, a forcing that has ended
// drives nothing, and a 1 s half-cosine ramp scales the first steps by (1 - cos(pi t))/2.
TEST(SceneWaveMakers, ForcingGainRampAndEndFromTheScene) {
  const std::string base =
      std::string(kForcingTank) + "forcing_region: {x_start: 0.1, length: 1.0, wave: {amplitude: 0.01, period: 1.0}EXTRA}\n";
  // Velocities by particle id after 20 steps. The region also relaxes the start-up
  // settling of the water toward its target, so the baseline is the same region with a
  // vanishing target (gain 1e-9): the differences are what the target drives.
  auto velocities = [&](std::string text) {
    const auto c = io::loadSceneText(text, "f.yaml");
    auto built = io::buildScene<2>(c);
    fluid::FluidSimulation<2> sim(built.scene.setup, built.scene.fluid, built.scene.boundary);
    io::addSceneEffects(sim, c, built);
    for (int n = 0; n < 20; ++n) sim.step();
    std::vector<fluid::Vec<2>> v(sim.fluid().size());
    for (std::size_t i = 0; i < v.size(); ++i) v[sim.fluid().id[i]] = sim.fluid().v[i];
    return v;
  };
  auto with = [&](const std::string& extra) { return std::string(base).replace(base.find("EXTRA"), 5, extra); };
  const auto zero = velocities(with(", gain: 1e-9"));
  auto driven = [&](const std::vector<fluid::Vec<2>>& v) {
    double sum = 0.0;
    for (std::size_t i = 0; i < v.size(); ++i) sum += (v[i] - zero[i]).norm();
    return sum;
  };
  const double one = driven(velocities(with(""))), two = driven(velocities(with(", gain: 2")));
  const double ramped = driven(velocities(with(", ramp_up: 1")));
  std::printf("sum |v - v_zero target| after 20 steps: gain 1 %.4g, gain 2 %.4g, 1 s ramp %.3g m/s\n", one, two, ramped);
  EXPECT_NEAR(two / one, 2.0, 0.05);
  EXPECT_LT(ramped, 0.01 * one);  // the ramp averages ~1e-4 over the first 20 steps (0.01 s)
  // A forcing that has ended leaves the run exactly as if the scene had none.
  std::string none = with(", end_time: 0");
  const auto ended = velocities(none);
  none.erase(none.find("forcing_region: {"));
  none.replace(none.find(", forcing_region]"), 17, "]");
  const auto plain = velocities(none);
  for (std::size_t i = 0; i < plain.size(); ++i) ASSERT_EQ(ended[i], plain[i]) << "particle " << i;
  EXPECT_NE(errorOf(with(", gain: 0")).find("'forcing_region.gain'"),
            std::string::npos);
}

// gauges[].volume_edge: the plain crossing (false) reads s(xi_t) = 0.4532 h below the
// volume-edge reading in still water (the half-space depth of wave_gauge.hpp, 2D, xi_t = 0.8).
TEST(SceneWaveMakers, GaugeVolumeEdgeSwitch) {
  const std::string text = R"(dim: 2
end_time: 1.0
resolution: {dx: 0.02}
geometry:
  - tank: {lower: [0, 0], upper: [1, 0.5]}
  - water: {lower: [0, 0], upper: [1, 0.3]}
gauges:
  - {name: edge, x: 0.5, top: 0.45}
  - {name: plain, x: 0.5, top: 0.45, volume_edge: false}
)";
  const auto c = io::loadSceneText(text, "g.yaml");
  EXPECT_TRUE(c.gauges[0].volume_edge);
  EXPECT_FALSE(c.gauges[1].volume_edge);
  EXPECT_FALSE(io::loadSceneText(io::resolvedSceneYaml(c), "r.yaml").gauges[1].volume_edge);
  auto built = io::buildScene<2>(c);
  fluid::FluidSimulation<2> sim(built.scene.setup, built.scene.fluid, built.scene.boundary);
  const double edge = fluid::WaveGauge<2>(built.gauges[0]).read(sim);
  const double plain = fluid::WaveGauge<2>(built.gauges[1]).read(sim);
  EXPECT_NEAR(edge - plain, 0.4532 * 1.2 * 0.02, 1e-4 * 0.02);
  EXPECT_NEAR(edge, 0.3, 0.1 * 0.02);
}
