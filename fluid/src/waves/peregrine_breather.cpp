#include <moorsph/fluid/waves/peregrine_breather.hpp>

#include <cmath>
#include <stdexcept>
#include <string>

namespace moorsph::fluid::waves {

std::complex<double> peregrineNormalizedEnvelope(int order, double X, double T) {
  const double X2 = X * X;
  const double T2 = T * T;
  double sign = 0.0;
  double G = 0.0;
  double H = 0.0;
  double D = 0.0;
  if (order == 1) {
    sign = -1.0;
    G = 4.0;
    H = 16.0 * T;
    D = 1.0 + 4.0 * X2 + 16.0 * T2;
  } else if (order == 2) {
    sign = 1.0;
    const double r = X2 + 4.0 * T2;
    G = 0.75 - (r + 0.75) * (X2 + 20.0 * T2 + 0.75);
    H = 2.0 * T * (3.0 * X2 - 4.0 * T2 - 2.0 * r * r + 15.0 / 8.0);
    const double m = X2 - 12.0 * T2;
    D = r * r * r / 3.0 + m * m / 4.0 + 3.0 * (12.0 * X2 + 176.0 * T2 + 1.0) / 64.0;
  } else {
    throw std::invalid_argument("Peregrine breather: order must be 1 or 2, got " +
                                std::to_string(order));
  }
  const std::complex<double> rational(sign + G / D, H / D);
  return rational * std::polar(1.0, 2.0 * T);
}

PeregrineBreather::PeregrineBreather(int order, double carrierAmplitude,
                                     double carrierWaveNumber, double gravity)
    : order_(order), a0_(carrierAmplitude), k0_(carrierWaveNumber) {
  if (order != 1 && order != 2) {
    throw std::invalid_argument("PeregrineBreather: order must be 1 or 2");
  }
  if (!(carrierAmplitude > 0.0) || !(carrierWaveNumber > 0.0) || !(gravity > 0.0)) {
    throw std::invalid_argument("PeregrineBreather: a0, k0 and g must be positive");
  }
  omega0_ = std::sqrt(gravity * k0_);
  psi0_ = std::sqrt(2.0) * k0_ * a0_;
}

double PeregrineBreather::scaledX(double x, double t) const {
  return (k0_ * x - 0.5 * omega0_ * t) * psi0_;
}

double PeregrineBreather::scaledT(double t) const {
  return -(omega0_ / 8.0) * psi0_ * psi0_ * t;
}

std::complex<double> PeregrineBreather::envelope(double X, double T) const {
  return a0_ * peregrineNormalizedEnvelope(order_, X, T);
}

double PeregrineBreather::elevation(double x, double t) const {
  const std::complex<double> psi = envelope(scaledX(x, t), scaledT(t));
  return std::real(psi * std::polar(1.0, k0_ * x - omega0_ * t));
}

double PeregrineBreather::envelopeAmplitude(double x, double t) const {
  return std::abs(envelope(scaledX(x, t), scaledT(t)));
}

}  // namespace moorsph::fluid::waves
