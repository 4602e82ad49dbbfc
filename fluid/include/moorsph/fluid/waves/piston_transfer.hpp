#pragma once
// Linear piston wave-maker theory (Biesel & Suquet 1951; Dean & Dalrymple 1991, section 6.3).
//
// A flat piston of stroke S (peak to peak) [m] at frequency omega on depth d makes, far from
// the piston (beyond the evanescent modes, i.e. a few depths), a progressive wave of height H:
//
//   H / S = 2 (cosh 2kd - 1) / (sinh 2kd + 2kd),   omega^2 = g k tanh(kd)          (1)
//
// which tends to 2 in deep water and to kd in shallow water. Phase: the displacement
// X(t) = (S/2) sin(omega t) makes eta = (H/2) cos(k x - omega t), i.e. the far-field wave
// extrapolated back to the piston's mean position x = 0 is in phase with the piston VELOCITY.
//
// For an arbitrary target elevation eta(t) at the piston's mean position this is applied
// frequency by frequency (linear superposition). With the FFT convention
// eta(t) = sum_f E(f) exp(+2 pi i f t):
//
//   Xhat(f) = -i sign(f) Ehat(f) / (H/S)(|f|)        (inverse transfer, the piston signal)
//   Ehat(f) = +i sign(f) (H/S)(|f|) Xhat(f)          (forward transfer, the generated wave)
//
// LOW-FREQUENCY LIMIT: (H/S) -> kd -> 0 as f -> 0 (k ~ omega / sqrt(g d)), so the stroke
// needed for a given elevation diverges like 1/f; any slow drift, mean level or spectral
// leakage of the record would ask the piston for an unbounded stroke, and a mean level
// cannot be made by a piston at all. Components below lowCutoffFrequency are therefore
// removed, and a raised-cosine taper of width lowTaperWidth above the cut-off avoids a sharp
// spectral edge (which would ring in time). Choose the cut-off well below the band of the
// target wave (e.g. half the lowest frequency of interest): the removed part is not generated.
// The same filter may also remove components above an optional high cut-off.
//
// The record is zero padded (default) to at least twice its length so the non-causal tails of
// the filter do not wrap around. An optional half-cosine ramp-up (ramp-down) multiplies the
// target elevation before the transform AND the displacement after it, so the piston starts
// (ends) exactly at rest at X = 0; the ramp region of the wave is then smoothly tapered.
// FFT: Eigen's FFT module (kissfft back end, already part of libeigen3-dev).
#include <limits>
#include <vector>

#include <moorsph/fluid/waves/dispersion.hpp>

namespace moorsph::fluid::waves {

/// Biesel height-to-stroke ratio H/S [-] of eq. (1) for wave number k [rad/m], depth d [m]
/// (kInfiniteDepth gives 2).
double pistonHeightToStroke(double k, double depth);

/// H/S [-] for a wave of period T [s] on depth d [m].
double pistonHeightToStrokeFromPeriod(double period, double depth, double gravity = kGravity);

/// A uniformly sampled time series: values[i] at time t0 + i dt [s].
struct UniformSeries {
  double t0 = 0.0;  ///< time of the first sample [s]
  double dt = 0.0;  ///< sampling interval [s]
  std::vector<double> values;
  double time(std::size_t i) const { return t0 + static_cast<double>(i) * dt; }
  double duration() const {
    return values.empty() ? 0.0 : static_cast<double>(values.size() - 1) * dt;
  }
};

/// Frequency filter and tapers of the elevation-to-displacement conversion.
struct PistonFilterOptions {
  /// f_c [Hz], required > 0: components below it are removed (see LOW-FREQUENCY LIMIT).
  double lowCutoffFrequency = 0.0;
  /// [Hz] raised-cosine taper from f_c (gain 0) to f_c + width (gain 1); 0 = sharp cut.
  double lowTaperWidth = 0.0;
  /// [Hz] components above it are removed; default: none.
  double highCutoffFrequency = std::numeric_limits<double>::infinity();
  /// [s] half-cosine ramp-up at the start of the record; 0 = none.
  double rampUpTime = 0.0;
  /// [s] half-cosine ramp-down at the end of the record; 0 = none.
  double rampDownTime = 0.0;
  /// Zero pad to the next power of two >= 2N before the FFT (recommended).
  bool zeroPad = true;
};

/// Piston displacement X(t) [m] (same sampling as the input) that makes the target
/// free-surface elevation eta(t) [m] at the piston's mean position on depth d [m].
UniformSeries pistonDisplacementFromElevation(const UniformSeries& elevation, double depth,
                                              const PistonFilterOptions& options,
                                              double gravity = kGravity);

/// Linear transport of a wave record over `distance` [m] downstream on depth d [m]: each
/// frequency moves with its own wave number, Ehat(f) -> Ehat(f) exp(-i sign(f) k(|f|) x)
/// (a component cos(omega t - k x) at x), with k of omega^2 = g k tanh(k d)
/// (kInfiniteDepth: deep water). The record is zero padded as pistonDisplacementFromElevation
/// does, so a group delayed past the record's end is cut rather than wrapped.
UniformSeries transportLinearWaves(const UniformSeries& elevation, double distance, double depth,
                                   double gravity = kGravity);

/// The record that linear waves on depth d carry over `distance` to what linear
/// deep-water waves would carry the given one to: Ehat(f) exp(+i sign(f) (k_d - k_deep) x).
/// A deep-water target at a piston (a breather of METHOD.md 4c) made on finite depth
/// travels with the finite-depth group speed, faster below k d ~ 3 (1.07 times deep water's at
/// k d = 2.1, 1.13 at 1.75); this pre-compensates that linear part so the group reaches
/// `distance` when deep-water theory says (the nonlinear focusing is not corrected).
UniformSeries finiteDepthCorrection(const UniformSeries& elevation, double distance, double depth,
                                    double gravity = kGravity);

/// Forward transfer: far-field elevation eta(t) [m], extrapolated to the piston's mean
/// position, made by the piston displacement X(t) [m] on depth d [m] (linear theory).
UniformSeries elevationFromPistonDisplacement(const UniformSeries& displacement, double depth,
                                              bool zeroPad = true, double gravity = kGravity);

/// Half-cosine ramp weight in [0,1]: 0 at s = 0, 1 for s >= width (1 everywhere if width <= 0).
double halfCosineRamp(double s, double width);

}  // namespace moorsph::fluid::waves
