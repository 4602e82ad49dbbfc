#pragma once
// A velocity probe: the fluid velocity at a fixed point, SPH-interpolated (issue 6:
// "wave gauges and velocity probes"; the orbital velocity under a wave, the inflow on a
// body).
//
//   v(r0) = sum_j v_j W(|r0 - r_j|) V_j / sum_j W(|r0 - r_j|) V_j,   V_j = m_j / rho_j,
//
// the Shepard-normalised kernel average (exact for a uniform field on any particle set,
// second order in h for a smooth one where the kernel is full; first order where it is
// cut by a wall or the surface). The denominator is the particle density xi of METHOD.md
// section 3; where it is below `min_fill` the point is out of the water (in air above a
// trough, or between splashes) and the probe reads NaN, not a velocity of a few
// outlying particles.
#include <moorsph/fluid/fluid_simulation.hpp>

namespace moorsph::fluid {

template <int D>
struct VelocityProbeSpec {
  Vec<D> point = Vec<D>::Zero();  ///< [m], ground frame
  double min_fill = 0.5;          ///< xi below which the point is dry [-]
};

template <int D>
class VelocityProbe {
 public:
  explicit VelocityProbe(VelocityProbeSpec<D> spec);

  const VelocityProbeSpec<D>& spec() const { return spec_; }

  /// The interpolated velocity [m/s], NaN in every component where the point is dry;
  /// uses the simulation's cell grid.
  Vec<D> read(const FluidSimulation<D>& sim) const;

 private:
  VelocityProbeSpec<D> spec_;
};

}  // namespace moorsph::fluid
