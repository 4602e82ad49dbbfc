#include <moorsph/cases/run_recorder.hpp>

#include <algorithm>
#include <cstdio>

namespace moorsph::cases {

template <int D>
RunRecorder<D>::RunRecorder(fluid::FluidSimulation<D>& sim, io::SeriesFile& file, double output_interval)
    : sim_(sim), file_(file), interval_(output_interval) {
  energy_series_ = file_.addSeries("energy",
                                   {{"kinetic", "J"}, {"potential", "J"}, {"elastic", "J"}, {"total", "J"},
                                    {"dt", "s"}, {"steps", "1"}, {"wall_time", "s"}},
                                   "fluid mechanical energy (potential relative to y = 0), time step, wall time");
}

template <int D>
void RunRecorder<D>::addSeries(const std::string& name, const std::vector<io::SeriesColumn>& columns, Probe probe,
                               const std::string& description) {
  probes_.push_back({file_.addSeries(name, columns, description), std::move(probe)});
}

template <int D>
void RunRecorder<D>::record() {
  const auto e = sim_.calcEnergy();
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  if (sim_.stepCount() == 0) summary_.initial_energy = e.total();
  summary_.max_energy_rise = std::max(summary_.max_energy_rise, e.total() - summary_.initial_energy);
  summary_.final_energy = e.total();
  if (timing_series_ < 0) {
    std::vector<io::SeriesColumn> columns;
    for (const auto& name : sim_.phaseTimers().names()) columns.push_back({name, "s"});
    timing_series_ = file_.addSeries("timing", columns, "accumulated wall time per phase of the step");
  }
  file_.append(timing_series_, sim_.time(), sim_.phaseTimers().seconds());
  file_.append(energy_series_, sim_.time(),
               {e.kinetic, e.potential, e.elastic, e.total(), sim_.lastDt(), static_cast<double>(sim_.stepCount()), wall});
  for (auto& p : probes_) file_.append(p.handle, sim_.time(), p.probe(sim_));
  file_.flush();
}

template <int D>
RunSummary RunRecorder<D>::runTo(double end_time, const std::function<void(const std::string&)>& log) {
  start_ = std::chrono::steady_clock::now();
  summary_.particles = sim_.fluid().size();
  record();
  double next_output = sim_.time() + interval_;
  try {
    while (sim_.time() < end_time - 1e-12) {
      sim_.step();
      if (sim_.time() >= next_output - 1e-12) {
        record();
        next_output += interval_;
        if (log) {
          char line[160];
          const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
          std::snprintf(line, sizeof line, "t = %.4f s  steps = %zu  dt = %.3e s  wall = %.1f s", sim_.time(),
                        sim_.stepCount(), sim_.lastDt(), wall);
          log(line);
        }
      }
    }
  } catch (const fluid::SimulationError& e) {
    summary_.error = e.what();
    file_.flush();
    if (log) log(std::string("run stopped: ") + e.what());
  }
  summary_.simulated_time = sim_.time();
  summary_.steps = sim_.stepCount();
  summary_.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  return summary_;
}

template class RunRecorder<2>;
template class RunRecorder<3>;

}  // namespace moorsph::cases
