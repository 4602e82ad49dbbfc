#include <moorsph/fluid/waves/stokes2_wave.hpp>

#include <cmath>

namespace moorsph::fluid::waves {

Stokes2Wave::Stokes2Wave(double amplitude, double period, double depth, double gravity)
    : airy_(amplitude, period, depth, gravity) {
  const double a = amplitude;
  const double k = airy_.waveNumber();
  const double kd = k * depth;
  const double s = std::sinh(kd);  // may be +inf in deep water: every use below stays finite
  const double invS2 = 1.0 / (s * s);
  // cosh(kd)(2 + cosh 2kd)/sinh^3(kd) = coth(kd) (2 + 3/sinh^2 kd), since cosh 2kd = 1 + 2 sinh^2.
  eta2_ = 0.25 * k * a * a * (2.0 + 3.0 * invS2) / std::tanh(kd);
  // cosh(2kd)/sinh^4(kd) = (1 + 2 sinh^2)/sinh^4 = 1/sinh^4 + 2/sinh^2; the y dependence is
  // carried as cosh(2ky)/cosh(2kd) so nothing overflows.
  velocity2_ = 0.75 * a * a * k * airy_.angularFrequency() * (invS2 * invS2 + 2.0 * invS2);
}

double Stokes2Wave::secondHarmonicRatio() const {
  return airy_.amplitude() > 0.0 ? eta2_ / airy_.amplitude() : 0.0;
}

double Stokes2Wave::ursellNumber() const {
  const double lambda = airy_.wavelength();
  const double d = airy_.depth();
  return 2.0 * airy_.amplitude() * lambda * lambda / (d * d * d);
}

double Stokes2Wave::elevation(double x, double t) const {
  const double psi = airy_.phase(x, t);
  return airy_.elevation(x, t) + eta2_ * std::cos(2.0 * psi);
}

Eigen::Vector2d Stokes2Wave::velocity(double x, double y, double t) const {
  const double psi = airy_.phase(x, t);
  const double k2y = 2.0 * airy_.waveNumber() * y;
  const double k2d = 2.0 * airy_.waveNumber() * airy_.depth();
  Eigen::Vector2d v = airy_.velocity(x, y, t);
  v.x() += velocity2_ * coshOverCosh(k2y, k2d) * std::cos(2.0 * psi);
  v.y() += velocity2_ * sinhOverCosh(k2y, k2d) * std::sin(2.0 * psi);
  return v;
}

}  // namespace moorsph::fluid::waves
