// `moorsph run` and `moorsph check` with bodies: a scene with a rigid body runs as a
// fluid-body co-simulation and writes the body's kinematics, the fluid wrench, line
// tensions, the energy ledger and the coupling timers; a stop-and-restart continues
// bit-identically (fluid and bodies); a restart may change a body's mass and a line's
// stiffness; a body leaving the domain stops the run naming the body.
#include <gtest/gtest.h>

#include "run_support.hpp"
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>
#include <moorsph/io/checkpoint.hpp>
#include <moorsph/io/csv_export.hpp>
#include <moorsph/io/scene_loader.hpp>
#include "run/run_scene.hpp"
#include "run/scene_bodies.hpp"
#include "scene_text.hpp"

using namespace moorsph;

namespace {

using moorsph::test_support::freshDir;

// The 2D floating box of tests/coupling at its Archimedes draught (m / (rho w) =
// 0.05 m: centre at the still level 0.2 m), coarse, tethered to the floor by a
// slack spring so the line series exist.
const char* const kBox = R"(dim: 2
name: box
end_time: 0.2
resolution: {dx: 0.02}
fluid: {viscosity: 0.05, sound_speed: 20}
geometry:
  - tank: {name: tank, lower: [0, 0], upper: [0.8, 0.4]}
  - water: {lower: [0, 0], upper: [0.8, 0.2]}
bodies:
  - name: box
    mass: 10
    inertia: 0.0416667
    position: [0.4, 0.2]
    shape: {box: {size: [0.2, 0.1]}}
moorings:
  - {name: tether, model: tension_only_spring, fairlead: {body: box, point: [0, -0.05]}, anchor: {point: [0.4, 0.0]},
     stiffness: 100, rest_length: 0.2}
coupling: {release_time: 0.05}
output: {interval: 0.01, checkpoint_minutes: 0}
)";

app::RunOptions options(const std::string& scene, const std::string& out, double end) {
  app::RunOptions o;
  o.scene = scene;
  o.out = out;
  o.end = end;
  o.threads = 1;
  return o;
}

/// The values of csv/<series>.csv (time, value per line).
std::vector<double> column(const std::string& dir, const std::string& series) {
  std::ifstream in(dir + "/csv/" + series + ".csv");
  std::string line;
  std::getline(in, line);
  std::vector<double> out;
  while (std::getline(in, line)) out.push_back(std::stod(line.substr(line.find(',') + 1)));
  return out;
}

/// Equal bit for bit (NaN equals NaN: an intact line's break time).
bool identical(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t k = 0; k < a.size(); ++k)
    if (!(a[k] == b[k] || (std::isnan(a[k]) && std::isnan(b[k])))) return false;
  return true;
}

std::string header(const std::string& dir, const std::string& file) {
  std::ifstream in(dir + "/csv/" + file + ".csv");
  std::string line;
  std::getline(in, line);
  return line;
}

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

TEST(BodyRuns, FloatingBoxRunsAndRecordsBodyLineLedgerAndTimers) {
  const std::string dir = freshDir("moorsph_body_run");
  const std::string scene = test::writeScene(dir + "/scene.yaml", kBox);
  ASSERT_EQ(app::runScene(options(scene, dir + "/run", 0.2)), app::kSuccess);
  ASSERT_GT(io::exportSeriesCsv(dir + "/run").size(), 0u);
  EXPECT_EQ(header(dir + "/run", "body_box.angle"), "time [s],angle [rad]");
  EXPECT_EQ(header(dir + "/run", "velocity_box.wz"), "time [s],wz [rad/s]");
  EXPECT_EQ(header(dir + "/run", "wrench_box.Fy"), "time [s],Fy [N/m]");
  EXPECT_EQ(header(dir + "/run", "wrench_box.Mz"), "time [s],Mz [N m/m]");
  EXPECT_EQ(header(dir + "/run", "line_tether.fairlead_tension"), "time [s],fairlead_tension [N]");
  EXPECT_EQ(header(dir + "/run", "line_tether.broken"), "time [s],broken [1]");
  EXPECT_EQ(header(dir + "/run", "ledger.work_by_fluid_on_bodies"), "time [s],work_by_fluid_on_bodies [J/m]");
  EXPECT_EQ(header(dir + "/run", "coupling_timing.exchange"), "time [s],exchange [s]");
  // Held until 0.05 s: the box does not move; afterwards the fluid carries it.
  const auto y = column(dir + "/run", "body_box.y");
  ASSERT_EQ(y.size(), 21u);
  EXPECT_EQ(y[0], 0.2);
  EXPECT_EQ(y[4], 0.2);
  // Archimedes: at its draught the water holds the box up with m g = 98.1 N/m; the
  // coarse start-up transient allows 15% on the mean over the released outputs.
  const auto fy = column(dir + "/run", "wrench_box.Fy");
  double mean = 0.0;
  for (std::size_t k = 6; k < fy.size(); ++k) mean += fy[k] / static_cast<double>(fy.size() - 6);
  EXPECT_NEAR(mean, 10 * 9.81, 0.15 * 10 * 9.81);
  // Held, the series gives the fluid's load that the hold restrains (here the first 50 ms
  // of the start, the water still coming into contact with the box): not the zero applied.
  EXPECT_GT(std::max({fy[1], fy[2], fy[3], fy[4]}), 0.1);
  // The spring is slack (span 0.15 m < rest length 0.2 m): no tension, slack flag set.
  EXPECT_EQ(column(dir + "/run", "line_tether.fairlead_tension").back(), 0.0);
  EXPECT_EQ(column(dir + "/run", "line_tether.slack").back(), 1.0);
  EXPECT_GT(column(dir + "/run", "coupling_timing.bodies").back(), 0.0);
  const std::string log = slurp(dir + "/run/log.txt");
  EXPECT_NE(log.find("body 'box': box, 3 of 3 DOF free, mass 10 kg/m"), std::string::npos) << log;
  EXPECT_NE(log.find("line 'tether': tension_only_spring"), std::string::npos) << log;
}

TEST(BodyRuns, StopAndRestartIsBitIdenticalWithBodies) {
  const std::string dir = freshDir("moorsph_body_restart");
  const std::string scene = test::writeScene(dir + "/scene.yaml", kBox);
  ASSERT_EQ(app::runScene(options(scene, dir + "/straight", 0.16)), app::kSuccess);
  ASSERT_EQ(app::runScene(options(scene, dir + "/first", 0.1)), app::kSuccess);
  app::RunOptions again = options(scene, dir + "/second", 0.16);
  again.restart = dir + "/first/checkpoint.h5";
  ASSERT_EQ(app::runScene(again), app::kSuccess);
  const auto a = io::readCheckpoint(dir + "/straight/checkpoint.h5");
  const auto b = io::readCheckpoint(dir + "/second/checkpoint.h5");
  const auto half = io::readCheckpoint(dir + "/first/checkpoint.h5");
  ASSERT_FALSE(a.bodies.empty());
  EXPECT_EQ(a.steps, b.steps);
  EXPECT_EQ(a.r, b.r);
  EXPECT_EQ(a.v, b.v);
  EXPECT_EQ(a.rho, b.rho);
  EXPECT_TRUE(identical(a.bodies, b.bodies));  // body time, pose, velocities, wrenches, line states
  const auto sa = app::unpackSnapshot(a.bodies), sh = app::unpackSnapshot(half.bodies);
  EXPECT_GT(std::abs(sa.bodies[0].position.y() - sh.bodies[0].position.y()), 1e-6) << "the box did not move";
}

TEST(BodyRuns, RestartMayChangeMassAndLineButNotTheBody) {
  const std::string dir = freshDir("moorsph_body_variant");
  const std::string scene = test::writeScene(dir + "/scene.yaml", kBox);
  ASSERT_EQ(app::runScene(options(scene, dir + "/first", 0.1)), app::kSuccess);
  app::RunOptions same = options(scene, dir + "/same", 0.14);
  same.restart = dir + "/first/checkpoint.h5";
  ASSERT_EQ(app::runScene(same), app::kSuccess);
  app::RunOptions heavy = options(scene, dir + "/heavy", 0.14);
  heavy.restart = dir + "/first/checkpoint.h5";
  heavy.sets = {"bodies.0.mass=20", "bodies.0.inertia=0.0833333", "moorings.0.stiffness=300", "moorings.0.rest_length=0.1"};
  ASSERT_EQ(app::runScene(heavy), app::kSuccess);
  // Twice the mass with the same buoyancy: without added mass the box would
  // accelerate down at (B - 2 m g) / 2m = -g/2 (more with the now taut line) where it
  // floated; its heave added mass (of the order of its own mass) and the buoyancy it
  // gains as it sinks slow that down: at least a quarter of it over the 0.04 s.
  const auto s = app::unpackSnapshot(io::readCheckpoint(dir + "/same/checkpoint.h5").bodies);
  const auto h = app::unpackSnapshot(io::readCheckpoint(dir + "/heavy/checkpoint.h5").bodies);
  const double dv = h.bodies[0].velocity.y() - s.bodies[0].velocity.y();
  EXPECT_LT(dv, -0.25 * 0.5 * 9.81 * 0.04) << "a heavier box must sink faster";
  EXPECT_NE(slurp(dir + "/heavy/log.txt").find("mass 20 kg/m"), std::string::npos);
  // A line may change between models; the log says what the restarted line starts from.
  app::RunOptions lumped = options(scene, dir + "/lumped", 0.12);
  lumped.restart = dir + "/first/checkpoint.h5";
  lumped.sets = {"moorings.0.model=lumped_mass", "moorings.0.length=0.2", "moorings.0.axial_stiffness=20",
                 "moorings.0.mass_per_length=0.1", "moorings.0.diameter=0.005", "moorings.0.segments=5"};
  ASSERT_EQ(app::runScene(lumped), app::kSuccess);
  EXPECT_NE(slurp(dir + "/lumped/log.txt")
                .find("note: line 'tether': tension_only_spring in the checkpoint's run, lumped_mass now (it starts at "
                      "rest in its static shape between the restored ends)"),
            std::string::npos)
      << slurp(dir + "/lumped/log.txt");
  app::RunOptions bigger = options(scene, dir + "/bigger", 0.14);
  bigger.restart = dir + "/first/checkpoint.h5";
  bigger.sets = {"bodies.0.shape.box.size=[0.3, 0.1]"};
  EXPECT_EQ(app::runScene(bigger), app::kBadInput);
}

TEST(BodyRuns, BodyLeavingTheDomainStopsTheRunNamingIt) {
  const std::string dir = freshDir("moorsph_body_escape");
  std::string text = kBox;
  text.replace(text.find("coupling: {release_time: 0.05}"), 30, "coupling: {release_time: 0}");
  const std::string scene = test::writeScene(dir + "/scene.yaml", text);
  app::RunOptions o = options(scene, dir + "/run", 0.2);
  o.sets = {"bodies.0.velocity=[0, 40]", "moorings.0.rest_length=5"};  // thrown up, line slack
  EXPECT_EQ(app::runScene(o), app::kRunFailed);
  const std::string error = slurp(dir + "/run/error.txt");
  EXPECT_NE(error.find("left the domain"), std::string::npos) << error;
  EXPECT_NE(error.find("body 'box'"), std::string::npos) << error;
  EXPECT_TRUE(std::filesystem::exists(dir + "/run/failure.checkpoint.h5"));
}

TEST(BodyRuns, CheckListsBodiesAndLines) {
  const std::string dir = freshDir("moorsph_body_check");
  const std::string scene = test::writeScene(dir + "/scene.yaml", kBox);
  std::FILE* pipe = popen((std::string(MOORSPH_BINARY) + " check --threads 1 " + scene + " 2>&1").c_str(), "r");
  std::string out;
  char buffer[512];
  while (pipe && std::fgets(buffer, sizeof buffer, pipe)) out += buffer;
  ASSERT_EQ(WEXITSTATUS(pclose(pipe)), 0) << out;
  EXPECT_NE(out.find("effects: pressure viscosity xsph gravity walls bodies"), std::string::npos) << out;
  EXPECT_NE(out.find("body 'box': box, 3 of 3 DOF free"), std::string::npos) << out;
  EXPECT_NE(out.find("boundary particles on its surface"), std::string::npos) << out;
  EXPECT_NE(out.find("line 'tether': tension_only_spring from box to a ground anchor, initial tension 0 N at the fairlead (slack)"),
            std::string::npos) << out;
  EXPECT_NE(out.find("coupling: bodies held until t = 0.05 s"), std::string::npos) << out;
}

TEST(BodyRuns, BodyExampleScenesRun) {
  // The annotated examples under cases/ run a few steps at a coarse resolution.
  const std::string source = std::getenv("MOORSPH_SOURCE_DIR") ? std::getenv("MOORSPH_SOURCE_DIR") : ".";
  for (const char* name : {"floating_box_2d", "tethered_buoy_3d", "moored_buoy_catenary_3d"}) {
    SCOPED_TRACE(name);
    app::RunOptions o = options(source + "/cases/" + name + ".yaml", testing::TempDir() + "moorsph_example_" + name, 0.01);
    o.sets = {"output.interval=0.005"};
    if (std::string(name) != "floating_box_2d") o.sets.push_back("resolution.dx=0.04");
    std::filesystem::remove_all(o.out);
    EXPECT_EQ(app::runScene(o), app::kSuccess);
  }
}

TEST(BodyRuns, EveryMooringModelRunsByChangingOneWord) {
  // The catenary example's line, described once, run with each model word (released
  // at once so the line acts): a spring model derives k = EA / length, L0 = length.
  const std::string source = std::getenv("MOORSPH_SOURCE_DIR") ? std::getenv("MOORSPH_SOURCE_DIR") : ".";
  for (const char* model : {"elastic_catenary", "lumped_mass", "tension_only_spring", "cable_path"}) {
    SCOPED_TRACE(model);
    const std::string out = testing::TempDir() + "moorsph_model_" + model;
    std::filesystem::remove_all(out);
    app::RunOptions o = options(source + "/cases/moored_buoy_catenary_3d.yaml", out, 0.02);
    o.sets = {"resolution.dx=0.04", "coupling.release_time=0", "coupling.ramp_time=0", "output.interval=0.01",
              std::string("moorings.0.model=") + model};
    ASSERT_EQ(app::runScene(o), app::kSuccess);
    EXPECT_NE(slurp(out + "/log.txt").find(std::string("line 'chain': ") + model), std::string::npos);
    ASSERT_GT(io::exportSeriesCsv(out).size(), 0u);
    const auto tension = column(out, "line_chain.fairlead_tension");
    ASSERT_FALSE(tension.empty());
    EXPECT_TRUE(std::isfinite(tension.back()));
  }
}

TEST(BodyRuns, RollPitchYawAreContinuousThroughZero) {
  // R = Ry(yaw) Rz(pitch) Rx(roll) (y up) built from known angles gives them back, small
  // negative angles included (no jumps by pi in the series).
  for (const Eigen::Vector3d& rpy : {Eigen::Vector3d(0.1, -0.2, 0.3), Eigen::Vector3d(-0.004, 0.002, -0.001),
                                    Eigen::Vector3d(2.5, 1.2, -3.0)}) {
    const Eigen::Quaterniond q = Eigen::AngleAxisd(rpy[2], Eigen::Vector3d::UnitY()) *
                                 Eigen::AngleAxisd(rpy[1], Eigen::Vector3d::UnitZ()) *
                                 Eigen::AngleAxisd(rpy[0], Eigen::Vector3d::UnitX());
    EXPECT_LT((app::rollPitchYaw(q) - rpy).norm(), 1e-12) << rpy.transpose();
  }
}

TEST(BodyRuns, PitchIsAboutTheAcrossAxisAndYawAboutUp) {
  // y is up, x along the tank: a turn about z (across) is pitch, about y (up) is yaw.
  EXPECT_LT((app::rollPitchYaw(Eigen::Quaterniond(Eigen::AngleAxisd(0.1, Eigen::Vector3d::UnitZ()))) -
             Eigen::Vector3d(0.0, 0.1, 0.0)).norm(), 1e-15);
  EXPECT_LT((app::rollPitchYaw(Eigen::Quaterniond(Eigen::AngleAxisd(0.1, Eigen::Vector3d::UnitY()))) -
             Eigen::Vector3d(0.0, 0.0, 0.1)).norm(), 1e-15);
  EXPECT_LT((app::rollPitchYaw(Eigen::Quaterniond(Eigen::AngleAxisd(0.1, Eigen::Vector3d::UnitX()))) -
             Eigen::Vector3d(0.1, 0.0, 0.0)).norm(), 1e-15);
}

TEST(BodyRuns, SnapshotPackingRoundTrips) {
  // What a checkpoint keeps of the bodies: every field back exactly, a broken line's
  // time and tension included.
  bodies::SystemSnapshot s;
  s.time = 1.25;
  bodies::BodyKinematics k;
  k.position = Eigen::Vector3d(0.1, 0.2, 0.3);
  k.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 2, 3).normalized()));
  k.velocity = Eigen::Vector3d(-1, 0.5, 2);
  k.angularVelocity = Eigen::Vector3d(0.01, -0.02, 0.03);
  s.bodies = {k};
  s.wrenches = {bodies::BodyWrench{Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(4, 5, 6)}};
  bodies::LineSnapshot l;
  l.broken = true;
  l.breakTime = 0.75;
  l.breakTension = 12.5;
  l.cableDissipated = 0.125;
  l.internalState = {1.0, 2.0, 3.0};
  s.lines = {l};
  s.dissipated = 0.5;
  s.externalWork = -0.25;
  const bodies::SystemSnapshot r = app::unpackSnapshot(app::packSnapshot(s));
  EXPECT_EQ(r.time, s.time);
  EXPECT_EQ(r.bodies[0].position, k.position);
  EXPECT_EQ(r.bodies[0].orientation.coeffs(), k.orientation.coeffs());
  EXPECT_EQ(r.bodies[0].velocity, k.velocity);
  EXPECT_EQ(r.bodies[0].angularVelocity, k.angularVelocity);
  EXPECT_EQ(r.wrenches[0].torque, s.wrenches[0].torque);
  EXPECT_TRUE(r.lines[0].broken);
  EXPECT_EQ(r.lines[0].breakTime, 0.75);
  EXPECT_EQ(r.lines[0].breakTension, 12.5);
  EXPECT_EQ(r.lines[0].cableDissipated, 0.125);
  EXPECT_EQ(r.lines[0].internalState, l.internalState);
  EXPECT_EQ(r.dissipated, 0.5);
  EXPECT_EQ(r.externalWork, -0.25);
}

// Pressure probes on a body: point and normal in the body frame, carried with it. The
// floating box's bottom face sits at its draught, 0.05 m: the probe there reads the
// hydrostatic rho g 0.05 = 490.5 Pa; the top face is dry. A point off the body is refused.
TEST(BodyRuns, PressureProbesRideOnTheBody) {
  const std::string dir = freshDir("moorsph_body_probes");
  std::string text = kBox;
  text.replace(text.find("moorings:"), 0,
               "pressure_probes:\n  - {name: keel, surface: box, point: [0, -0.05], normal: [0, -1], moving_mean: 0.03}\n"
               "  - {name: deck, surface: box, point: [0, 0.05], normal: [0, 1]}\n");
  const auto c = io::loadSceneText(text, "s.yaml");
  ASSERT_EQ(c.probes.size(), 2u);
  EXPECT_TRUE(c.probes[0].on_body);
  const std::string scene = test::writeScene(dir + "/scene.yaml", text);
  ASSERT_EQ(app::runScene(options(scene, dir + "/run", 0.2)), app::kSuccess);
  ASSERT_GT(io::exportSeriesCsv(dir + "/run").size(), 0u);
  const auto keel = column(dir + "/run", "probes.keel_reaction");
  const auto deck = column(dir + "/run", "probes.deck_reaction");
  ASSERT_EQ(keel.size(), 21u);
  double k = 0.0, d = 0.0;
  for (std::size_t i = 6; i < keel.size(); ++i) {
    k += keel[i] / static_cast<double>(keel.size() - 6);
    d += deck[i] / static_cast<double>(keel.size() - 6);
  }
  std::printf("keel %.1f Pa (hydrostatic at the draught 490.5 Pa), deck %.1f Pa\n", k, d);
  // The 0.03 s trailing mean over the ~0.01 s outputs: the mean of the samples in (t - 0.03, t].
  const auto mean = column(dir + "/run", "probes.keel_reaction_mean");
  std::vector<double> t;
  {
    std::ifstream in(dir + "/run/csv/probes.keel_reaction.csv");
    std::string line;
    std::getline(in, line);
    while (std::getline(in, line)) t.push_back(std::stod(line.substr(0, line.find(','))));
  }
  ASSERT_EQ(mean.size(), keel.size());
  ASSERT_EQ(t.size(), keel.size());
  for (std::size_t i = 0; i < keel.size(); ++i) {
    double sum = 0.0;
    int n = 0;
    for (std::size_t j = 0; j <= i; ++j)
      if (t[j] > t[i] - 0.03) sum += keel[j], ++n;
    EXPECT_NEAR(mean[i], sum / n, 1e-9) << "output " << i;
  }
  EXPECT_NEAR(k, 1000.0 * 9.81 * 0.05, 0.25 * 490.5);
  EXPECT_LT(std::abs(d), 0.05 * 490.5);

  std::string off = text;
  off.replace(off.find("point: [0, 0.05]"), 16, "point: [0, 0.15]");
  try {
    io::loadSceneText(off, "s.yaml");
    ADD_FAILURE() << "a probe 0.1 m off the body was accepted";
  } catch (const io::SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("from the surface 'box'"), std::string::npos) << e.what();
  }
}

// Named body points and green water. The points ride rigidly with the body (stern - bow
// = R (0.2, 0) at every output); a 0.04 m layer of water placed on the deck reads its
// lattice volume at t = 0 and never more than that later.
TEST(BodyRuns, BodyPointsAndGreenWater) {
  const std::string dir = freshDir("moorsph_body_points");
  std::string text = kBox;
  text.replace(text.find("  - water: {lower: [0, 0], upper: [0.8, 0.2]}"), 0,
               "  - water: {lower: [0.3, 0.25], upper: [0.5, 0.29]}\n");
  text.replace(text.find("    shape: {box:"), 0,
               "    points: {bow: [-0.1, 0.05], stern: [0.1, 0.05]}\n"
               "    green_water: {deck_height: 0.05, x_range: [-0.1, 0.1]}\n");
  text.replace(text.find("sound_speed: 20"), 15, "sound_speed: 24");
  const auto c = io::loadSceneText(text, "s.yaml");
  ASSERT_EQ(c.bodies[0].points.size(), 2u);
  const auto again = io::loadSceneText(io::resolvedSceneYaml(c), "r.yaml");
  EXPECT_EQ(again.bodies[0].points[1].first, "stern");
  EXPECT_TRUE(again.bodies[0].green_water);
  const std::string scene = test::writeScene(dir + "/scene.yaml", text);
  ASSERT_EQ(app::runScene(options(scene, dir + "/run", 0.2)), app::kSuccess);
  ASSERT_GT(io::exportSeriesCsv(dir + "/run").size(), 0u);
  const auto bow_x = column(dir + "/run", "points_box.bow_x"), bow_y = column(dir + "/run", "points_box.bow_y");
  const auto stern_x = column(dir + "/run", "points_box.stern_x"), stern_y = column(dir + "/run", "points_box.stern_y");
  const auto com_y = column(dir + "/run", "points_box.com_y"), y = column(dir + "/run", "body_box.y");
  const auto angle = column(dir + "/run", "body_box.angle");
  ASSERT_EQ(bow_x.size(), 21u);
  EXPECT_DOUBLE_EQ(bow_x[0], 0.3);
  EXPECT_DOUBLE_EQ(bow_y[0], 0.25);
  for (std::size_t k = 0; k < bow_x.size(); ++k) {
    EXPECT_NEAR(stern_x[k] - bow_x[k], 0.2 * std::cos(angle[k]), 1e-12);
    EXPECT_NEAR(stern_y[k] - bow_y[k], 0.2 * std::sin(angle[k]), 1e-12);
    EXPECT_NEAR(com_y[k], y[k], 1e-12);  // the centre of mass is the reference point here
  }
  const auto green = column(dir + "/run", "green_water_box.volume");
  // Two rows of ten particles of 0.02 x 0.02 m (slightly compressed: hydrostatic start).
  EXPECT_NEAR(green[0], 20 * 0.0004, 0.01 * 20 * 0.0004);
  for (double v : green) EXPECT_LE(v, 1.02 * green[0]);
  std::printf("green water %.5f m^2/m at t = 0, %.5f at 0.2 s; bow y %.4f -> %.4f m\n", green[0], green.back(), bow_y[0],
              bow_y.back());
}
