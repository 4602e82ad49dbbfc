#pragma once
// Piston displacement signals X(t) [m] for the piston wave maker (METHOD.md sections 4b, 4c),
// built on the linear transfer function of piston_transfer.hpp. Time starts at 0 [s] and the
// piston's mean position is the origin of the wave's x axis unless stated otherwise.
//
// Regular wave (closed form, no FFT): the Airy wave eta = a cos(k x - omega t) is made by
//   X(t) = r(t) (a / (H/S)) sin(omega t),  stroke S = H / (H/S),  H = 2a,
// with r(t) the half-cosine ramp-up over rampUpTime.
//
// Peregrine breather focused at distance x_f from the piston at time t_f: the target
// elevation at the piston is the breather evaluated at the piston, eta(-x_f, t - t_f) (the
// envelope propagated back from the focus by the NLS solution itself), converted frequency
// by frequency with pistonDisplacementFromElevation. The breather is deep-water theory
// (omega0^2 = g k0) while the transfer function uses the finite depth d; the two agree for
// k0 d >= ~1.75 (METHOD.md section 6.5), which is where breather tanks should be.
#include <moorsph/fluid/waves/airy_wave.hpp>
#include <moorsph/fluid/waves/peregrine_breather.hpp>
#include <moorsph/fluid/waves/piston_transfer.hpp>

namespace moorsph::fluid::waves {

/// Piston stroke S = H / (H/S) [m] (peak to peak) for wave height H [m], period T [s],
/// depth d [m].
double pistonStroke(double height, double period, double depth, double gravity = kGravity);

/// X(t) [m] sampled at t = i dt, 0 <= t <= duration [s], making the regular wave `wave`
/// (its amplitude, period, depth and gravity), ramped up over rampUpTime [s].
UniformSeries regularWavePistonSignal(const AiryWave& wave, double duration, double dt,
                                      double rampUpTime);

/// Target elevation eta(t) [m] at the piston, 0 <= t <= duration, of `breather` focused
/// focusDistance [m] downstream of the piston at time focusTime [s].
UniformSeries breatherElevationAtPiston(const PeregrineBreather& breather, double focusDistance,
                                        double focusTime, double duration, double dt);

/// X(t) [m] making that target on depth d [m]; `options` as for
/// pistonDisplacementFromElevation (a ramp-up is strongly advised: the breather's background
/// sea has full amplitude a0 at t = 0).
UniformSeries breatherPistonSignal(const PeregrineBreather& breather, double focusDistance,
                                   double focusTime, double depth, double duration, double dt,
                                   const PistonFilterOptions& options, double gravity = kGravity);

/// A breather wave maker's whole motion (scenes' `signal: {type: breather}` and the
/// moorsph_breather_signal tool): the piston rests for `still` seconds (bodies settle),
/// then follows breatherPistonSignal for the record from `still` to `duration`, with a
/// half-cosine ramp-up over `ramp` seconds (the breather's background sea has its full
/// amplitude everywhere, so an unramped start would jerk the piston), components below
/// half the carrier frequency removed (taper a quarter of it wide: a piston cannot make a
/// mean level, piston_transfer.hpp LOW-FREQUENCY LIMIT) and, when rampDown > 0, a
/// half-cosine ramp-down over the record's last rampDown seconds so the plate comes to
/// rest. The ramp front travels at the group speed; it must have left the tank before
/// the focus time.
struct BreatherMakerSpec {
  int order = 1;
  double a0 = 0.0;             ///< carrier amplitude [m]
  double k0 = 0.0;             ///< carrier wave number [rad/m]
  double focusDistance = 0.0;  ///< from the piston's rest position [m]
  double focusTime = 0.0;      ///< [s]
  double depth = 0.0;          ///< still depth [m]
  double still = 0.0;          ///< [s] at rest before the waves (rounded to whole samples)
  double ramp = 0.0;           ///< [s] ramp-up after the still phase
  double rampDown = 0.0;       ///< [s] ramp-down at the end of the record
  double duration = 0.0;       ///< [s] end of the record (the piston holds after it)
  double dt = 0.0;             ///< [s] sampling interval
  /// Pre-compensate the finite depth's linear dispersion over the focus distance
  /// (finiteDepthCorrection, piston_transfer.hpp), so the envelope arrives at the focus
  /// when the deep-water breather says; false: the breather as METHOD.md 4c writes it.
  bool finiteDepthCorrection = false;
};

/// X(t) [m] at t = i dt from 0 to duration; throws std::invalid_argument for an
/// inconsistent spec (0 <= still, still + ramp < focusTime < duration are required).
UniformSeries breatherMakerSignal(const BreatherMakerSpec& spec, double gravity = kGravity);

}  // namespace moorsph::fluid::waves
