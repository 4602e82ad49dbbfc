#include <moorsph/fluid/waves/airy_wave.hpp>

#include <cmath>
#include <stdexcept>

namespace moorsph::fluid::waves {

double coshOverCosh(double a, double b) {
  // cosh a / cosh b = e^(a-b) (1 + e^-2a) / (1 + e^-2b)
  return std::exp(a - b) * (1.0 + std::exp(-2.0 * a)) / (1.0 + std::exp(-2.0 * b));
}

double sinhOverCosh(double a, double b) {
  // sinh a / cosh b = e^(a-b) (1 - e^-2a) / (1 + e^-2b); -expm1 keeps small a accurate.
  return std::exp(a - b) * (-std::expm1(-2.0 * a)) / (1.0 + std::exp(-2.0 * b));
}

AiryWave::AiryWave(double amplitude, double period, double depth, double gravity)
    : a_(amplitude), period_(period), d_(depth), g_(gravity) {
  if (!(amplitude >= 0.0)) throw std::invalid_argument("AiryWave: amplitude must be >= 0");
  if (!std::isfinite(depth)) throw std::invalid_argument("AiryWave: depth must be finite");
  k_ = waveNumberFromPeriod(period, depth, gravity);
  omega_ = 2.0 * kPi / period;
}

double AiryWave::wavelength() const { return 2.0 * kPi / k_; }

double AiryWave::elevation(double x, double t) const { return a_ * std::cos(phase(x, t)); }

Eigen::Vector2d AiryWave::velocity(double x, double y, double t) const {
  const double psi = phase(x, t);
  const double scale = a_ * g_ * k_ / omega_;
  const double ky = k_ * y;
  const double kd = k_ * d_;
  return {scale * coshOverCosh(ky, kd) * std::cos(psi),
          scale * sinhOverCosh(ky, kd) * std::sin(psi)};
}

}  // namespace moorsph::fluid::waves
