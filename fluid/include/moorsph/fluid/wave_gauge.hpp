#pragma once
// A wave gauge: a vertical line sensor at a fixed horizontal position that reports
// the free-surface height (METHOD.md section 3).
//
// The particle density at a point,
//
//   xi(r) = sum_i (m_i / rho_i) W(|r - r_i|, h),
//
// is ~1 inside the water and 0 in air (it is a Shepard sum of the kernel). The surface
// on the line is where xi crosses xi_t = 0.8: sampling from the top of the line down
// in steps of 0.1 dx, the first sample with xi >= xi_t and the sample above it
// bracket the crossing, and the height is interpolated linearly between them. With
// the walls' b_off = 0.5 this threshold puts the surface of a still lattice block
// where its particles' volumes end (half a spacing above the top row).
//
// The crossing of xi_t = 0.8 is not the surface itself: xi falls to 1/2 where the
// water's volume ends and reaches 0.8 only some way below it (a still lattice block
// crosses 0.8 at its top row's centres, dx/2 under the still level). By default the
// gauge therefore adds the depth s(xi_t) at which a uniform half space of water has
// xi = xi_t, so a still surface reads the still level (the water volume over the
// width) rather than dx/2 low:
//   xi(s) = 1/2 + int_0^s P(z) dz,   P(z) = the kernel integrated over a plane
// (2D: a line) at distance z, a property of the kernel alone: s(0.8) = 0.453 h in
// 2D, 0.446 h in 3D (0.54 dx for h = 1.2 dx). `volume_edge = false` gives the plain crossing
// (the METHOD.md reading, reference preset).
//
// If no sample reaches xi_t the line is dry and the gauge reports its bottom height.
// Heights are absolute y [m] (y is up); subtract the floor height for a depth.
//
// Cost: the fluid particles within 2h of the line are gathered once per reading
// from the columns of cells around it (the simulation's cell grid, whose fluid order
// is that of the last re-sort), sorted by height, and each sample only visits the
// ones within 2h of it: a reading costs O(column particles x log) plus O(samples x
// local particles), cheap enough for every output.
#include <cstdint>
#include <vector>
#include <moorsph/fluid/fluid_simulation.hpp>

namespace moorsph::fluid {

/// Where a gauge stands. `position` holds the horizontal coordinates: x in 2D,
/// x and z in 3D (the y entry is ignored). Heights are y [m].
template <int D>
struct WaveGaugeSpec {
  Vec<D> position = Vec<D>::Zero();  ///< [m]; component 1 (y) unused
  double bottom = 0.0;               ///< lowest height of the line [m] (the floor)
  double top = 1.0;                  ///< height where the downward search starts [m]
  double threshold = 0.8;            ///< xi_t (METHOD.md section 3)
  double step_fraction = 0.1;        ///< search step in units of dx
  bool volume_edge = true;           ///< report the crossing + s(xi_t) (see above)
};

/// s(xi_t) / h: the depth below the plane face of a uniform half space of water at
/// which the Wendland particle density reaches xi_t (negative above it for xi_t < 1/2).
template <int D>
double halfSpaceThresholdDepth(double threshold);

template <int D>
class WaveGauge {
 public:
  explicit WaveGauge(WaveGaugeSpec<D> spec);

  const WaveGaugeSpec<D>& spec() const { return spec_; }

  /// Free-surface height [m] from the simulation's current state, found with its
  /// cell grid.
  double read(const FluidSimulation<D>& sim) const;

  /// Same, by a scan over every particle (no grid): for tests and for particle sets
  /// that are not inside a simulation; dx is the particle spacing [m] (sets the search step).
  double read(const FluidParticles<D>& fluid, const Domain<D>& domain, const WendlandKernel<D>& kernel,
              double dx) const;

  /// The particle density xi at a point [-], by a scan over every particle.
  static double particleDensity(const FluidParticles<D>& fluid, const Domain<D>& domain,
                                const WendlandKernel<D>& kernel, const Vec<D>& point);

 private:
  struct Candidate {
    double y;       // height of the particle [m]
    double r2h;     // squared horizontal distance to the line [m^2]
    double volume;  // m / rho [m^3 or m^2]
  };
  double searchDown(const WendlandKernel<D>& kernel, double dx) const;
  void addCandidate(const FluidParticles<D>& fluid, const Domain<D>& domain, double support, std::size_t i) const;

  WaveGaugeSpec<D> spec_;
  double edge_depth_ = 0.0;  // s(xi_t) / h added to the crossing (volume_edge)
  // Scratch reused between readings (a reading is not thread safe).
  mutable std::vector<Candidate> candidates_;
  mutable std::vector<std::uint32_t> cells_;
};

}  // namespace moorsph::fluid
