// Piston wave maker: Biesel transfer function and the elevation <-> displacement conversion.
#include <gtest/gtest.h>

#include <cmath>

#include <moorsph/fluid/waves/piston_signal.hpp>
#include <moorsph/fluid/waves/piston_transfer.hpp>

namespace w = moorsph::fluid::waves;

namespace {
constexpr double pi = 3.14159265358979323846;

// Biesel's formula written out here, independently of the library's stable form.
double bieselDirect(double k, double d) {
  return 2.0 * (std::cosh(2.0 * k * d) - 1.0) / (std::sinh(2.0 * k * d) + 2.0 * k * d);
}
}  // namespace

// Table value quoted in issue 6: depth 0.5 m, T = 1.0 s -> H/S = 1.714.
TEST(PistonTransfer, BieselTableValueAndLimits) {
  EXPECT_NEAR(w::pistonHeightToStrokeFromPeriod(1.0, 0.5), 1.714, 0.0005);
  EXPECT_EQ(w::pistonHeightToStroke(1.0, w::kInfiniteDepth), 2.0);
  EXPECT_NEAR(w::pistonHeightToStroke(100.0, 10.0), 2.0, 1e-15);     // kd = 1000: no overflow
  EXPECT_NEAR(w::pistonHeightToStroke(1e-4, 1.0), 1e-4, 1e-12);      // shallow: H/S -> kd
  for (double kd : {0.1, 0.5, 1.0, 2.0, 5.0}) {
    EXPECT_NEAR(w::pistonHeightToStroke(kd, 1.0), bieselDirect(kd, 1.0), 1e-13);
  }
}

// Regular wave: the piston amplitude after the ramp is S/2 with S = H / (H/S).
TEST(PistonTransfer, RegularWaveStroke) {
  const double H = 0.1;
  const w::AiryWave wave(0.5 * H, 1.0, 0.5);
  const w::UniformSeries x = w::regularWavePistonSignal(wave, 20.0, 0.001, 5.0);
  ASSERT_EQ(x.values.size(), 20001u);
  EXPECT_EQ(x.values.front(), 0.0);  // starts at rest
  double maxLate = 0.0;
  double maxEarly = 0.0;
  for (std::size_t i = 0; i < x.values.size(); ++i) {
    (x.time(i) >= 5.0 ? maxLate : maxEarly) =
        std::max(x.time(i) >= 5.0 ? maxLate : maxEarly, std::abs(x.values[i]));
  }
  const double strokeTable = H / 1.714;
  std::printf("stroke %.6f m, from the table %.6f m\n", 2.0 * maxLate, strokeTable);
  EXPECT_NEAR(2.0 * maxLate, strokeTable, 3e-4 * strokeTable);  // table has 4 digits
  EXPECT_NEAR(w::pistonStroke(H, 1.0, 0.5), strokeTable, 3e-4 * strokeTable);
  EXPECT_LT(maxEarly, maxLate);
}

// A periodic record of three sinusoids on exact FFT bins, no padding: the FFT path must give
// the closed form X = sum (a_n / (H/S)_n) sin(omega_n t + theta_n) for eta = sum a_n cos(...).
TEST(PistonTransfer, FftPathMatchesClosedFormForSinusoids) {
  const double d = 0.6;
  const double dt = 0.01;
  const std::size_t n = 4000;  // 40 s record
  const double fs[3] = {0.5, 0.8, 1.25};
  const double as[3] = {0.01, 0.02, 0.005};
  const double th[3] = {0.3, -1.1, 2.0};
  w::UniformSeries eta{0.0, dt, std::vector<double>(n, 0.0)};
  std::vector<double> expected(n, 0.0);
  for (int m = 0; m < 3; ++m) {
    const double om = 2.0 * pi * fs[m];
    const double k = w::waveNumberFromAngularFrequency(om, d);
    for (std::size_t i = 0; i < n; ++i) {
      const double t = eta.time(i);
      eta.values[i] += as[m] * std::cos(om * t + th[m]);
      expected[i] += as[m] / bieselDirect(k, d) * std::sin(om * t + th[m]);
    }
  }
  w::PistonFilterOptions opt;
  opt.lowCutoffFrequency = 0.2;
  opt.zeroPad = false;
  const w::UniformSeries x = w::pistonDisplacementFromElevation(eta, d, opt);
  double worst = 0.0;
  for (std::size_t i = 0; i < n; ++i) worst = std::max(worst, std::abs(x.values[i] - expected[i]));
  std::printf("sinusoids: max |X - closed form| = %.3g m\n", worst);
  EXPECT_LT(worst, 1e-12);
  // And the forward transfer of the closed form gives back eta.
  const w::UniformSeries back =
      w::elevationFromPistonDisplacement(w::UniformSeries{0.0, dt, expected}, d, false);
  double worstBack = 0.0;
  for (std::size_t i = 0; i < n; ++i)
    worstBack = std::max(worstBack, std::abs(back.values[i] - eta.values[i]));
  EXPECT_LT(worstBack, 1e-12);
}

// Round trip with zero padding on a band-limited, non-periodic record: a Gaussian wave
// packet (carrier 1 Hz, spectrum width ~0.08 Hz, nothing below the 0.3 Hz cut-off).
TEST(PistonTransfer, RoundTripReproducesBandLimitedTarget) {
  const double d = 0.5;
  const double dt = 0.02;
  const std::size_t n = 3001;  // 60 s, an odd length on purpose
  const double a = 0.02;
  const double t0 = 30.0;
  const double sigma = 2.0;
  w::UniformSeries eta{0.0, dt, std::vector<double>(n)};
  for (std::size_t i = 0; i < n; ++i) {
    const double s = eta.time(i) - t0;
    eta.values[i] = a * std::exp(-0.5 * s * s / (sigma * sigma)) * std::cos(2.0 * pi * s);
  }
  w::PistonFilterOptions opt;
  opt.lowCutoffFrequency = 0.2;
  opt.lowTaperWidth = 0.1;
  const w::UniformSeries x = w::pistonDisplacementFromElevation(eta, d, opt);
  const w::UniformSeries back = w::elevationFromPistonDisplacement(x, d);
  double worst = 0.0;
  double maxX = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    worst = std::max(worst, std::abs(back.values[i] - eta.values[i]));
    maxX = std::max(maxX, std::abs(x.values[i]));
  }
  std::printf("packet round trip: max error %.3g m (a = %.3g m), max |X| = %.4f m\n", worst, a,
              maxX);
  EXPECT_LT(worst, 1e-9 * a);
  // The packet's stroke is that of its carrier: a / (H/S)(1 Hz) to within a few percent.
  EXPECT_NEAR(maxX, a / w::pistonHeightToStrokeFromPeriod(1.0, d), 0.03 * maxX);
}

// The low-frequency limit: H/S -> kd -> 0, so the stroke per unit elevation grows like 1/f.
TEST(PistonTransfer, LowFrequencyLimitIsEnforced) {
  const double d = 0.5;
  const double g = 9.81;
  for (double f : {0.01, 0.001}) {
    const double k = w::waveNumberFromAngularFrequency(2.0 * pi * f, d);
    EXPECT_NEAR(1.0 / w::pistonHeightToStroke(k, d), std::sqrt(g / d) / (2.0 * pi * f),
                1e-3 / (2.0 * pi * f));
  }
  w::UniformSeries eta{0.0, 0.01, std::vector<double>(100, 0.01)};
  w::PistonFilterOptions opt;  // no cut-off given
  EXPECT_THROW(w::pistonDisplacementFromElevation(eta, d, opt), std::invalid_argument);
  // A constant (mean level) target cannot be made by a piston: it is filtered out entirely
  // (periodic record, so the constant is exactly the zero-frequency bin).
  opt.lowCutoffFrequency = 0.1;
  opt.zeroPad = false;
  const w::UniformSeries x = w::pistonDisplacementFromElevation(eta, d, opt);
  for (double v : x.values) EXPECT_NEAR(v, 0.0, 1e-15);
}

// Breather at the piston: the target is the breather evaluated at the piston, the
// displacement starts at rest, and its forward transfer reproduces the (ramped) target.
TEST(PistonTransfer, BreatherSignalMakesTheBreatherAtThePiston) {
  const w::PeregrineBreather b(1, 0.01, 6.0);  // METHOD.md 6.4, order 1
  const double d = 0.6;
  const double xf = 6.24;
  const double tf = 40.0;
  const double duration = 60.0;
  const double dt = 0.01;
  const w::UniformSeries eta = w::breatherElevationAtPiston(b, xf, tf, duration, dt);
  ASSERT_EQ(eta.values.size(), 6001u);
  EXPECT_DOUBLE_EQ(eta.values[1234], b.elevation(-xf, eta.time(1234) - tf));
  w::PistonFilterOptions opt;
  // Carrier 1.22 Hz. The breather's spectrum is not compact: it decays exponentially away
  // from the carrier, so the cut-off removes a little of the target (measured: 2e-4 a0 at
  // f_c = 0.2 Hz, 1.5e-3 a0 at 0.4 Hz, 1.1e-2 a0 at 0.6 Hz, all with a 0.2 Hz taper).
  opt.lowCutoffFrequency = 0.2;
  opt.lowTaperWidth = 0.2;
  opt.highCutoffFrequency = 4.0;
  opt.rampUpTime = 5.0;
  opt.rampDownTime = 5.0;
  const w::UniformSeries x = w::breatherPistonSignal(b, xf, tf, d, duration, dt, opt);
  EXPECT_EQ(x.values.front(), 0.0);
  EXPECT_EQ(x.values.back(), 0.0);
  const w::UniformSeries back = w::elevationFromPistonDisplacement(x, d);
  double worst = 0.0;
  double maxX = 0.0;
  for (std::size_t i = 0; i < x.values.size(); ++i) {
    maxX = std::max(maxX, std::abs(x.values[i]));
    const double t = x.time(i);
    if (t < 10.0 || t > 50.0) continue;  // away from the ramps
    worst = std::max(worst, std::abs(back.values[i] - eta.values[i]));
  }
  std::printf("breather: max |X| = %.4f m, forward-transfer error %.3g m (a0 = 0.01 m)\n", maxX,
              worst);
  EXPECT_LT(worst, 5e-4 * b.carrierAmplitude());
  // Stroke bounded by the carrier's: peak amplitude 3 a0 over H/S at the carrier frequency.
  const double kCarrier = w::waveNumberFromAngularFrequency(b.carrierAngularFrequency(), d);
  EXPECT_LT(maxX, 1.2 * 3.0 * b.carrierAmplitude() / w::pistonHeightToStroke(kCarrier, d));
}

// Linear transport: a sinusoid carried L downstream on depth d is cos(omega t - k L) with k
// of the dispersion relation; the finite-depth correction is the record that finite depth
// carries to what deep water carries the original to; on a wave group at k0 d = 1.75 it
// delays the group by L (1/c_g,deep - 1/c_g,d), the finite depth's head start.
TEST(PistonTransfer, LinearTransportAndFiniteDepthCorrection) {
  const double d = 0.35, L = 2.0, dt = 0.01, omega = std::sqrt(9.81 * 5.0);  // METHOD.md 6.4 order 2: deep k0 d = 1.75
  const std::size_t n = 8001;
  w::UniformSeries sine{0.0, dt, std::vector<double>(n)};
  for (std::size_t i = 0; i < n; ++i)  // ramped in and out over 10 s: no spectral leakage from the ends
    sine.values[i] = w::halfCosineRamp(sine.time(i), 10.0) * w::halfCosineRamp(80.0 - sine.time(i), 10.0) *
                     std::cos(omega * sine.time(i));
  const double k = w::waveNumberFromAngularFrequency(omega, d);
  const auto moved = w::transportLinearWaves(sine, L, d);
  double worst = 0.0;
  for (std::size_t i = 3000; i < 5000; ++i)  // 30-50 s, well inside the ramps
    worst = std::max(worst, std::abs(moved.values[i] - std::cos(omega * sine.time(i) - k * L)));
  EXPECT_LT(worst, 1e-6);

  // A Gaussian group of the carrier, 3 s wide, centred at 30 s.
  w::UniformSeries group{0.0, dt, std::vector<double>(n)};
  for (std::size_t i = 0; i < n; ++i) {
    const double t = group.time(i) - 30.0;
    group.values[i] = std::exp(-t * t / (2.0 * 3.0 * 3.0)) * std::cos(omega * group.time(i));
  }
  const auto corrected = w::finiteDepthCorrection(group, L, d);
  const auto on_depth = w::transportLinearWaves(corrected, L, d);
  const auto deep = w::transportLinearWaves(group, L, w::kInfiniteDepth);
  double diff = 0.0;
  for (std::size_t i = 0; i < n; ++i) diff = std::max(diff, std::abs(on_depth.values[i] - deep.values[i]));
  EXPECT_LT(diff, 1e-9);
  const auto centre = [](const w::UniformSeries& s) {
    double num = 0.0, den = 0.0;
    for (std::size_t i = 0; i < s.values.size(); ++i) num += s.time(i) * s.values[i] * s.values[i], den += s.values[i] * s.values[i];
    return num / den;
  };
  const double delay = centre(corrected) - centre(group);
  const double expected = L / w::groupSpeed(omega * omega / 9.81, w::kInfiniteDepth) - L / w::groupSpeed(k, d);
  std::printf("finite-depth correction at k d = %.2f: group delayed %.4f s (linear group speeds: %.4f s)\n", k * d, delay,
              expected);
  EXPECT_GT(expected, 0.3);
  EXPECT_NEAR(delay, expected, 0.03 * expected);
}
