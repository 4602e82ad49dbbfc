#pragma once
// A packing probe: how closely the fluid particles sit against the volumes their
// densities give them, averaged over a box (the diagnostic session 37 needed by hand to
// find why the ship tank's gauges fell; docs/validation/ship.md finding 6).
//
// At each point of a regular grid inside the box it takes the particle density of
// METHOD.md section 3,
//
//   xi(r) = sum_j (m_j / rho_j) W(|r - r_j|, h),
//
// a Shepard sum of the kernel: 1 (to the lattice's partition-of-unity error) where the
// particles fill exactly the space sum(m/rho) says, 0 in air. Inside the water a mean
// above its start value means the particles have packed closer than their densities
// say: the same water volume then occupies less space, so the particle surface (what
// gauges and bodies feel) stands lower than the volume's level by about
// depth x (xi_mean - xi_mean(0)) (1.1% over 132 m was the 6 m ship tank's 1.5-1.9 m
// gauge fall under the reference wall law). Uniform compaction of the positions by a
// factor s raises xi by s^-D (tests/fluid/test_packing_probe.cpp).
//
// Points whose xi is below `min_fill` are dry (above the surface or in a splash gap) and
// are left out of the mean and spread; the wet fraction is reported beside them, so a
// box reaching into the waves reads the packing of its wet part.
//
// Cost: one kernel sum per grid point per reading (the simulation's cell grid, as the
// velocity probe), OpenMP over points; a 1000-point box costs about a velocity probe
// per point.
#include <vector>
#include <moorsph/fluid/fluid_simulation.hpp>

namespace moorsph::fluid {

/// The grid spacing scenes default to, as a fraction of dx: the golden-ratio fraction, so
/// the points spread over the start lattice's cells. A spacing of dx samples one spot of
/// every cell (on the 2D flume of cases/piston_flume_2d.yaml: xi 1.0152 against the cell
/// average 1.0000).
inline constexpr double kPackingSpacingPerDx = 0.618;

template <int D>
struct PackingProbeSpec {
  Vec<D> lower = Vec<D>::Zero();  ///< box corner [m], ground frame
  Vec<D> upper = Vec<D>::Ones();  ///< opposite corner [m]
  double spacing = 0.0;           ///< grid spacing [m] (> 0); points at cell centres
  double min_fill = 0.5;          ///< xi below which a point is dry [-]
};

/// One reading over the box's wet points.
struct PackingReading {
  double mean = 0.0;          ///< mean xi over the wet points [-]; NaN when none is wet
  double spread = 0.0;        ///< standard deviation of xi over them [-]; NaN when none
  double wet_fraction = 0.0;  ///< wet points / all points [-]
};

template <int D>
class PackingProbe {
 public:
  explicit PackingProbe(PackingProbeSpec<D> spec);

  const PackingProbeSpec<D>& spec() const { return spec_; }
  /// The grid: cell centres of the box cut into ~spacing cells (count per axis rounded).
  const std::vector<Vec<D>>& points() const { return points_; }
  std::size_t pointCount() const { return points_.size(); }

  PackingReading read(const FluidSimulation<D>& sim) const;

 private:
  PackingProbeSpec<D> spec_;
  std::vector<Vec<D>> points_;
};

}  // namespace moorsph::fluid
