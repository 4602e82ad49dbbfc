#include <moorsph/fluid/waves/piston_transfer.hpp>

#include <cmath>
#include <complex>
#include <stdexcept>
#include <string>

#include <unsupported/Eigen/FFT>

namespace moorsph::fluid::waves {
namespace {

using Complex = std::complex<double>;

std::size_t paddedLength(std::size_t n, bool zeroPad) {
  if (!zeroPad) return n;
  std::size_t m = 1;
  while (m < 2 * n) m *= 2;
  return m;
}

// Signed frequency [Hz] of bin j of an M-point transform with sampling dt.
double binFrequency(std::size_t j, std::size_t m, double dt) {
  const double jj = (2 * j <= m) ? static_cast<double>(j)
                                 : static_cast<double>(j) - static_cast<double>(m);
  return jj / (static_cast<double>(m) * dt);
}

void requireSeries(const UniformSeries& s, const char* who) {
  if (s.values.size() < 2 || !(s.dt > 0.0)) {
    throw std::invalid_argument(std::string(who) + ": need >= 2 samples and dt > 0");
  }
}

// Applies spectrum(j) *= multiplier(f_j) for every bin of the (padded) series; the
// Nyquist bin of an even-length transform has no sign and is dropped (it carries no
// progressive wave a piston could make at a resolvable phase).
template <class Multiplier>
std::vector<double> filterSeries(const std::vector<double>& in, double dt, bool zeroPad,
                                 Multiplier multiplier) {
  const std::size_t n = in.size();
  const std::size_t m = paddedLength(n, zeroPad);
  std::vector<Complex> time(m, Complex(0.0, 0.0));
  for (std::size_t i = 0; i < n; ++i) time[i] = Complex(in[i], 0.0);
  Eigen::FFT<double> fft;
  std::vector<Complex> spec;
  fft.fwd(spec, time);
  for (std::size_t j = 0; j < m; ++j) {
    if (m % 2 == 0 && 2 * j == m) {
      spec[j] = 0.0;
      continue;
    }
    spec[j] *= multiplier(binFrequency(j, m, dt));
  }
  fft.inv(time, spec);  // scaled by 1/m
  std::vector<double> out(n);
  for (std::size_t i = 0; i < n; ++i) out[i] = time[i].real();
  return out;
}

double rampWeight(double t, double t0, double tEnd, const PistonFilterOptions& o) {
  return halfCosineRamp(t - t0, o.rampUpTime) * halfCosineRamp(tEnd - t, o.rampDownTime);
}

}  // namespace

double halfCosineRamp(double s, double width) {
  if (width <= 0.0 || s >= width) return 1.0;
  if (s <= 0.0) return 0.0;
  return 0.5 * (1.0 - std::cos(kPi * s / width));
}

double pistonHeightToStroke(double k, double depth) {
  if (!(k > 0.0) || !(depth > 0.0)) {
    throw std::invalid_argument("pistonHeightToStroke: k and depth must be positive");
  }
  if (std::isinf(depth)) return 2.0;
  const double kd = k * depth;
  const double x = 2.0 * kd;
  if (kd < 20.0) {
    // cosh 2kd - 1 = 2 sinh^2 kd keeps the shallow limit (H/S -> kd) accurate.
    const double s = std::sinh(kd);
    return 4.0 * s * s / (std::sinh(x) + x);
  }
  // Divide through by cosh 2kd: no overflow for any kd.
  const double invCosh = 1.0 / std::cosh(x);
  return 2.0 * (1.0 - invCosh) / (std::tanh(x) + x * invCosh);
}

double pistonHeightToStrokeFromPeriod(double period, double depth, double gravity) {
  return pistonHeightToStroke(waveNumberFromPeriod(period, depth, gravity), depth);
}

UniformSeries pistonDisplacementFromElevation(const UniformSeries& elevation, double depth,
                                              const PistonFilterOptions& o, double gravity) {
  requireSeries(elevation, "pistonDisplacementFromElevation");
  if (!(o.lowCutoffFrequency > 0.0)) {
    throw std::invalid_argument(
        "pistonDisplacementFromElevation: lowCutoffFrequency must be > 0 Hz (the piston "
        "transfer function vanishes at zero frequency, so the stroke would diverge)");
  }
  if (o.lowTaperWidth < 0.0 || !(o.highCutoffFrequency > o.lowCutoffFrequency + o.lowTaperWidth)) {
    throw std::invalid_argument(
        "pistonDisplacementFromElevation: need lowTaperWidth >= 0 and highCutoffFrequency > "
        "lowCutoffFrequency + lowTaperWidth");
  }
  const double t0 = elevation.t0;
  const double tEnd = elevation.time(elevation.values.size() - 1);
  std::vector<double> eta = elevation.values;
  for (std::size_t i = 0; i < eta.size(); ++i) eta[i] *= rampWeight(elevation.time(i), t0, tEnd, o);

  auto multiplier = [&](double f) -> Complex {
    const double af = std::abs(f);
    if (af < o.lowCutoffFrequency || af > o.highCutoffFrequency) return 0.0;
    const double taper = halfCosineRamp(af - o.lowCutoffFrequency, o.lowTaperWidth);
    const double k = waveNumberFromAngularFrequency(2.0 * kPi * af, depth, gravity);
    const double sign = f > 0.0 ? 1.0 : -1.0;
    return Complex(0.0, -sign * taper / pistonHeightToStroke(k, depth));
  };
  UniformSeries out{elevation.t0, elevation.dt,
                    filterSeries(eta, elevation.dt, o.zeroPad, multiplier)};
  for (std::size_t i = 0; i < out.values.size(); ++i) {
    out.values[i] *= rampWeight(out.time(i), t0, tEnd, o);
  }
  return out;
}

UniformSeries elevationFromPistonDisplacement(const UniformSeries& displacement, double depth,
                                              bool zeroPad, double gravity) {
  requireSeries(displacement, "elevationFromPistonDisplacement");
  auto multiplier = [&](double f) -> Complex {
    if (f == 0.0) return 0.0;
    const double af = std::abs(f);
    const double k = waveNumberFromAngularFrequency(2.0 * kPi * af, depth, gravity);
    const double sign = f > 0.0 ? 1.0 : -1.0;
    return Complex(0.0, sign * pistonHeightToStroke(k, depth));
  };
  return UniformSeries{displacement.t0, displacement.dt,
                       filterSeries(displacement.values, displacement.dt, zeroPad, multiplier)};
}

namespace {

/// Multiplies each component by exp(-i sign(f) phase(|omega|)).
template <class Phase>
UniformSeries shiftPhases(const UniformSeries& elevation, Phase phase) {
  auto multiplier = [&](double f) -> Complex {
    if (f == 0.0) return 1.0;
    const double sign = f > 0.0 ? 1.0 : -1.0;
    return std::exp(Complex(0.0, -sign * phase(2.0 * kPi * std::abs(f))));
  };
  return UniformSeries{elevation.t0, elevation.dt, filterSeries(elevation.values, elevation.dt, true, multiplier)};
}

}  // namespace

UniformSeries transportLinearWaves(const UniformSeries& elevation, double distance, double depth, double gravity) {
  requireSeries(elevation, "transportLinearWaves");
  return shiftPhases(elevation, [&](double omega) {
    return waveNumberFromAngularFrequency(omega, depth, gravity) * distance;
  });
}

UniformSeries finiteDepthCorrection(const UniformSeries& elevation, double distance, double depth, double gravity) {
  requireSeries(elevation, "finiteDepthCorrection");
  return shiftPhases(elevation, [&](double omega) {
    return (omega * omega / gravity - waveNumberFromAngularFrequency(omega, depth, gravity)) * distance;
  });
}

}  // namespace moorsph::fluid::waves
