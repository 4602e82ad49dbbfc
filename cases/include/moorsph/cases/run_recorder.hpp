#pragma once
// Runs a fluid simulation to an end time and records, at a fixed output interval,
// the time series every run has (energy terms, dt, particle count, wall time) plus
// a scene's own probes, into series.h5. Output k is written at the first step that
// reaches t = k x interval. Output is flushed at every output time, so a
// run that stops early keeps what it wrote.
#include <chrono>
#include <functional>
#include <string>
#include <vector>
#include <moorsph/fluid/fluid_simulation.hpp>
#include <moorsph/io/series_file.hpp>

namespace moorsph::cases {

struct RunSummary {
  double simulated_time = 0.0;  ///< [s]
  std::size_t steps = 0;
  double wall_seconds = 0.0;
  std::size_t particles = 0;
  double initial_energy = 0.0;     ///< [J]
  double max_energy_rise = 0.0;    ///< max over outputs of E(t) - E(0) [J]
  double final_energy = 0.0;       ///< [J]
  std::string error;               ///< non-empty if the run stopped on a SimulationError
};

/// Hooks of a run driven by the moorsph command (checkpoints, snapshots, progress,
/// Ctrl-C). Every member is optional; a default RunControl is a plain run.
struct RunControl {
  /// Called after each time-series row is written (particle snapshots hang here).
  std::function<void()> on_output;
  /// Called after every step (progress display).
  std::function<void()> on_step;
  /// Polled before each step: true asks for a checkpoint after that step.
  std::function<bool()> checkpoint_due;
  /// Polled before each step: true stops the run after that step, with a checkpoint.
  std::function<bool()> stop_requested;
  /// Writes a checkpoint; called right after the step (the checkpoint carries the
  /// positions of the last list build, so no rebuild is needed before it).
  std::function<void()> on_checkpoint;
  /// Index of the next output: output k is at t = k x interval. A fresh run records
  /// output 0 at its start; a restart passes the index saved in its checkpoint.
  long long next_output = 0;
};

template <int D>
class RunRecorder {
 public:
  using Probe = std::function<std::vector<double>(const fluid::FluidSimulation<D>&)>;

  RunRecorder(fluid::FluidSimulation<D>& sim, io::SeriesFile& file, double output_interval);
  /// Record one more series; `probe` returns one value per column at each output.
  void addSeries(const std::string& name, const std::vector<io::SeriesColumn>& columns, Probe probe,
                 const std::string& description = "");
  /// Run to end_time. A SimulationError stops the run: it is reported in the summary
  /// (and printed by `log` if given) after the output written so far is flushed.
  RunSummary runTo(double end_time, const std::function<void(const std::string&)>& log = {},
                   const RunControl& control = {});
  /// Index of the next output time (what a checkpoint saves).
  long long nextOutputIndex() const { return next_output_; }
  /// True if the last runTo stopped on stop_requested before the end time.
  bool stoppedEarly() const { return stopped_; }

 private:
  void record();

  fluid::FluidSimulation<D>& sim_;
  io::SeriesFile& file_;
  double interval_;
  int energy_series_;
  int timing_series_ = -1;
  struct Entry {
    int handle;
    Probe probe;
  };
  std::vector<Entry> probes_;
  RunSummary summary_;
  long long next_output_ = 0;
  bool stopped_ = false;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace moorsph::cases
