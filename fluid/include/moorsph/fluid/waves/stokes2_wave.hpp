#pragma once
// Stokes second-order progressive regular wave on constant depth d (METHOD.md section 4a;
// Dean & Dalrymple 1991, section 11.2, written with a = H/2 and L = 2 pi / k).
// Coordinates as AiryWave: x along the tank [m], y up from the floor [m], psi = k x - omega t,
// omega^2 = g k tanh(k d) (the second order does not change the dispersion relation).
//
//   eta   = a cos psi + (k a^2 / 4) cosh(kd) (2 + cosh 2kd) / sinh^3(kd) cos 2psi      [m]
//   v_x   = Airy v_x + (3 a^2 k omega / 4) cosh(2ky) / sinh^4(kd) cos 2psi               [m/s]
//   v_y   = Airy v_y + (3 a^2 k omega / 4) sinh(2ky) / sinh^4(kd) sin 2psi               [m/s]
//
// The velocity is the gradient of phi = phi_1 + (3/8) a^2 omega cosh(2ky)/sinh^4(kd) sin 2psi,
// hence divergence free. In deep water the second-order velocity vanishes and the bound
// harmonic tends to (k a^2 / 2) cos 2psi. The expansion is meaningful while the bound
// harmonic is small compared with a (secondHarmonicRatio() << 1; Dean & Dalrymple use an
// Ursell number H L^2 / d^3 below about 26 as the practical limit).
#include <Eigen/Core>

#include <moorsph/fluid/waves/airy_wave.hpp>

namespace moorsph::fluid::waves {

class Stokes2Wave {
 public:
  /// amplitude a [m] of the first harmonic, period T [s], still depth d [m] (finite).
  Stokes2Wave(double amplitude, double period, double depth, double gravity = kGravity);

  /// The first-order (Airy) part.
  const AiryWave& firstOrder() const { return airy_; }
  double amplitude() const { return airy_.amplitude(); }
  double waveNumber() const { return airy_.waveNumber(); }
  double angularFrequency() const { return airy_.angularFrequency(); }
  double depth() const { return airy_.depth(); }

  /// Amplitude of the bound second harmonic in eta [m].
  double secondHarmonicAmplitude() const { return eta2_; }
  /// secondHarmonicAmplitude() / a [-].
  double secondHarmonicRatio() const;
  /// Ursell number H L^2 / d^3 with H = 2a [-].
  double ursellNumber() const;

  /// Free-surface elevation above the still level [m].
  double elevation(double x, double t) const;
  /// Velocity (v_x, v_y) [m/s] at height y above the floor.
  Eigen::Vector2d velocity(double x, double y, double t) const;

 private:
  AiryWave airy_;
  double eta2_;       // bound harmonic amplitude [m]
  double velocity2_;  // 3 a^2 k omega / 4 * (cosh 2kd / sinh^4 kd) [m/s]
};

}  // namespace moorsph::fluid::waves
