// Peregrine breathers of orders 1 and 2 (METHOD.md 4c): the NLS by finite differences,
// the peak amplifications, the background, and the dimensional scaling.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <functional>

#include <moorsph/fluid/waves/peregrine_breather.hpp>

namespace w = moorsph::fluid::waves;
using C = std::complex<double>;

namespace {

const C I(0.0, 1.0);

// Eighth-order central stencils: truncation ~ h^8 f^(9) / 630, round-off ~ eps |f| / h^2.
const double kD1[5] = {0.0, 4.0 / 5.0, -1.0 / 5.0, 4.0 / 105.0, -1.0 / 280.0};
const double kD2[5] = {-205.0 / 72.0, 8.0 / 5.0, -1.0 / 5.0, 8.0 / 315.0, -1.0 / 560.0};

C diff1(const std::function<C(double)>& f, double s, double h) {
  C sum = 0.0;
  for (int j = 1; j <= 4; ++j) sum += kD1[j] * (f(s + j * h) - f(s - j * h));
  return sum / h;
}
C diff2(const std::function<C(double)>& f, double s, double h) {
  C sum = kD2[0] * f(s);
  for (int j = 1; j <= 4; ++j) sum += kD2[j] * (f(s + j * h) + f(s - j * h));
  return sum / (h * h);
}

using Envelope = std::function<C(double, double)>;

// max over a 25 x 25 grid of |i psi_T + psi_XX + 2|psi|^2 psi| / max(1, |psi|^3) (the size of
// the largest term: relative to the field magnitude).
double worstNlsResidual(const Envelope& psi, double h) {
  double worst = 0.0;
  for (double X = -3.0; X <= 3.0001; X += 0.25) {
    for (double T = -1.5; T <= 1.5001; T += 0.125) {
      const C p = psi(X, T);
      const C pT = diff1([&](double s) { return psi(X, s); }, T, h);
      const C pXX = diff2([&](double s) { return psi(s, T); }, X, h);
      const C r = I * pT + pXX + 2.0 * std::norm(p) * p;
      const double mag = std::abs(p);
      worst = std::max(worst, std::abs(r) / std::max(1.0, mag * mag * mag));
    }
  }
  return worst;
}

// The order-2 envelope with the misprinted -15/8 in H2: the test must be able to see it.
C misprintedOrder2(double X, double T) {
  const double X2 = X * X, T2 = T * T, r = X2 + 4.0 * T2, m = X2 - 12.0 * T2;
  const double G = 0.75 - (r + 0.75) * (X2 + 20.0 * T2 + 0.75);
  const double H = 2.0 * T * (3.0 * X2 - 4.0 * T2 - 2.0 * r * r - 15.0 / 8.0);
  const double D = r * r * r / 3.0 + m * m / 4.0 + 3.0 * (12.0 * X2 + 176.0 * T2 + 1.0) / 64.0;
  return C(1.0 + G / D, H / D) * std::polar(1.0, 2.0 * T);
}

}  // namespace

TEST(PeregrineBreather, BothOrdersSolveNlsByFiniteDifferences) {
  for (int order : {1, 2}) {
    const Envelope psi = [order](double X, double T) {
      return w::peregrineNormalizedEnvelope(order, X, T);
    };
    // Two step sizes, both small enough that the h^8 truncation error at the narrow order-2
    // peak (2.4e-5 at h = 0.01, 2.4e-9 at h = 0.003) is below the round-off floor (~eps |psi| / h^2,
    // about 3e-10 here): the residual must be small for both (no lucky cancellation).
    const double r1 = worstNlsResidual(psi, 2.5e-3);
    const double r2 = worstNlsResidual(psi, 2e-3);
    std::printf("order %d: max NLS residual %.3g (h = 0.0025), %.3g (h = 0.002)\n", order, r1, r2);
    EXPECT_LT(r1, 1e-8);
    EXPECT_LT(r2, 1e-8);
  }
  const double bad = worstNlsResidual(misprintedOrder2, 2e-3);
  std::printf("misprinted order 2 (-15/8): max NLS residual %.3g\n", bad);
  EXPECT_GT(bad, 1e-2);
}

TEST(PeregrineBreather, PeakAmplificationsAreThreeAndFive) {
  EXPECT_NEAR(std::abs(w::peregrineNormalizedEnvelope(1, 0.0, 0.0)), 3.0, 1e-15);
  EXPECT_NEAR(std::abs(w::peregrineNormalizedEnvelope(2, 0.0, 0.0)), 5.0, 1e-15);
  // ... and they are the maxima of |psi| over the (X, T) plane.
  for (int order : {1, 2}) {
    double peak = 0.0;
    for (double X = -4.0; X <= 4.0; X += 0.01)
      for (double T = -2.0; T <= 2.0; T += 0.01)
        peak = std::max(peak, std::abs(w::peregrineNormalizedEnvelope(order, X, T)));
    EXPECT_LE(peak, 2.0 * order + 1.0 + 1e-12);
  }
  const w::PeregrineBreather b1(1, 0.01, 6.0);
  const w::PeregrineBreather b2(2, 0.01, 5.0);
  EXPECT_NEAR(b1.elevation(0.0, 0.0), 3.0 * 0.01, 1e-15);  // crest at the focus
  EXPECT_NEAR(b2.elevation(0.0, 0.0), 5.0 * 0.01, 1e-15);
  EXPECT_NEAR(b1.envelopeAmplitude(0.0, 0.0) / b1.carrierAmplitude(), 3.0, 1e-14);
  EXPECT_NEAR(b2.envelopeAmplitude(0.0, 0.0) / b2.carrierAmplitude(), 5.0, 1e-14);
}

TEST(PeregrineBreather, BackgroundAndCarrier) {
  for (int order : {1, 2}) {
    EXPECT_NEAR(std::abs(w::peregrineNormalizedEnvelope(order, 1e4, 0.3)), 1.0, 1e-6);
    EXPECT_NEAR(std::abs(w::peregrineNormalizedEnvelope(order, 0.2, 1e4)), 1.0, 1e-6);
  }
  // METHOD.md 6.4: k0 = 6 -> omega0 = 7.6720, k0 = 5 -> omega0 = 7.0036 (deep water).
  EXPECT_NEAR(w::PeregrineBreather(1, 0.01, 6.0).carrierAngularFrequency(), 7.6720, 5e-5);
  EXPECT_NEAR(w::PeregrineBreather(2, 0.01, 5.0).carrierAngularFrequency(), 7.0036, 5e-5);
  EXPECT_NEAR(w::PeregrineBreather(1, 0.01, 6.0).steepness(), 0.06, 1e-15);
  EXPECT_THROW(w::PeregrineBreather(3, 0.01, 6.0), std::invalid_argument);
}

// The dimensional envelope A(x,t) = psi_j(X(x,t), T(t)) solves the deep-water NLS of
// Zakharov (1968) for eta = Re{A exp(i(k0 x - omega0 t))}:
//   i (A_t + c_g A_x) - omega0/(8 k0^2) A_xx - (omega0 k0^2 / 2) |A|^2 A = 0,  c_g = omega0/(2 k0)
// (its linear part is the Taylor expansion of omega = sqrt(g k), its nonlinear part the Stokes
// frequency correction omega0 k0^2 a^2 / 2). This checks METHOD's scaled variables.
TEST(PeregrineBreather, DimensionalScalingSolvesDeepWaterNls) {
  for (int order : {1, 2}) {
    const w::PeregrineBreather b(order, 0.01, 6.0);
    const double k0 = b.carrierWaveNumber();
    const double w0 = b.carrierAngularFrequency();
    const double cg = w0 / (2.0 * k0);
    const auto A = [&](double x, double t) { return b.envelope(b.scaledX(x, t), b.scaledT(t)); };
    const double hx = 0.003 / (k0 * b.psi0());
    // The time step must resolve the envelope's motion at c_g (X changes by (omega0/2) psi0 per
    // second), not only the slow scaled time T; A_t and c_g A_x then cancel to FD accuracy.
    const double ht = 0.003 / (0.5 * w0 * b.psi0());
    const double scale = w0 * k0 * k0 * std::pow(b.carrierAmplitude(), 3);
    double worst = 0.0;
    for (double x : {-2.0, -0.5, 0.0, 0.3, 1.7})
      for (double t : {-30.0, -5.0, 0.0, 2.0, 12.0}) {
        const C a = A(x, t);
        const C at = diff1([&](double s) { return A(x, s); }, t, ht);
        const C ax = diff1([&](double s) { return A(s, t); }, x, hx);
        const C axx = diff2([&](double s) { return A(s, t); }, x, hx);
        const C r = I * (at + cg * ax) - w0 / (8.0 * k0 * k0) * axx -
                    0.5 * w0 * k0 * k0 * std::norm(a) * a;
        worst = std::max(worst, std::abs(r) / scale);
      }
    std::printf("order %d: dimensional NLS residual / (omega0 k0^2 a0^3) = %.3g\n", order, worst);
    EXPECT_LT(worst, 1e-7);
  }
}
