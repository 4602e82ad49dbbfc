#pragma once
// Progress of a run. On a terminal: one line rewritten in place at most every 0.5 s
// (simulated time, steps/s, real-time factor, ETA). Otherwise (a pipe, a batch job):
// a log line every `log_interval` seconds of wall time.
#include <chrono>
#include <string>
#include <vector>
#include "run_log.hpp"

namespace moorsph::app {

class Progress {
 public:
  Progress(RunLog& log, double start_time, double end_time, double log_interval = 10.0);
  /// Call after every step; cheap unless it is time to print.
  void update(double time, std::size_t steps, double dt);
  /// Erase the terminal line before other output.
  void clear();
  bool onTerminal() const { return tty_; }
  /// "t = ... s (..%), ... steps/s, real-time factor ..., ETA ..."
  std::string describe(double time, std::size_t steps, double dt) const;

 private:
  RunLog& log_;
  double start_time_, end_time_, log_interval_;
  bool tty_;
  bool line_shown_ = false;
  std::size_t start_steps_ = 0;
  bool started_ = false;
  std::chrono::steady_clock::time_point wall_start_, last_print_, last_logged_;
};

/// Where a run's wall time went, for its last log line: "time by phase (2443 s wall):
/// pairs 1198 s (49%), neighbours 972 s (40%), ..., other 23 s (1%)". Phases are listed
/// largest first; those under 1% of the wall time are summed into "other", with the time
/// no phase counts (output, progress).
std::string describePhases(const std::vector<std::string>& names, const std::vector<double>& seconds, double wall);

}  // namespace moorsph::app
