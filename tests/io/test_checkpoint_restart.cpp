// Checkpoints: a run stopped at t1 and restarted from its checkpoint ends bit-identical
// to a straight run (same thread count); Ctrl-C (SIGINT) stops with a checkpoint that
// restarts; a failing run keeps its output and writes a failure checkpoint.
#include <gtest/gtest.h>

#include "run_support.hpp"

#include <cmath>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <moorsph/io/checkpoint.hpp>
#include <moorsph/io/series_history.hpp>
#include "run/run_scene.hpp"
#include "scene_text.hpp"

using namespace moorsph;

namespace {

using moorsph::test_support::freshDir;

app::RunOptions options(const std::string& scene, const std::string& out, double end) {
  app::RunOptions o;
  o.scene = scene;
  o.out = out;
  o.end = end;
  o.threads = 2;
  return o;
}

std::size_t countDifferences(const io::Checkpoint& a, const io::Checkpoint& b) {
  std::size_t differing = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    bool same = a.id[i] == b.id[i] && a.rho[i] == b.rho[i] && a.m[i] == b.m[i];
    for (int d = 0; d < a.dim; ++d) same = same && a.r[a.dim * i + d] == b.r[a.dim * i + d] && a.v[a.dim * i + d] == b.v[a.dim * i + d];
    if (!same) ++differing;
  }
  return differing;
}

std::string readText(const std::string& path) {
  std::ifstream in(path);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

/// The restart's series.h5 holds the whole run: every row of the straight run's energy
/// series (but the wall time), the same times and values to the bit, from t = 0.
void expectSameHistory(const std::string& straight, const std::string& restarted, double restart_time) {
  const io::SeriesTable a = io::readSeriesTable(straight, "energy");
  const io::SeriesTable b = io::readSeriesTable(restarted, "energy");
  ASSERT_EQ(a.time.size(), b.time.size());
  ASSERT_GT(a.time.size(), 5u);
  std::size_t before_restart = 0;
  for (std::size_t r = 0; r < a.time.size(); ++r) {
    EXPECT_EQ(a.time[r], b.time[r]) << "row " << r;
    if (a.time[r] <= restart_time) ++before_restart;
  }
  EXPECT_GT(before_restart, 2u);  // not trivial: the history is carried, not just the restart's rows
  ASSERT_EQ(a.columns.size(), b.columns.size());
  for (std::size_t c = 0; c < a.columns.size(); ++c) {
    if (a.columns[c].name == "wall_time") continue;
    EXPECT_EQ(a.columns[c].name, b.columns[c].name);
    EXPECT_EQ(a.values[c], b.values[c]) << a.columns[c].name;
  }
}

}  // namespace

TEST(Checkpoint, StopAndRestartIsBitIdenticalToAStraightRun) {
  const std::string dir = freshDir("moorsph_restart");
  const std::string scene = test::writeScene(dir + "/scene.yaml", test::kSmallDamBreak);
  ASSERT_EQ(app::runScene(options(scene, dir + "/straight", 0.1)), app::kSuccess);
  ASSERT_EQ(app::runScene(options(scene, dir + "/first", 0.06)), app::kSuccess);
  app::RunOptions again = options(scene, dir + "/second", 0.1);
  again.restart = dir + "/first/checkpoint.h5";
  ASSERT_EQ(app::runScene(again), app::kSuccess);

  const auto half = io::readCheckpoint(dir + "/first/checkpoint.h5");
  EXPECT_EQ(half.reason, "end");
  EXPECT_GE(half.time, 0.06);
  const auto a = io::readCheckpoint(dir + "/straight/checkpoint.h5");
  const auto b = io::readCheckpoint(dir + "/second/checkpoint.h5");
  ASSERT_EQ(a.size(), 200u);
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(a.time, b.time);
  EXPECT_EQ(a.steps, b.steps);
  EXPECT_EQ(a.next_output, b.next_output);
  EXPECT_EQ(countDifferences(a, b), 0u);
  // Not trivial: the particles moved between the checkpoint and the end.
  EXPECT_GT(countDifferences(half, b), 190u);
  // The checkpoint was written atomically: no temporary is left behind.
  EXPECT_FALSE(std::filesystem::exists(dir + "/first/checkpoint.h5.tmp"));
  expectSameHistory(dir + "/straight/series.h5", dir + "/second/series.h5", half.time);
  // The restart took its particles from the checkpoint without building the water again
  // (the scene is the checkpoint's) and carries the scene's particle count on.
  EXPECT_EQ(half.scene_fluid_count, 200);
  EXPECT_EQ(b.scene_fluid_count, 200);
  EXPECT_NE(readText(dir + "/second/log.txt").find("water blocks not built again"), std::string::npos);
  // A checkpoint written before session 38 has no count: the restart builds the water to
  // check it against the scene, and ends the same.
  io::Checkpoint old = half;
  old.scene_fluid_count = 0;
  io::writeCheckpoint(dir + "/old.h5", old);
  app::RunOptions from_old = options(scene, dir + "/from_old", 0.1);
  from_old.restart = dir + "/old.h5";
  ASSERT_EQ(app::runScene(from_old), app::kSuccess);
  EXPECT_EQ(readText(dir + "/from_old/log.txt").find("water blocks not built again"), std::string::npos);
  const auto c = io::readCheckpoint(dir + "/from_old/checkpoint.h5");
  EXPECT_EQ(countDifferences(a, c), 0u);
  EXPECT_EQ(c.scene_fluid_count, 200);
}

TEST(Checkpoint, InterruptWritesACheckpointThatRestarts) {
  const std::string dir = freshDir("moorsph_interrupt");
  const std::string scene = test::writeScene(dir + "/scene.yaml", test::kSmallDamBreak);
  app::RunOptions o = options(scene, dir + "/run", 0.1);
  o.after_step = [](std::size_t step) {
    if (step == 150) std::raise(SIGINT);  // handled by moorsph: stop after the next step
  };
  ASSERT_EQ(app::runScene(o), app::kInterrupted);
  const auto stopped = io::readCheckpoint(dir + "/run/checkpoint.h5");
  EXPECT_EQ(stopped.reason, "interrupt");
  EXPECT_EQ(stopped.steps, 151);
  EXPECT_LT(stopped.time, 0.1);

  app::RunOptions resume = options(scene, dir + "/resumed", 0.1);
  resume.restart = dir + "/run/checkpoint.h5";
  ASSERT_EQ(app::runScene(resume), app::kSuccess);
  const auto end = io::readCheckpoint(dir + "/resumed/checkpoint.h5");
  EXPECT_GE(end.time, 0.1);
  // The checkpoint carries the positions of the run's last list build, so the resumed
  // run has the lists the interrupted one had and matches a straight run to the bit (no
  // rebuild was forced before the interrupt's checkpoint).
  ASSERT_EQ(app::runScene(options(scene, dir + "/straight", 0.1)), app::kSuccess);
  const auto straight = io::readCheckpoint(dir + "/straight/checkpoint.h5");
  ASSERT_EQ(straight.steps, end.steps);
  EXPECT_EQ(countDifferences(straight, end), 0u);
  EXPECT_GT(countDifferences(stopped, end), 190u);
}

TEST(Checkpoint, FailedRunKeepsOutputAndWritesADiagnostic) {
  const std::string dir = freshDir("moorsph_failure");
  // No walls: the block falls out of the bottom of the domain within ~0.1 s.
  const std::string scene = test::writeScene(dir + "/scene.yaml", R"(dim: 2
end_time: 0.5
resolution: {dx: 0.01}
fluid: {sound_speed: 20}
effects: [pressure, gravity]
domain: {lower: [-0.1, -0.02], upper: [0.2, 0.3]}
geometry:
  - water: {lower: [0, 0], upper: [0.1, 0.1]}
output: {interval: 0.01, checkpoint_minutes: 0}
)");
  ASSERT_EQ(app::runScene(options(scene, dir + "/run", 0.0)), app::kRunFailed);
  const auto failed = io::readCheckpoint(dir + "/run/failure.checkpoint.h5");
  EXPECT_EQ(failed.reason, "failure");
  EXPECT_GT(failed.time, 0.05);
  std::ifstream error(dir + "/run/error.txt");
  std::string message;
  std::getline(error, message);
  EXPECT_NE(message.find("left the domain"), std::string::npos) << message;
  ASSERT_EQ(app::exportRun(dir + "/run"), app::kSuccess);  // series.h5 is readable
  std::ifstream csv(dir + "/run/csv/energy.kinetic.csv");
  int rows = 0;
  for (std::string line; std::getline(csv, line);) ++rows;
  EXPECT_GT(rows, 5);  // header + the rows written before the failure
}

TEST(Checkpoint, WrittenAtTheWallTimeInterval) {
  const std::string dir = freshDir("moorsph_interval");
  const std::string scene = test::writeScene(dir + "/scene.yaml", test::kSmallDamBreak);
  app::RunOptions o = options(scene, dir + "/run", 0.01);
  o.sets = {"output.checkpoint_minutes=1e-6"};  // 60 us: about every step
  ASSERT_EQ(app::runScene(o), app::kSuccess);
  std::ifstream log(dir + "/run/log.txt");
  int interval = 0, end = 0;
  for (std::string line; std::getline(log, line);) {
    if (line.find("(interval)") != std::string::npos) ++interval;
    if (line.find("(end)") != std::string::npos) ++end;
  }
  EXPECT_GT(interval, 5);
  EXPECT_EQ(end, 1);
  EXPECT_EQ(io::readCheckpoint(dir + "/run/checkpoint.h5").reason, "end");
}

TEST(Checkpoint, RestartWithAMovingPistonIsBitIdentical) {
  const std::string dir = freshDir("moorsph_restart_piston");
  const std::string scene = test::writeScene(dir + "/scene.yaml", R"(dim: 2
end_time: 0.3
resolution: {dx: 0.02}
effects: [pressure, viscosity, xsph, gravity, walls, piston, damping_zone]
geometry:
  - tank: {lower: [0, 0], upper: [1.2, 0.4]}
  - water: {lower: [0.1, 0], upper: [1.2, 0.2]}
piston: {x: 0.1, bottom: 0, top: 0.3, signal: {type: regular, wave_height: 0.04, period: 0.8, ramp_up: 0.1}}
damping_zones: [{x_start: 0.8, x_end: 1.2, k_max: 10}]
output: {interval: 0.05, checkpoint_minutes: 0}
)");
  ASSERT_EQ(app::runScene(options(scene, dir + "/straight", 0.3)), app::kSuccess);
  ASSERT_EQ(app::runScene(options(scene, dir + "/first", 0.15)), app::kSuccess);
  app::RunOptions again = options(scene, dir + "/second", 0.3);
  again.restart = dir + "/first/checkpoint.h5";
  ASSERT_EQ(app::runScene(again), app::kSuccess);
  const auto a = io::readCheckpoint(dir + "/straight/checkpoint.h5");
  const auto b = io::readCheckpoint(dir + "/second/checkpoint.h5");
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(a.steps, b.steps);
  EXPECT_EQ(countDifferences(a, b), 0u);
  // The plate's work on the water carries across the restart (it restarted at 0 before).
  const auto half = io::readCheckpoint(dir + "/first/checkpoint.h5");
  ASSERT_EQ(a.piston_work.size(), 1u);
  ASSERT_EQ(b.piston_work.size(), 1u);
  EXPECT_GT(std::abs(half.piston_work.at(0)), 0.1 * std::abs(a.piston_work[0]));  // a restart from 0 would show
  EXPECT_EQ(b.piston_work[0], a.piston_work[0]);
}

TEST(Checkpoint, RestartRejectsAnotherGeometry) {
  const std::string dir = freshDir("moorsph_restart_geometry");
  const std::string scene = test::writeScene(dir + "/scene.yaml", test::kSmallDamBreak);
  ASSERT_EQ(app::runScene(options(scene, dir + "/first", 0.02)), app::kSuccess);
  // Same particle count, tank moved: rejected before running.
  app::RunOptions moved = options(scene, dir + "/moved", 0.04);
  moved.restart = dir + "/first/checkpoint.h5";
  moved.sets = {"geometry[0].tank.upper=[0.5, 0.3]"};
  EXPECT_EQ(app::runScene(moved), app::kBadInput);
  // Written differently, same particles (the side walls' top row moves by 1e-11 m): accepted.
  app::RunOptions rewritten = options(scene, dir + "/rewritten", 0.04);
  rewritten.restart = dir + "/first/checkpoint.h5";
  rewritten.sets = {"geometry[0].tank.upper=[0.4, 0.30000000001]"};
  EXPECT_EQ(app::runScene(rewritten), app::kSuccess);
  // Restarting into the checkpoint's own directory would overwrite its series.
  app::RunOptions same = options(scene, dir + "/first", 0.04);
  same.restart = dir + "/first/checkpoint.h5";
  EXPECT_EQ(app::runScene(same), app::kBadArguments);
  // End time, output cadence and method options may change.
  app::RunOptions allowed = options(scene, "", 0.04);
  allowed.restart = dir + "/first/checkpoint.h5";
  allowed.sets = {"output.interval=0.005", "method.cfl=0.4"};
  EXPECT_EQ(app::runScene(allowed), app::kSuccess);
  EXPECT_TRUE(std::filesystem::exists(dir + "/first.restart/checkpoint.h5"));  // the default directory
  // A changed skin gives other cells: the saved list positions do not fit, and the
  // restart builds its lists afresh instead of stopping.
  app::RunOptions reskinned = options(scene, dir + "/reskinned", 0.04);
  reskinned.restart = dir + "/first/checkpoint.h5";
  reskinned.sets = {"method.skin_factor=0.4"};
  EXPECT_EQ(app::runScene(reskinned), app::kSuccess);
  std::ifstream log(dir + "/reskinned/log.txt");
  const std::string text((std::istreambuf_iterator<char>(log)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("lists are built afresh"), std::string::npos);
}

TEST(Checkpoint, RestartAfterOutflowKeepsTheTallyAndLeavesTheRemovedOut) {
  const std::string dir = freshDir("moorsph_restart_outflow");
  std::string text = test::kSmallDamBreak;
  text.replace(text.find("walls]"), 6, "walls, outflow]");
  const std::string scene = test::writeScene(dir + "/scene.yaml", text);
  ASSERT_EQ(app::runScene(options(scene, dir + "/first", 0.02)), app::kSuccess);
  // A checkpoint as a run that removed particles ids 5 and 17 writes it.
  io::Checkpoint c = io::readCheckpoint(dir + "/first/checkpoint.h5");
  const std::size_t n = c.size();
  io::Checkpoint edited = c;
  edited.r.clear(), edited.v.clear(), edited.rho.clear(), edited.m.clear(), edited.id.clear();
  double removed_mass = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    if (c.id[i] == 5 || c.id[i] == 17) {
      removed_mass += c.m[i];
      continue;
    }
    for (int d = 0; d < c.dim; ++d) edited.r.push_back(c.r[c.dim * i + d]), edited.v.push_back(c.v[c.dim * i + d]);
    edited.rho.push_back(c.rho[i]);
    edited.m.push_back(c.m[i]);
    edited.id.push_back(c.id[i]);
  }
  edited.outflow = {2.0, removed_mass, 1.5, 0.01};
  // The run's list-build positions are for the full set; without them the restart builds
  // its lists afresh (a run that removes particles rebuilds its lists in the same step).
  edited.r_at_build.clear();
  edited.boundary_r_at_build.clear();
  io::writeCheckpoint(dir + "/edited.h5", edited);

  app::RunOptions again = options(scene, dir + "/second", 0.04);
  again.restart = dir + "/edited.h5";
  ASSERT_EQ(app::runScene(again), app::kSuccess);
  const auto b = io::readCheckpoint(dir + "/second/checkpoint.h5");
  EXPECT_EQ(b.size(), n - 2);
  ASSERT_EQ(b.outflow.size(), 4u);
  EXPECT_EQ(b.outflow[0], 2.0);
  EXPECT_EQ(b.outflow[1], removed_mass);
  EXPECT_EQ(b.outflow[2], 1.5);
  for (auto id : b.id) EXPECT_TRUE(id != 5 && id != 17);

  // The scene without 'outflow' cannot continue it; nor can a checkpoint that lost
  // particles without a tally.
  app::RunOptions plain = options(test::writeScene(dir + "/plain.yaml", test::kSmallDamBreak), dir + "/plain", 0.04);
  plain.restart = dir + "/edited.h5";
  EXPECT_EQ(app::runScene(plain), app::kBadInput);
  edited.outflow.clear();
  io::writeCheckpoint(dir + "/untallied.h5", edited);
  app::RunOptions untallied = options(scene, dir + "/untallied", 0.04);
  untallied.restart = dir + "/untallied.h5";
  EXPECT_EQ(app::runScene(untallied), app::kBadInput);
}
