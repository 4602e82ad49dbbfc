#pragma once
// The moorsph subcommands as functions, so tests can call them in-process:
//   run:    load the scene, build it (or restore a checkpoint), run it, write the
//           run directory (series.h5, particles.h5/.xmf, scene.resolved.yaml,
//           log.txt, checkpoint.h5), return an ExitCode.
//   check:  validate and report counts, dx, h, c_s, dt, steps, cost estimates.
//   export: series.h5 -> csv/<group>.<name>.csv.
#include <cstddef>
#include <functional>
#include <string>
#include <vector>
#include "exit_codes.hpp"

namespace moorsph::app {

struct RunOptions {
  std::string scene;                 ///< scene file (YAML)
  std::string out;                   ///< run directory; "" = moorsph-output/<scene name>
  int threads = 0;                   ///< OpenMP threads; 0 = OMP_NUM_THREADS or all cores
  double end = 0.0;                  ///< end time [s] overriding the scene's; 0 = the scene's
  std::vector<std::string> sets;     ///< "key.path=value" overrides
  std::string restart;               ///< checkpoint to continue from
  double log_interval = 10.0;        ///< [s] of wall time between progress lines when not on a terminal
  /// Test hook, called after every step with the step count.
  std::function<void(std::size_t)> after_step;
};

int runScene(const RunOptions& options);
int checkScene(const std::string& scene, const std::vector<std::string>& sets, int threads);
int exportRun(const std::string& directory);
/// PNG plots of every series of DIR/series.h5 in DIR/plots (needs /usr/bin/python3
/// with h5py and matplotlib; MOORSPH_PYTHON overrides the interpreter).
int plotRun(const std::string& directory);

/// What SIGINT/SIGTERM do once the scene steps: ask it to stop after its current step
/// (with a checkpoint). During the set-up a signal stops the program at once.
void requestStop();

}  // namespace moorsph::app
