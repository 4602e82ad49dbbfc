#pragma once
// Airy (linear) progressive regular wave on constant depth d (METHOD.md section 4a;
// Dean & Dalrymple 1991, chapter 4). Coordinates: x along the tank [m], y measured UP FROM
// THE FLOOR [m] (still surface at y = d), t [s]; phase psi = k x - omega t.
//
//   eta(x,t) = a cos psi                                            [m]
//   v_x      = (a g k / omega) cosh(k y) / cosh(k d) cos psi        [m/s]
//   v_y      = (a g k / omega) sinh(k y) / cosh(k d) sin psi        [m/s]
//
// with omega^2 = g k tanh(k d). The field is divergence free and satisfies the linearised
// kinematic surface condition d eta/dt = v_y(y = d) exactly. The hyperbolic ratios are
// evaluated in an overflow-free form, so deep water (k d of several hundred) is fine; the
// depth itself must be finite because y is measured from the floor.
#include <Eigen/Core>

#include <moorsph/fluid/waves/dispersion.hpp>

namespace moorsph::fluid::waves {

class AiryWave {
 public:
  /// amplitude a [m] (half the height), period T [s], still depth d [m] (finite), g [m/s^2].
  AiryWave(double amplitude, double period, double depth, double gravity = kGravity);

  double amplitude() const { return a_; }
  double period() const { return period_; }
  double depth() const { return d_; }
  double gravity() const { return g_; }
  double waveNumber() const { return k_; }
  double angularFrequency() const { return omega_; }
  double wavelength() const;
  /// psi = k x - omega t [rad].
  double phase(double x, double t) const { return k_ * x - omega_ * t; }

  /// Free-surface elevation above the still level [m].
  double elevation(double x, double t) const;
  /// Velocity (v_x, v_y) [m/s] at height y above the floor.
  Eigen::Vector2d velocity(double x, double y, double t) const;

 private:
  double a_;
  double period_;
  double d_;
  double g_;
  double k_;
  double omega_;
};

/// cosh(a)/cosh(b) for a, b >= 0 without overflow.
double coshOverCosh(double a, double b);
/// sinh(a)/cosh(b) for a, b >= 0 without overflow.
double sinhOverCosh(double a, double b);

}  // namespace moorsph::fluid::waves
