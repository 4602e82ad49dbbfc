#include <moorsph/fluid/waves/piston_signal.hpp>

#include <algorithm>
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

UniformSeries breatherMakerSignal(const BreatherMakerSpec& spec, double gravity) {
  if (!(spec.dt > 0.0)) throw std::invalid_argument("breather signal: the sampling interval must be positive");
  const std::size_t n_still = static_cast<std::size_t>(std::llround(std::max(spec.still, 0.0) / spec.dt));
  const double still = static_cast<double>(n_still) * spec.dt;
  if (!(spec.still >= 0.0 && still + spec.ramp < spec.focusTime && spec.focusTime < spec.duration)) {
    throw std::invalid_argument("breather signal: need 0 <= still, still + ramp < focus time < duration");
  }
  const PeregrineBreather breather(spec.order, spec.a0, spec.k0, gravity);
  const double f0 = breather.carrierAngularFrequency() / (2.0 * M_PI);
  PistonFilterOptions filter;
  filter.lowCutoffFrequency = 0.5 * f0;
  filter.lowTaperWidth = 0.25 * f0;
  filter.rampUpTime = spec.ramp;
  filter.rampDownTime = spec.rampDown;
  // Built from the end of the still phase: the record's own time is t - still.
  UniformSeries target = breatherElevationAtPiston(breather, spec.focusDistance, spec.focusTime - still,
                                                   spec.duration - still, spec.dt);
  if (spec.finiteDepthCorrection) target = finiteDepthCorrection(target, spec.focusDistance, spec.depth, gravity);
  const UniformSeries waves = pistonDisplacementFromElevation(target, spec.depth, filter, gravity);
  UniformSeries x{0.0, spec.dt, std::vector<double>(n_still, 0.0)};
  x.values.insert(x.values.end(), waves.values.begin(), waves.values.end());
  return x;
}

}  // namespace moorsph::fluid::waves
