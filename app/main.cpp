// moorsph: run a scene and write its results.
//   moorsph run SCENE.yaml [--out DIR] [--threads N] [--end T] [--set key=value ...] [--restart CKPT]
//   moorsph check SCENE.yaml      validate and estimate the cost
//   moorsph export DIR --csv      time series as CSV files
//   moorsph plot DIR              time series as PNG plots
//   moorsph study SCENE.yaml --dx LIST --metric NAME   accuracy against cost (app/study/)
// With no subcommand it runs the built-in demo scene, a coarse tethered buoy release
// (3D, a few minutes on 2 cores), plots it and says where its output went (the
// README's first command relies on this).
#include <CLI/CLI.hpp>
#include <omp.h>

#include <cstdio>
#include <filesystem>
#include <string>
#include <fstream>
#include "run/demo_scene.hpp"
#include "run/run_scene.hpp"
#include "study/study_cli.hpp"

namespace {

struct DemoOptions {
  std::string out = "moorsph-output/demo_buoy_release";
  double end = 0.0;  ///< 0: the demo scene's
  double dx = 0.0;   ///< 0: the demo scene's
  int threads = 0;
};

/// The built-in demo (run/demo_scene.hpp): written to <out>/demo_scene.yaml, run like
/// any scene, then plotted into <out>/plots.
int runDemo(const DemoOptions& o) {
  using namespace moorsph::app;
  std::filesystem::create_directories(o.out);
  const std::string scene = o.out + "/demo_scene.yaml";
  std::ofstream(scene) << kDemoScene;
  std::printf("moorsph demo: a tethered buoy (R = 0.1015 m, 1.745 kg) pulled 6 cm under and released, 3D, coarse\n"
              "  scene: %s\n", std::filesystem::absolute(scene).c_str());
  RunOptions run;
  run.scene = scene;
  run.out = o.out;
  run.threads = o.threads;
  run.end = o.end;
  if (o.dx > 0.0) {
    char dx[32];
    std::snprintf(dx, sizeof dx, "%.17g", o.dx);  // every digit: std::to_string keeps six decimals
    run.sets.push_back(std::string("resolution.dx=") + dx);
  }
  const int code = runScene(run);
  if (code != kSuccess) return code;
  const int plotted = plotRun(o.out);
  std::printf("output: %s (series.h5, particles.xmf for ParaView, log.txt%s)\n",
              std::filesystem::absolute(o.out).c_str(), plotted == kSuccess ? ", plots/*.png" : "");
  std::printf("  look at plots/body_buoy.png (heave y), plots/line_tether.png (tension), plots/ledger.png (energy)\n");
  return kSuccess;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace moorsph::app;
  CLI::App app{"moorsph: SPH simulation of moored floating bodies in waves"};
  app.require_subcommand(0, 1);
  DemoOptions demo;
  app.add_option("--out", demo.out, "output directory of the demo");
  app.add_option("--end", demo.end, "simulated end time of the demo [s]")->check(CLI::PositiveNumber);
  app.add_option("--dx", demo.dx, "particle spacing of the demo [m]")->check(CLI::PositiveNumber);
  app.add_option("--threads", demo.threads, "OpenMP threads (0: OMP_NUM_THREADS or all cores)");

  RunOptions run;
  CLI::App* run_cmd = app.add_subcommand("run", "run a scene file (docs/scene-reference.md)");
  run_cmd->add_option("scene", run.scene, "scene file (YAML)")->required()->check(CLI::ExistingFile);
  run_cmd->add_option("--out", run.out, "run directory (default moorsph-output/<scene name>; for a restart, <checkpoint dir>.restart)");
  run_cmd->add_option("--threads", run.threads, "OpenMP threads (0: OMP_NUM_THREADS or all cores)")->check(CLI::NonNegativeNumber);
  run_cmd->add_option("--end", run.end, "simulated end time [s], overriding end_time")->check(CLI::PositiveNumber);
  run_cmd->add_option("--set", run.sets, "override a scene key: key.path=value (repeatable), e.g. --set resolution.dx=0.01")
      ->allow_extra_args(false);  // one value per --set, so a scene path after it stays positional
  run_cmd->add_option("--restart", run.restart, "continue from a checkpoint (bit-identical at the same thread count)")
      ->check(CLI::ExistingFile);

  std::string check_scene;
  std::vector<std::string> check_sets;
  int check_threads = 0;
  CLI::App* check_cmd = app.add_subcommand("check", "validate a scene and estimate particles, steps, wall time and memory");
  check_cmd->add_option("scene", check_scene, "scene file (YAML)")->required()->check(CLI::ExistingFile);
  check_cmd->add_option("--set", check_sets, "override a scene key: key.path=value (repeatable)")->allow_extra_args(false);
  check_cmd->add_option("--threads", check_threads, "OpenMP threads for the timed sample");

  std::string export_dir;
  bool export_csv = false;
  CLI::App* export_cmd = app.add_subcommand("export", "write the time series of a run directory as CSV files");
  export_cmd->add_option("dir", export_dir, "run directory")->required()->check(CLI::ExistingDirectory);
  export_cmd->add_flag("--csv", export_csv, "write DIR/csv/<group>.<name>.csv (time first, SI units in the header)")->required();

  std::string plot_dir;
  CLI::App* plot_cmd = app.add_subcommand("plot", "PNG plots of every time series of a run directory (DIR/plots/<group>.png)");
  plot_cmd->add_option("dir", plot_dir, "run directory")->required()->check(CLI::ExistingDirectory);

  study::StudyOptions study_options;
  CLI::App* study_cmd = study::addStudyCommand(app, study_options);

  app.footer(
      "Exit codes: 0 success, 1 bad arguments, 2 bad input (scene or checkpoint rejected), 3 the run stopped on a "
      "numerical failure (failure checkpoint and diagnostic written), 4 output could not be written (or plotting unavailable), 130 interrupted "
      "(SIGINT/SIGTERM; checkpoint written, unless it came during the set-up).");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 1;
  }
  if (*run_cmd) return runScene(run);
  if (*check_cmd) return checkScene(check_scene, check_sets, check_threads);
  if (*export_cmd) return exportRun(export_dir);
  if (*plot_cmd) return plotRun(plot_dir);
  if (*study_cmd) return study::runStudy(study_options);
  try {
    return runDemo(demo);
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  }
}
