#pragma once
// The time series a scene's sensors add to series.h5: /gauges (one column per wave
// gauge: free-surface height y [m]) and /probes (per pressure probe, the pressure
// from the wall reactions and the SPH-interpolated one [Pa]).
#include <stdexcept>
#include <string>
#include <vector>
#include <moorsph/cases/run_recorder.hpp>
#include <moorsph/io/scene_builder.hpp>

namespace moorsph::app {

template <int D>
class SceneSeries {
 public:
  SceneSeries(const fluid::FluidSimulation<D>& sim, const io::BuiltScene<D>& built) : names_(built.gauge_names) {
    for (const auto& g : built.gauges) gauges_.emplace_back(g);
    for (std::size_t k = 0; k < built.probes.size(); ++k) {
      try {
        probes_.emplace_back(built.probes[k], *sim.walls());
      } catch (const std::invalid_argument& e) {
        throw std::invalid_argument("pressure probe '" + built.probe_names[k] + "': " + e.what());
      }
    }
    probe_names_ = built.probe_names;
  }

  void attach(cases::RunRecorder<D>& recorder) {
    if (!gauges_.empty()) {
      std::vector<io::SeriesColumn> columns;
      for (const auto& n : names_) columns.push_back({n, "m"});
      recorder.addSeries("gauges", columns,
                         [this](const fluid::FluidSimulation<D>& s) {
                           std::vector<double> v;
                           for (const auto& g : gauges_) v.push_back(g.read(s));
                           return v;
                         },
                         "wave gauges: free-surface height y (METHOD.md section 3)");
    }
    if (!probes_.empty()) {
      std::vector<io::SeriesColumn> columns;
      for (const auto& n : probe_names_) {
        columns.push_back({n + "_reaction", "Pa"});
        columns.push_back({n + "_interpolated", "Pa"});
      }
      recorder.addSeries("probes", columns,
                         [this](const fluid::FluidSimulation<D>& s) {
                           std::vector<double> v;
                           for (const auto& p : probes_) {
                             v.push_back(p.readReaction(s));
                             v.push_back(p.readInterpolated(s));
                           }
                           return v;
                         },
                         "wall pressure probes: from the boundary reactions and SPH-interpolated in front of the wall");
    }
  }

 private:
  std::vector<std::string> names_;
  std::vector<fluid::WaveGauge<D>> gauges_;
  std::vector<std::string> probe_names_;
  std::vector<fluid::PressureProbe<D>> probes_;
};

}  // namespace moorsph::app
