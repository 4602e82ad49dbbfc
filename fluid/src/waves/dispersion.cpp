#include <moorsph/fluid/waves/dispersion.hpp>

#include <cmath>
#include <stdexcept>
#include <string>

namespace moorsph::fluid::waves {
namespace {

constexpr double kTwoPi = 2.0 * kPi;

void requirePositive(double value, const char* what) {
  if (!(value > 0.0)) {
    throw std::invalid_argument(std::string("waves: ") + what + " must be positive, got " +
                                std::to_string(value));
  }
}

// Root x of x tanh(x) = y, y > 0, by Newton from Eckart's guess.
double solveDimensionless(double y) {
  double x = y / std::sqrt(std::tanh(y));
  for (int iter = 0; iter < 100; ++iter) {
    const double t = std::tanh(x);
    const double f = x * t - y;
    const double df = t + x * (1.0 - t * t);
    const double step = f / df;
    x -= step;
    if (std::abs(step) <= 4.0 * std::numeric_limits<double>::epsilon() * x) return x;
  }
  throw std::runtime_error("waves: dispersion Newton iteration did not converge (y = " +
                           std::to_string(y) + ")");
}

}  // namespace

double waveNumberFromAngularFrequency(double omega, double depth, double gravity) {
  requirePositive(omega, "angular frequency");
  requirePositive(depth, "depth");
  requirePositive(gravity, "gravity");
  const double kDeep = omega * omega / gravity;
  if (std::isinf(depth)) return kDeep;
  // For y = omega^2 d / g above ~20, tanh(x) = 1 to round-off and the deep-water value is
  // exact; the dimensionless Newton handles every finite depth uniformly.
  return solveDimensionless(kDeep * depth) / depth;
}

double waveNumberFromPeriod(double period, double depth, double gravity) {
  requirePositive(period, "period");
  return waveNumberFromAngularFrequency(kTwoPi / period, depth, gravity);
}

double angularFrequencyFromWaveNumber(double k, double depth, double gravity) {
  requirePositive(k, "wave number");
  requirePositive(depth, "depth");
  const double t = std::isinf(depth) ? 1.0 : std::tanh(k * depth);
  return std::sqrt(gravity * k * t);
}

double wavelengthFromPeriod(double period, double depth, double gravity) {
  return kTwoPi / waveNumberFromPeriod(period, depth, gravity);
}

double phaseSpeed(double k, double depth, double gravity) {
  return angularFrequencyFromWaveNumber(k, depth, gravity) / k;
}

double groupSpeed(double k, double depth, double gravity) {
  const double c = phaseSpeed(k, depth, gravity);
  if (std::isinf(depth)) return 0.5 * c;
  const double kd2 = 2.0 * k * depth;
  // 2kd/sinh(2kd) -> 1 as kd -> 0 and -> 0 (no overflow issue: x/inf = 0) as kd -> inf.
  const double ratio = kd2 < 1e-8 ? 1.0 : kd2 / std::sinh(kd2);
  return 0.5 * c * (1.0 + ratio);
}

LinearWaveProperties linearWaveFromPeriod(double period, double depth, double gravity) {
  LinearWaveProperties p;
  p.period = period;
  p.depth = depth;
  p.angularFrequency = kTwoPi / period;
  p.waveNumber = waveNumberFromPeriod(period, depth, gravity);
  p.wavelength = kTwoPi / p.waveNumber;
  p.phaseSpeed = p.angularFrequency / p.waveNumber;
  p.groupSpeed = groupSpeed(p.waveNumber, depth, gravity);
  return p;
}

}  // namespace moorsph::fluid::waves
