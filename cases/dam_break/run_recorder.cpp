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
RunSummary RunRecorder<D>::runTo(double end_time, const std::function<void(const std::string&)>& log,
                                 const RunControl& control) {
  start_ = std::chrono::steady_clock::now();
  summary_.particles = sim_.fluid().size();
  stopped_ = false;
  next_output_ = control.next_output;
  const double eps = 1e-12;
  auto outputTime = [&](long long k) { return static_cast<double>(k) * interval_; };
  if (sim_.time() >= outputTime(next_output_) - eps) {
    record();
    if (control.on_output) control.on_output();
    while (outputTime(next_output_) <= sim_.time() + eps) ++next_output_;
  }
  try {
    while (sim_.time() < end_time - eps) {
      const bool stop = control.stop_requested && control.stop_requested();
      const bool checkpoint = stop || (control.checkpoint_due && control.checkpoint_due());
      sim_.step();
      if (control.on_step) control.on_step();
      if (sim_.time() >= outputTime(next_output_) - eps) {
        record();
        while (outputTime(next_output_) <= sim_.time() + eps) ++next_output_;
        if (control.on_output) control.on_output();
        if (log) {
          char line[160];
          const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
          std::snprintf(line, sizeof line, "t = %.4f s  steps = %zu  dt = %.3e s  wall = %.1f s", sim_.time(),
                        sim_.stepCount(), sim_.lastDt(), wall);
          log(line);
        }
      }
      if (checkpoint && control.on_checkpoint) control.on_checkpoint();
      if (stop) {
        stopped_ = true;
        break;
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
