// Airy and Stokes second-order fields: incompressibility, kinematic surface condition and
// known limits, all checked by finite differences against the governing equations.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include <moorsph/fluid/waves/airy_wave.hpp>
#include <moorsph/fluid/waves/stokes2_wave.hpp>

namespace w = moorsph::fluid::waves;

namespace {
constexpr double pi = 3.14159265358979323846;
}  // namespace

namespace {

// Fourth-order central difference of f at s with step h.
double d1(const std::function<double(double)>& f, double s, double h) {
  return (8.0 * (f(s + h) - f(s - h)) - (f(s + 2.0 * h) - f(s - 2.0 * h))) / (12.0 * h);
}

// Wave cases: (amplitude [m], period [s], depth [m]) from METHOD.md 6.2c/6.3 and issue 6.
struct Case {
  double a, T, d;
};
const Case kCases[] = {{0.058, 1.0, 0.8}, {0.040, 2.0, 0.8}, {0.071, 3.0, 0.8}, {0.02, 1.0, 0.5}};

template <class Wave>
double worstDivergence(const Wave& wave, double a, double d) {
  const double k = wave.waveNumber();
  const double scale = a * wave.angularFrequency() * k;  // velocity gradient scale [1/s]
  const double h = 1e-3 / k;
  double worst = 0.0;
  for (double x : {0.0, 0.13, 0.71, 1.9})
    for (double y : {0.05 * d, 0.4 * d, 0.9 * d, d})
      for (double t : {0.0, 0.37, 1.3}) {
        const double dudx = d1([&](double s) { return wave.velocity(s, y, t).x(); }, x, h);
        const double dvdy = d1([&](double s) { return wave.velocity(x, s, t).y(); }, y, h);
        worst = std::max(worst, std::abs(dudx + dvdy) / scale);
      }
  return worst;
}

// Full (nonlinear) kinematic condition at the true surface y = d + eta:
// R = eta_t + u eta_x - v, normalised by a omega.
template <class Wave>
double worstSurfaceKinematics(const Wave& wave, double a, double d) {
  const double k = wave.waveNumber();
  const double omega = wave.angularFrequency();
  double worst = 0.0;
  for (double x : {0.0, 0.21, 0.55, 1.1, 2.3}) {
    for (double t : {0.0, 0.1, 0.45}) {
      const double eta = wave.elevation(x, t);
      const double etaT = d1([&](double s) { return wave.elevation(x, s); }, t, 1e-3 / omega);
      const double etaX = d1([&](double s) { return wave.elevation(s, t); }, x, 1e-3 / k);
      const Eigen::Vector2d v = wave.velocity(x, d + eta, t);
      worst = std::max(worst, std::abs(etaT + v.x() * etaX - v.y()) / (a * omega));
    }
  }
  return worst;
}

}  // namespace

TEST(AiryStokes, IncompressibleByFiniteDifferences) {
  double worstA = 0.0;
  double worstS = 0.0;
  for (const Case& c : kCases) {
    worstA = std::max(worstA, worstDivergence(w::AiryWave(c.a, c.T, c.d), c.a, c.d));
    worstS = std::max(worstS, worstDivergence(w::Stokes2Wave(c.a, c.T, c.d), c.a, c.d));
  }
  std::printf("max |div v|/(a omega k): Airy %.3g, Stokes2 %.3g\n", worstA, worstS);
  EXPECT_LT(worstA, 1e-9);
  EXPECT_LT(worstS, 1e-9);
}

// Linearised kinematic condition d eta/dt = v_y(y = d), exact for the Airy wave.
TEST(AiryStokes, AiryLinearisedKinematicSurfaceCondition) {
  double worst = 0.0;
  for (const Case& c : kCases) {
    const w::AiryWave wave(c.a, c.T, c.d);
    const double omega = wave.angularFrequency();
    for (double x : {0.0, 0.3, 1.7})
      for (double t : {0.0, 0.2, 0.9}) {
        const double etaT =
            d1([&](double s) { return wave.elevation(x, s); }, t, 1e-3 / omega);
        worst = std::max(worst, std::abs(etaT - wave.velocity(x, c.d, t).y()) / (c.a * omega));
      }
  }
  std::printf("max linearised kinematic residual / (a omega): %.3g\n", worst);
  EXPECT_LT(worst, 1e-9);
}

// At the true surface the kinematic residual of an n-th order theory is O(a^(n+1)):
// halving a divides it by ~4 for Airy and by ~8 for Stokes 2nd order. This checks that the
// bound harmonic of eta and the second-order velocity are mutually consistent.
TEST(AiryStokes, KinematicResidualOrderAtTrueSurface) {
  for (const Case& c : kCases) {
    const double a1 = c.a;
    const double a2 = 0.5 * c.a;
    const double ra = worstSurfaceKinematics(w::AiryWave(a1, c.T, c.d), a1, c.d) /
                      worstSurfaceKinematics(w::AiryWave(a2, c.T, c.d), a2, c.d);
    const double rs = worstSurfaceKinematics(w::Stokes2Wave(a1, c.T, c.d), a1, c.d) /
                      worstSurfaceKinematics(w::Stokes2Wave(a2, c.T, c.d), a2, c.d);
    std::printf("T=%.0f d=%.1f: residual ratio for a -> a/2: Airy %.2f (expect 2), Stokes2 %.2f "
                "(expect 4)\n",
                c.T, c.d, ra, rs);
    // Ratios of residual/(a omega): O(a) -> 2, O(a^2) -> 4.
    EXPECT_NEAR(ra, 2.0, 0.3);
    EXPECT_NEAR(rs, 4.0, 0.6);
  }
}

// Deep water: u at the crest equals a omega and decays as exp(k z) below the surface;
// the Stokes bound harmonic tends to k a^2 / 2 (Stokes 1847) and its velocity vanishes.
TEST(AiryStokes, DeepWaterLimits) {
  const double a = 0.01;
  const double T = 1.0;
  const double d = 1000.0;  // cosh(k d) would overflow without the stable ratios
  const w::Stokes2Wave s(a, T, d);
  const double k = s.waveNumber();
  const double omega = s.angularFrequency();
  const Eigen::Vector2d vTop = s.velocity(0.0, d, 0.0);
  EXPECT_NEAR(vTop.x(), a * omega, 1e-14);
  EXPECT_NEAR(vTop.y(), 0.0, 1e-14);
  const double lambda = 2.0 * pi / k;
  EXPECT_NEAR(s.velocity(0.0, d - lambda, 0.0).x(), a * omega * std::exp(-2.0 * pi), 1e-15);
  EXPECT_NEAR(s.secondHarmonicAmplitude(), 0.5 * k * a * a, 1e-15);
  EXPECT_NEAR(s.elevation(0.0, 0.0), a + 0.5 * k * a * a, 1e-15);
}

// Dean & Dalrymple's shallow-water form of the bound harmonic: for kd -> 0 it tends to
// (3/4) a^2 k / (kd)^3 = 3 a^2 / (4 k^2 d^3).
TEST(AiryStokes, ShallowBoundHarmonic) {
  const double a = 0.001;
  const double d = 0.05;
  const w::Stokes2Wave s(a, 20.0, d);
  const double k = s.waveNumber();
  ASSERT_LT(k * d, 0.03);
  const double expected = 3.0 * a * a / (4.0 * k * k * d * d * d);
  EXPECT_NEAR(s.secondHarmonicAmplitude(), expected, 2.0 * k * d * k * d * expected);
  EXPECT_NEAR(s.ursellNumber(), 2.0 * a * std::pow(2.0 * pi / k, 2) / std::pow(d, 3), 1e-9);
}
