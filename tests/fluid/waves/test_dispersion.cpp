// Linear dispersion relation: values against published/closed-form numbers only.
#include <gtest/gtest.h>

#include <cmath>

#include <moorsph/fluid/waves/dispersion.hpp>

namespace w = moorsph::fluid::waves;

namespace {
constexpr double g = 9.81;
constexpr double pi = 3.14159265358979323846;
}  // namespace

// Table value quoted in issue 6 (depth 0.5 m, T = 1.0 s).
TEST(Dispersion, TableDepth05Period1) {
  EXPECT_NEAR(w::wavelengthFromPeriod(1.0, 0.5), 1.513, 0.0005);
}

// METHOD.md section 4a: T = 1 s, d = 0.8 m, 3 wavelengths = 4.669 m; section 6.2c: T = 2 s
// gives a 4.85 m tank (1 wavelength) and T = 3 s a 7.90 m tank (1 wavelength).
TEST(Dispersion, MethodExamples) {
  EXPECT_NEAR(3.0 * w::wavelengthFromPeriod(1.0, 0.8), 4.669, 0.0005);
  EXPECT_NEAR(w::wavelengthFromPeriod(2.0, 0.8), 4.85, 0.005);
  EXPECT_NEAR(w::wavelengthFromPeriod(3.0, 0.8), 7.90, 0.005);
}

// Deep water: lambda = g T^2 / (2 pi), c = g T / (2 pi), c_g = c / 2.
TEST(Dispersion, DeepWaterLimit) {
  for (double T : {0.5, 1.0, 3.0, 17.4}) {
    const double lambdaDeep = g * T * T / (2.0 * pi);
    EXPECT_NEAR(w::wavelengthFromPeriod(T, w::kInfiniteDepth), lambdaDeep, 1e-12 * lambdaDeep);
    // A finite but deep tank (d = 2 lambda): tanh(4 pi) = 1 - 2.4e-11.
    EXPECT_NEAR(w::wavelengthFromPeriod(T, 2.0 * lambdaDeep), lambdaDeep, 1e-10 * lambdaDeep);
    // Huge depth: no overflow, exact deep-water value.
    EXPECT_NEAR(w::wavelengthFromPeriod(T, 1e6), lambdaDeep, 1e-12 * lambdaDeep);
    const double k = w::waveNumberFromPeriod(T, w::kInfiniteDepth);
    EXPECT_NEAR(w::phaseSpeed(k, w::kInfiniteDepth), g * T / (2.0 * pi), 1e-12);
    EXPECT_NEAR(w::groupSpeed(k, 1e6), 0.5 * g * T / (2.0 * pi), 1e-12);
  }
}

// Shallow water: c = c_g = sqrt(g d), lambda = T sqrt(g d), to O((kd)^2).
TEST(Dispersion, ShallowWaterLimit) {
  const double d = 0.01;
  const double T = 100.0;
  const double c0 = std::sqrt(g * d);
  const double k = w::waveNumberFromPeriod(T, d);
  const double kd = k * d;
  ASSERT_LT(kd, 3e-3);
  EXPECT_NEAR(w::phaseSpeed(k, d), c0, c0 * kd * kd);          // c = c0 (1 - (kd)^2/6 + ...)
  EXPECT_NEAR(w::groupSpeed(k, d), c0, c0 * kd * kd);          // c_g = c0 (1 - (kd)^2/2 + ...)
  EXPECT_NEAR(w::wavelengthFromPeriod(T, d), T * c0, T * c0 * kd * kd);
}

// Newton converges to round-off from omega^2 d / g = 1e-12 to 1e4 (shallow to very deep).
TEST(Dispersion, NewtonResidualOverAllDepths) {
  double worst = 0.0;
  for (double logY = -12.0; logY <= 4.0; logY += 0.25) {
    const double y = std::pow(10.0, logY);
    const double d = 1.0;
    const double omega = std::sqrt(y * g / d);
    const double k = w::waveNumberFromAngularFrequency(omega, d);
    const double residual = std::abs(g * k * std::tanh(k * d) - omega * omega) / (omega * omega);
    worst = std::max(worst, residual);
    EXPECT_NEAR(w::angularFrequencyFromWaveNumber(k, d), omega, 1e-13 * omega);
  }
  EXPECT_LT(worst, 1e-14);
  std::printf("worst relative dispersion residual: %.3g\n", worst);
}

TEST(Dispersion, GroupSpeedFormula) {
  // Intermediate depth against the textbook expression c_g = n c, n = (1 + 2kd/sinh 2kd)/2.
  const w::LinearWaveProperties p = w::linearWaveFromPeriod(1.0, 0.5);
  const double kd = p.waveNumber * 0.5;
  const double n = 0.5 * (1.0 + 2.0 * kd / std::sinh(2.0 * kd));
  EXPECT_NEAR(p.groupSpeed, n * p.phaseSpeed, 1e-14);
  EXPECT_NEAR(p.phaseSpeed, p.wavelength / p.period, 1e-14);
  EXPECT_NEAR(p.angularFrequency, 2.0 * pi, 1e-15);
}

TEST(Dispersion, RejectsBadInput) {
  EXPECT_THROW(w::waveNumberFromPeriod(0.0, 1.0), std::invalid_argument);
  EXPECT_THROW(w::waveNumberFromPeriod(1.0, -1.0), std::invalid_argument);
  EXPECT_THROW(w::waveNumberFromAngularFrequency(-1.0, 1.0), std::invalid_argument);
}
