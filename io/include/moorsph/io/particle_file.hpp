#pragma once
// Particle snapshots for ParaView: particles.h5 holds one group per output time,
//   /snapshots/000000/{position (N,3) m, velocity (N,3) m/s, pressure (N) Pa,
//                      density (N) kg/m^3, type (N) 0 fluid 1 boundary, id (N)}
// with a `time` attribute [s] on each group, plus /polyvertex/N (0..N-1, the vertex
// cells of an N-particle grid), and particles.xmf (XDMF 2) lists them as a temporal
// collection of point grids, so ParaView opens particles.xmf directly (checked with
// tools/check_paraview.py).
// Positions are padded to three components in 2D (z = 0), which every XDMF reader
// understands. Fluid particles come first, in id order (stable across re-sorts and
// restarts), then the boundary particles. The HDF5 file is flushed and the XDMF file
// rewritten atomically (write, then rename) at every snapshot, so a run that is
// killed leaves both readable up to its last snapshot.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>
#include <moorsph/fluid/fluid_simulation.hpp>

namespace moorsph::io {

/// One snapshot as plain arrays (3 components per vector whatever the dimension).
struct ParticleSnapshot {
  double time = 0.0;
  std::vector<double> position, velocity;  ///< 3 N [m], [m/s]
  std::vector<double> pressure, density;   ///< N [Pa], [kg/m^3]
  std::vector<std::int32_t> type;          ///< 0 fluid, 1 boundary
  std::vector<std::int64_t> id;
  std::size_t size() const { return type.size(); }
};

/// The simulation's particles at its current time; pressure from the equation of
/// state at the current density.
template <int D>
ParticleSnapshot takeSnapshot(const fluid::FluidSimulation<D>& sim);

class ParticleFile {
 public:
  /// Create (truncate) dir/particles.h5 and dir/particles.xmf.
  explicit ParticleFile(const std::string& directory);
  ~ParticleFile();
  ParticleFile(const ParticleFile&) = delete;
  ParticleFile& operator=(const ParticleFile&) = delete;

  void write(const ParticleSnapshot& snapshot);
  std::size_t count() const { return entries_.size(); }

 private:
  void writeXdmf() const;
  void writePolyvertex(std::size_t n);

  struct Entry {
    std::string group;
    double time;
    std::size_t n;
  };
  std::string directory_;
  long long file_ = -1;  // hid_t
  std::vector<Entry> entries_;
};

}  // namespace moorsph::io
