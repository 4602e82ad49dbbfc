#include <moorsph/fluid/waves/piston_signal.hpp>

#include <cmath>
#include <stdexcept>

namespace moorsph::fluid::waves {
namespace {

std::size_t sampleCount(double duration, double dt) {
  if (!(duration > 0.0) || !(dt > 0.0)) {
    throw std::invalid_argument("piston signal: duration and dt must be positive");
  }
  // Include the end point when duration is a whole number of steps (to round-off).
  return static_cast<std::size_t>(std::floor(duration / dt + 1e-9)) + 1;
}

}  // namespace

double pistonStroke(double height, double period, double depth, double gravity) {
  return height / pistonHeightToStrokeFromPeriod(period, depth, gravity);
}

UniformSeries regularWavePistonSignal(const AiryWave& wave, double duration, double dt,
                                      double rampUpTime) {
  const std::size_t n = sampleCount(duration, dt);
  const double halfStroke =
      wave.amplitude() / pistonHeightToStroke(wave.waveNumber(), wave.depth());
  UniformSeries s{0.0, dt, std::vector<double>(n)};
  for (std::size_t i = 0; i < n; ++i) {
    const double t = s.time(i);
    s.values[i] = halfCosineRamp(t, rampUpTime) * halfStroke *
                  std::sin(wave.angularFrequency() * t);
  }
  return s;
}

UniformSeries breatherElevationAtPiston(const PeregrineBreather& breather, double focusDistance,
                                        double focusTime, double duration, double dt) {
  const std::size_t n = sampleCount(duration, dt);
  UniformSeries s{0.0, dt, std::vector<double>(n)};
  for (std::size_t i = 0; i < n; ++i) {
    s.values[i] = breather.elevation(-focusDistance, s.time(i) - focusTime);
  }
  return s;
}

UniformSeries breatherPistonSignal(const PeregrineBreather& breather, double focusDistance,
                                   double focusTime, double depth, double duration, double dt,
                                   const PistonFilterOptions& options, double gravity) {
  return pistonDisplacementFromElevation(
      breatherElevationAtPiston(breather, focusDistance, focusTime, duration, dt), depth,
      options, gravity);
}

}  // namespace moorsph::fluid::waves
