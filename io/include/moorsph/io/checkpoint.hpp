#pragma once
// Checkpoints: everything a run needs to continue bit-identically (same thread count).
// The fluid state arrays are saved in their storage order (sorted by cell at the last
// neighbour rebuild), with the positions that rebuild saw, so the restart rebuilds the
// same lists (NeighbourSearch::restore) and the run needs no extra rebuild before a
// checkpoint; with the clock, the output counters and the resolved scene. The boundary
// is rebuilt from the scene on restart, so a restart may change what does not alter the
// particle set (end time, output cadence). Written atomically: to PATH.tmp, then renamed.
//
// File layout (HDF5): attributes dim, time [s], last_dt [s], steps, next_output,
// next_snapshot, scene (YAML text), reason; datasets r (N,D) [m], v (N,D) [m/s],
// rho (N) [kg/m^3], m (N) [kg], id (N); r_at_build (N,D) and boundary_r_at_build
// (NB,D) [m], the positions of the last list build (absent in checkpoints written before
// session 35: such a restart builds its lists afresh); with bodies, "bodies": the
// multibody state (bodies::SystemSnapshot packed into numbers by the app, SI units);
// scene_fluid_count: the fluid particles the scene built at the run's start (absent before
// session 38), so a restart of the same scene need not build its water again.
#include <cstdint>
#include <string>
#include <vector>
#include <moorsph/fluid/fluid_simulation.hpp>

namespace moorsph::io {

struct Checkpoint {
  int dim = 2;
  double time = 0.0;
  double last_dt = 0.0;
  std::int64_t steps = 0;
  std::int64_t next_output = 0;    ///< index of the next time-series output
  std::int64_t next_snapshot = 0;  ///< index of the next particle snapshot
  std::string scene_yaml;
  std::string reason;              ///< "end", "interval", "interrupt", "failure"
  std::vector<double> r, v, rho, m;  ///< r and v hold D values per particle
  std::vector<std::int64_t> id;
  /// Positions of the last neighbour-list build, D values per particle (fluid; boundary
  /// particles); empty if the run had not built lists or the file predates them.
  std::vector<double> r_at_build, boundary_r_at_build;
  std::vector<double> bodies;        ///< packed multibody state; empty without bodies
  /// The outflow's tally (particles, mass, energy, first time); empty when nothing left.
  std::vector<double> outflow;
  /// The piston's work on the water so far [J]; empty without a piston.
  std::vector<double> piston_work;
  /// Fluid particles the scene built at the run's start (the saved ones plus those the
  /// outflow removed); 0 when unknown (files written before session 38).
  std::int64_t scene_fluid_count = 0;
  std::size_t size() const { return rho.size(); }
};

template <int D>
Checkpoint captureCheckpoint(const fluid::FluidSimulation<D>& sim);

/// The saved fluid particles, in their saved order, for the simulation's constructor.
template <int D>
fluid::FluidParticles<D> restoreParticles(const Checkpoint& checkpoint);

/// Restore what the effects accumulate over a run: the outflow's tally (throws
/// std::runtime_error if the checkpoint's run removed particles but `sim` has no outflow
/// effect) and the piston's work.
template <int D>
void restoreEffectTotals(const Checkpoint& checkpoint, fluid::FluidSimulation<D>& sim);

/// Give a restarted simulation the lists its run had (FluidSimulation::restoreNeighbourLists).
/// Returns false for a checkpoint without build positions, or with positions that do not
/// fit (the restart changed the smoothing length or the skin, and with them the cells, or
/// the number of boundary particles, e.g. a body sampled by another version); the restart
/// then builds its lists afresh and does not continue bit-identically.
template <int D>
bool restoreNeighbourLists(const Checkpoint& checkpoint, fluid::FluidSimulation<D>& sim);

/// Write to `path` atomically. Throws std::runtime_error on failure.
void writeCheckpoint(const std::string& path, const Checkpoint& checkpoint);
/// Throws std::runtime_error naming the path if it is missing or not a checkpoint.
Checkpoint readCheckpoint(const std::string& path);

}  // namespace moorsph::io
