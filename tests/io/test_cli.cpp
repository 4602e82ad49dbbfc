// The moorsph command as a user runs it: check's report, exit codes, --set before the
// scene path, export, and the progress line's contents.
#include <gtest/gtest.h>

#include "run_support.hpp"
#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include "run/progress.hpp"

namespace {

using Result = moorsph::test_support::CliResult;

Result run(const std::string& arguments) { return moorsph::test_support::runMoorsph(arguments); }

std::string source() { return std::getenv("MOORSPH_SOURCE_DIR") ? std::getenv("MOORSPH_SOURCE_DIR") : "."; }

}  // namespace

TEST(Cli, CheckReportsCountsStepsAndCosts) {
  const Result r = run("check " + source() + "/cases/dam_break_2d.yaml --threads 1 --set resolution.dx=0.01");
  ASSERT_EQ(r.code, 0) << r.output;
  for (const char* expected : {"particles: 200 fluid, 280 boundary", "dx = 0.01 m", "h = 0.012 m", "c_s = 28 m/s",
                               "dt <= 2.1428e-04 s", "at least 4667 steps", "estimated wall time", "memory:",
                               "effects: pressure viscosity xsph gravity walls"})
    EXPECT_NE(r.output.find(expected), std::string::npos) << expected << "\n" << r.output;
  const Result flume = run("check " + source() + "/cases/piston_flume_2d.yaml --threads 1");
  ASSERT_EQ(flume.code, 0) << flume.output;
  EXPECT_NE(flume.output.find("piston: H = 0.03 m, T = 1.2 s, d = 0.3 m: stroke 0.02883 m"), std::string::npos)
      << flume.output;
  EXPECT_NE(flume.output.find("effects: pressure viscosity xsph gravity walls piston damping_zone"), std::string::npos);
}

TEST(Cli, ExitCodes) {
  const std::string dir = testing::TempDir() + "moorsph_cli";
  std::filesystem::remove_all(dir);
  // --set before the scene path, then a value out of range: bad input, nothing run.
  Result r = run("run --set resolution.dx=-1 " + source() + "/cases/dam_break_2d.yaml --out " + dir);
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("--set resolution.dx: 'resolution.dx': expected a particle spacing > 0 [m]"), std::string::npos)
      << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir + "/series.h5"));
  EXPECT_EQ(run("run").code, 1);                        // no scene
  EXPECT_EQ(run("frobnicate").code, 1);                 // no such subcommand
  EXPECT_EQ(run("export " + dir + " --csv").code, 1);   // no such directory (argument check)
  std::filesystem::create_directories(dir);
  EXPECT_EQ(run("export " + dir + " --csv").code, 2);   // not a run directory
  // A short run, then export.
  r = run("run " + source() + "/cases/dam_break_2d.yaml --end 0.02 --threads 1 --out " + dir +
          " --set resolution.dx=0.01 --set output.particles_interval=0");
  ASSERT_EQ(r.code, 0) << r.output;
  EXPECT_NE(r.output.find("output: "), std::string::npos) << r.output;
  r = run("export " + dir + " --csv");
  EXPECT_EQ(r.code, 0) << r.output;
  EXPECT_TRUE(std::filesystem::exists(dir + "/csv/gauges.G_mid.csv"));
}

TEST(Cli, ProgressLineSaysWhereTheRunIs) {
  moorsph::app::RunLog log(testing::TempDir() + "progress_log.txt");
  moorsph::app::Progress progress(log, 0.0, 2.0);
  const std::string line = progress.describe(0.5, 1000, 1e-4);
  for (const char* expected : {"t = 0.5000 / 2 s", "( 25%)", "steps/s", "dt = 1.00e-04 s", "real-time factor", "ETA"})
    EXPECT_NE(line.find(expected), std::string::npos) << expected << " in " << line;
}

TEST(Cli, PhaseLineListsTheLargestPhasesFirstAndTheRestAsOther) {
  // 200 s of wall: pairs 120 s (60%), neighbours 50 s (25%), walls 20 s (10%), checks 1 s
  // (0.5%, into "other"), leaving 200 - 190 = 10 s (5%) as "other".
  const std::string line = moorsph::app::describePhases({"neighbours", "walls", "pairs", "checks"}, {50.0, 20.0, 120.0, 1.0}, 200.0);
  EXPECT_EQ(line, "time by phase (200 s wall): pairs 120 s (60%), neighbours 50.0 s (25%), walls 20.0 s (10%), other 10.0 s (5%)");
  // Timers that overrun the wall (a restart counts its list restore before the run) leave no negative rest.
  EXPECT_EQ(moorsph::app::describePhases({"pairs"}, {12.0}, 10.0), "time by phase (10.0 s wall): pairs 12.0 s (120%), other 0.000 s (0%)");
}

TEST(Cli, PlotWritesPngPerSeries) {
  if (std::system("/usr/bin/python3 -c 'import h5py, matplotlib' > /dev/null 2>&1") != 0)
    GTEST_SKIP() << "/usr/bin/python3 lacks h5py or matplotlib (python3-h5py, python3-matplotlib)";
  const std::string dir = testing::TempDir() + "moorsph_plot";
  std::filesystem::remove_all(dir);
  Result r = run("run " + source() + "/cases/dam_break_2d.yaml --end 0.02 --threads 1 --out " + dir +
                 " --set resolution.dx=0.01 --set output.particles_interval=0");
  ASSERT_EQ(r.code, 0) << r.output;
  r = run("plot " + dir);
  ASSERT_EQ(r.code, 0) << r.output;
  for (const char* group : {"energy", "timing", "gauges", "probes"}) {
    std::ifstream png(dir + "/plots/" + group + ".png", std::ios::binary);
    char magic[8] = {};
    png.read(magic, 8);
    EXPECT_EQ(std::string(magic + 1, 3), "PNG") << group;
  }
  std::filesystem::create_directories(dir + "/empty");
  EXPECT_EQ(run("plot " + dir + "/empty").code, 2);
}
