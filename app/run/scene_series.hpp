#pragma once
// The time series a scene's sensors add to series.h5: /gauges (one column per wave
// gauge: free-surface height y [m]) and /probes (per pressure probe, the pressure
// from the wall reactions and the SPH-interpolated one [Pa]), /velocity_probes (per
// velocity probe its components vx, vy (, vz) [m/s], NaN while the point is dry),
// /packing_probes (per packing probe the mean and spread of xi over its box's wet points
// and their fraction [-]) and
// /outflow (spray removed by the outflow effect: count, mass, energy carried out),
// /piston (the plate's displacement, velocity, the fluid's force on it and the work it
// has done on the water).
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>
#include <moorsph/cases/run_recorder.hpp>
#include <moorsph/fluid/piston.hpp>
#include <moorsph/io/scene_builder.hpp>
#include "moving_mean.hpp"

namespace moorsph::app {

template <int D>
class SceneSeries {
 public:
  /// `note` receives the notices a run's log should carry (a packing probe's rise).
  SceneSeries(const fluid::FluidSimulation<D>& sim, const io::BuiltScene<D>& built,
              std::function<void(const std::string&)> note = {})
      : note_(std::move(note)),
        names_(built.gauge_names),
        piston_(sim.template findEffect<fluid::Piston<D>>()),
        outflow_(sim.outflow()),
        plate_(built.piston_surface) {
    for (const auto& g : built.gauges) gauges_.emplace_back(g);
    for (std::size_t k = 0; k < built.probes.size(); ++k) {
      try {
        probes_.emplace_back(built.probes[k], *sim.walls());
      } catch (const std::invalid_argument& e) {
        throw std::invalid_argument("pressure probe '" + built.probe_names[k] + "': " + e.what());
      }
    }
    probe_names_ = built.probe_names;
    for (const auto& v : built.velocity_probes) velocity_probes_.emplace_back(v);
    velocity_probe_names_ = built.velocity_probe_names;
    for (std::size_t k = 0; k < built.packing_probes.size(); ++k)
      packing_.push_back({built.packing_probe_names[k], fluid::PackingProbe<D>(built.packing_probes[k]),
                          built.packing_warn_rises[k], std::numeric_limits<double>::quiet_NaN(), false});
    for (std::size_t k = 0; k < built.probes.size(); ++k) {
      const double window = k < built.probe_means.size() ? built.probe_means[k] : 0.0;
      means_.push_back({MovingMean(window), MovingMean(window), window > 0.0});
    }
  }

  void attach(cases::RunRecorder<D>& recorder) {
    if (outflow_) {
      const char* per = D == 2 ? "/m" : "";
      recorder.addSeries("outflow",
                         {{"particles", "1"}, {"mass", std::string("kg") + per}, {"energy", std::string("J") + per}},
                         [this](const fluid::FluidSimulation<D>&) {
                           const fluid::OutflowTally& t = outflow_->tally();
                           return std::vector<double>{static_cast<double>(t.particles), t.mass, t.energy};
                         },
                         "outflow: fluid particles removed since the start after leaving the domain above the walls, "
                         "their mass, and the kinetic + potential + elastic energy they carried out");
    }
    if (piston_) {
      const char* per = D == 2 ? "/m" : "";
      recorder.addSeries("piston",
                         {{"displacement", "m"}, {"velocity", "m/s"}, {"force", std::string("N") + per},
                          {"work", std::string("J") + per}},
                         [this](const fluid::FluidSimulation<D>& s) {
                           const double force = s.walls()->calcSurfaceWrench(plate_, fluid::Vec<D>::Zero()).force[0];
                           return std::vector<double>{piston_->displacement(),
                                                      s.walls()->surfaceMotion(plate_).velocity[0], force, piston_->work()};
                         },
                         "piston wave maker: displacement X and velocity of the plate, x-force of the fluid on it, "
                         "work it has done on the water since the run started (carried across restarts)");
    }
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
      for (std::size_t k = 0; k < probe_names_.size(); ++k) {
        const std::string& n = probe_names_[k];
        columns.push_back({n + "_reaction", "Pa"});
        columns.push_back({n + "_interpolated", "Pa"});
        if (means_[k].on) {
          columns.push_back({n + "_reaction_mean", "Pa"});
          columns.push_back({n + "_interpolated_mean", "Pa"});
        }
      }
      recorder.addSeries("probes", columns,
                         [this](const fluid::FluidSimulation<D>& s) {
                           std::vector<double> v;
                           for (std::size_t k = 0; k < probes_.size(); ++k) {
                             v.push_back(probes_[k].readReaction(s));
                             v.push_back(probes_[k].readInterpolated(s));
                             if (means_[k].on) {
                               const double reaction = v[v.size() - 2], interpolated = v.back();
                               v.push_back(means_[k].reaction.add(s.time(), reaction));
                               v.push_back(means_[k].interpolated.add(s.time(), interpolated));
                             }
                           }
                           return v;
                         },
                         "wall pressure probes: from the boundary reactions and SPH-interpolated in front of the wall; "
                         "*_mean: trailing moving mean over pressure_probes[].moving_mean of the recorded outputs");
    }
    if (!velocity_probes_.empty()) {
      std::vector<io::SeriesColumn> columns;
      const char* axes[3] = {"_vx", "_vy", "_vz"};
      for (const auto& n : velocity_probe_names_)
        for (int a = 0; a < D; ++a) columns.push_back({n + axes[a], "m/s"});
      recorder.addSeries("velocity_probes", columns,
                         [this](const fluid::FluidSimulation<D>& s) {
                           std::vector<double> v;
                           for (const auto& p : velocity_probes_) {
                             const fluid::Vec<D> u = p.read(s);
                             v.insert(v.end(), u.data(), u.data() + D);
                           }
                           return v;
                         },
                         "velocity probes: SPH-interpolated (Shepard) fluid velocity at a fixed point; NaN where the "
                         "particle density there is below min_fill (dry)");
    }
    if (!packing_.empty()) attachPacking(recorder);
  }

 private:
  void attachPacking(cases::RunRecorder<D>& recorder) {
    std::vector<io::SeriesColumn> columns;
    for (const auto& p : packing_) {
      columns.push_back({p.name + "_xi_mean", "1"});
      columns.push_back({p.name + "_xi_spread", "1"});
      columns.push_back({p.name + "_wet_fraction", "1"});
    }
    recorder.addSeries("packing_probes", columns,
                       [this](const fluid::FluidSimulation<D>& s) {
                         std::vector<double> v;
                         for (auto& p : packing_) {
                           const fluid::PackingReading r = p.probe.read(s);
                           watchPacking(p, r.mean, s.time());
                           v.insert(v.end(), {r.mean, r.spread, r.wet_fraction});
                         }
                         return v;
                       },
                       "packing probes: mean and standard deviation of the particle density xi = sum_j (m_j/rho_j) W "
                       "over the box's grid points with xi >= min_fill, and their fraction of the points; a mean rising "
                       "above its start value means the particles pack closer than their densities say (the particle "
                       "surface then stands lower than the water's volume by about depth x the rise)");
  }

  /// Notes once when a probe's mean xi has risen `rise` above its first reading: the
  /// particles pack closer than their densities say, and the surface sits low
  /// (docs/scene-reference.md, packing_probes).
  struct Packing;
  void watchPacking(Packing& w, double mean, double time) {
    if (std::isnan(w.first)) w.first = mean;
    if (w.noted || !(w.rise > 0.0) || !(mean - w.first >= w.rise) || !note_) return;
    w.noted = true;
    char text[400];
    std::snprintf(text, sizeof text,
                  "note: packing probe '%s': mean xi %.4f at t = %.6g s, %.2f%% above its first reading %.4f: the "
                  "particles pack closer than their densities say, so water levels and floating bodies nearby read low "
                  "by about the water depth x %.4f",
                  w.name.c_str(), mean, time, 100.0 * (mean - w.first), w.first, mean - w.first);
    note_(text);
  }

  std::function<void(const std::string&)> note_;
  std::vector<std::string> names_;
  const fluid::Piston<D>* piston_;
  const fluid::Outflow<D>* outflow_;
  std::size_t plate_;
  std::vector<fluid::WaveGauge<D>> gauges_;
  std::vector<std::string> probe_names_;
  std::vector<fluid::PressureProbe<D>> probes_;
  std::vector<std::string> velocity_probe_names_;
  std::vector<fluid::VelocityProbe<D>> velocity_probes_;
  struct Packing {
    std::string name;
    fluid::PackingProbe<D> probe;
    double rise;   ///< rise of the mean that the log notes; 0: never
    double first;  ///< the run's first reading (NaN before it)
    bool noted;
  };
  std::vector<Packing> packing_;
  struct Means {
    MovingMean reaction, interpolated;
    bool on;
  };
  std::vector<Means> means_;
};

}  // namespace moorsph::app
