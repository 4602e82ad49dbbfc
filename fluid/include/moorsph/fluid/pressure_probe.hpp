#pragma once
// A pressure sensor on a wall, with two estimates of the pressure at one point.
//
// 1. From the boundary reactions (METHOD.md section 2: "the same per-particle
//    reactions give local surface pressure"). Each boundary particle k of a surface
//    that tracks reactions carries R_k, the sum of the forces its fluid neighbours
//    exert on it (equal and opposite to the wall force on them). The wall's unit
//    normal n points into the fluid, so the fluid pushes along -n and the pressure
//    over the patch P of the surface's particles within `radius` of the sensor is
//
//      p_reaction = sum_{k in P} (-R_k . n) / (|P| s^(D-1)),
//
//    s the boundary spacing (each particle stands for an s x s tile of wall, s in 2D).
//    Edge and corner particles of the patch are counted as whole tiles. The wall law
//    spreads a fluid particle's push over the boundary particles within dx along the
//    wall, so this is a pressure smoothed over about radius + dx; its time signal
//    carries the acoustic noise of the weakly-compressible method.
//
// 2. SPH-interpolated in front of the wall: at r0 = point + offset n,
//
//      p_interp = sum_j p_j W(|r0 - r_j|) V_j / sum_j W(|r0 - r_j|) V_j,  V_j = m_j/rho_j,
//
//    the Shepard-normalised kernel average of the fluid pressure (p_j from the
//    equation of state), carried back to the wall by the hydrostatic difference
//    -rho0 g.(r0 - point). The Shepard denominator keeps it unbiased where the kernel
//    is truncated by the wall; with no fluid within 2h of r0 it reads 0.
//
// On a movable surface (a body, a piston) the sensor moves with it: its point and
// normal are kept in the surface's body frame (from the surface's motion when the
// probe is made) and placed by the surface's current motion at every reading, and the
// patch's own rotated normals carry the reaction estimate.
//
// Kleefsman et al. (2005) measured with 8 mm (diameter) transducers; both estimates
// average over a larger patch at the resolutions used here.
#include <cstdint>
#include <vector>
#include <moorsph/fluid/fluid_simulation.hpp>

namespace moorsph::fluid {

template <int D>
struct PressureProbeSpec {
  std::size_t surface = 0;          ///< index of a surface that tracks reactions
  Vec<D> point = Vec<D>::Zero();    ///< sensor position on the wall [m]
  Vec<D> normal = Vec<D>::Zero();   ///< wall normal into the fluid (normalised here)
  double radius = 0.0;              ///< patch radius for the reaction estimate [m]
  double boundary_spacing = 0.0;    ///< spacing of the surface's particles [m]
  double interpolation_offset = 0.0;  ///< distance of r0 in front of the wall [m]
  /// point and normal are in the body frame of a movable surface (relative to its
  /// reference point, in its axes) instead of the ground frame.
  bool body_frame = false;
};

template <int D>
class PressureProbe {
 public:
  /// Selects the patch: boundary particles of `spec.surface` within `spec.radius` of
  /// the point that carry a normal within 30 degrees of `spec.normal`. Throws
  /// std::invalid_argument if the surface does not track reactions or the patch is empty.
  PressureProbe(PressureProbeSpec<D> spec, const Walls<D>& walls);

  const PressureProbeSpec<D>& spec() const { return spec_; }
  /// Where the sensor is now, and its normal into the fluid (ground frame).
  Vec<D> currentPoint(const Walls<D>& walls) const;
  Vec<D> currentNormal(const Walls<D>& walls) const;
  const std::vector<std::uint32_t>& patch() const { return patch_; }

  /// Pressure [Pa] from the boundary reactions of the last rate evaluation.
  double readReaction(const Walls<D>& walls) const;
  double readReaction(const FluidSimulation<D>& sim) const;

  /// Pressure [Pa] interpolated from the fluid a distance `interpolation_offset` in
  /// front of the wall (uses the cell grid of the simulation).
  double readInterpolated(const FluidSimulation<D>& sim) const;

 private:
  PressureProbeSpec<D> spec_;
  std::vector<std::uint32_t> patch_;
  double patch_area_ = 0.0;  // |P| s^(D-1) [m^2, m in 2D]
  bool moving_ = false;      // on a movable surface: point and normal in its body frame
  Vec<D> body_point_ = Vec<D>::Zero(), body_normal_ = Vec<D>::Zero();
};

}  // namespace moorsph::fluid
