#pragma once
// Linear dispersion relation of gravity waves on water of constant depth d
// (METHOD.md section 4a; Dean & Dalrymple 1991, "Water Wave Mechanics for Engineers
// and Scientists", section 4.3):
//
//   omega^2 = g k tanh(k d)
//
// omega [rad/s], k [rad/m], d [m], g [m/s^2]. Deep water is d = +infinity
// (std::numeric_limits<double>::infinity()), where omega^2 = g k.
//
// The wave number is found by Newton iteration on the dimensionless form
// f(x) = x tanh(x) - y = 0 with x = k d, y = omega^2 d / g. f is increasing and convex
// for x > 0, so Newton converges monotonically from any positive start after at most
// one overshoot; the start x0 = y / sqrt(tanh y) (Eckart 1952) is within 5% of the
// root for every depth, so about 3-5 iterations reach round-off.
#include <limits>

namespace moorsph::fluid::waves {

/// Gravitational acceleration used throughout METHOD.md [m/s^2].
inline constexpr double kGravity = 9.81;

/// pi, spelled out because M_PI is not standard C++.
inline constexpr double kPi = 3.14159265358979323846264338327950288;

/// Deep water: pass as the depth.
inline constexpr double kInfiniteDepth = std::numeric_limits<double>::infinity();

/// k [rad/m] solving omega^2 = g k tanh(k d) for omega > 0 [rad/s], depth > 0 [m]
/// (may be kInfiniteDepth). Throws std::invalid_argument on non-positive input.
double waveNumberFromAngularFrequency(double omega, double depth, double gravity = kGravity);

/// k [rad/m] for a wave of period T [s] on depth d [m].
double waveNumberFromPeriod(double period, double depth, double gravity = kGravity);

/// omega [rad/s] = sqrt(g k tanh(k d)) for k > 0 [rad/m] (the forward relation).
double angularFrequencyFromWaveNumber(double k, double depth, double gravity = kGravity);

/// Wavelength lambda = 2 pi / k [m] of a wave of period T [s] on depth d [m].
double wavelengthFromPeriod(double period, double depth, double gravity = kGravity);

/// Phase speed c = omega / k [m/s] of wave number k [rad/m] on depth d [m].
double phaseSpeed(double k, double depth, double gravity = kGravity);

/// Group speed c_g = (c / 2) (1 + 2 k d / sinh(2 k d)) [m/s]; c/2 in deep water,
/// sqrt(g d) in the shallow limit.
double groupSpeed(double k, double depth, double gravity = kGravity);

/// All the linear properties of one regular wave, computed once.
struct LinearWaveProperties {
  double period = 0.0;           ///< T [s]
  double angularFrequency = 0.0; ///< omega [rad/s]
  double waveNumber = 0.0;       ///< k [rad/m]
  double wavelength = 0.0;       ///< lambda [m]
  double phaseSpeed = 0.0;       ///< c [m/s]
  double groupSpeed = 0.0;       ///< c_g [m/s]
  double depth = 0.0;            ///< d [m]
};

/// Solves the dispersion relation for period T [s] on depth d [m].
LinearWaveProperties linearWaveFromPeriod(double period, double depth, double gravity = kGravity);

}  // namespace moorsph::fluid::waves
