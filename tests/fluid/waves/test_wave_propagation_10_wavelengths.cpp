// Issue 6's slower validation: a regular wave at about 10 particles per wave height
// travels 10 wavelengths along a 2D tank and loses less than 5% of its height.
//
// The tank is periodic, one wavelength long (lambda = 1.0 m, d = 0.25 m, kd = 1.57,
// H = 0.05 m, T = 0.836 s), gauges every tenth of a wavelength, so the wave passes the
// gauges once per period and "distance travelled" is the distance its energy moves,
// c_g (t - t0) (c_g = 0.736 c here, the stricter of the two speeds). A forcing region
// makes the wave over the first 2.5 s and then stops; from then on nothing acts on it.
// Settings: the recommended low-dissipation wave fluid (cases::lowDissipationWaveFluid:
// the symplectic integrator, renormalised density diffusion, no XSPH, mirror floor) with
// h = 3 dx; dx = 5 mm asked, refitted to 5.56 mm (whole cells of 2h in the period),
// 9.2 particles per height, 8,100 particles.
//
// Asserted, from the per-period height (trough to crest, mean over the 10 gauges):
//  - the wave travels at least 9.5 wavelengths in the run (16 s: 16 periods free);
//  - the least-squares loss rate r of ln H against wavelengths travelled gives
//    exp(-10 r) >= 0.95: at most 5% lost in 10 wavelengths;
//  - the last period's height is >= 95% of the first free period's.
// Measured (docs/validation/wave-propagation.md, session 18): H/H0 = 0.969 after 9.86
// wavelengths, r = 0.0039 per wavelength, 96.2% left after 10; 2,948 s on one thread of
// a busy machine (about 40 minutes on an idle one). With predictor_fraction 0.55 in
// place of the symplectic step the same run loses 5.2-5.3% (fails; 4.5% with 0.52,
// which is not stable at a piston); the reference method loses 58% at 9.6 per height.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>
#include <moorsph/fluid/waves/dispersion.hpp>
#include "wave_tanks.hpp"

using namespace moorsph;

namespace {

/// Least-squares slope of -ln(H) against distance: the log loss per unit distance.
double logLossRate(const std::vector<double>& distance, const std::vector<double>& height) {
  const double n = static_cast<double>(distance.size());
  double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
  for (std::size_t i = 0; i < distance.size(); ++i) {
    const double y = std::log(height[i]);
    sx += distance[i];
    sy += y;
    sxx += distance[i] * distance[i];
    sxy += distance[i] * y;
  }
  return -(n * sxy - sx * sy) / (n * sxx - sx * sx);
}

}  // namespace

TEST(LogLossRate, RecoversAnExponentialDecay) {
  std::vector<double> d, h;
  for (int i = 0; i < 10; ++i) {
    d.push_back(0.5 + i);
    h.push_back(0.05 * std::exp(-0.0123 * d.back()));
  }
  EXPECT_NEAR(logLossRate(d, h), 0.0123, 1e-12);
}

TEST(WavePropagationValidation, TenWavelengthsLoseUnderFivePercent) {
  cases::PeriodicWaveTankSpec spec;  // T = 0.836 s, d = 0.25 m, lambda = 1.0 m
  spec.fluid = cases::lowDissipationWaveFluid(0.005);
  spec.fluid.method.h_factor = 3.0;
  spec.floor = "mirror";
  spec.amplitude = 0.025;
  spec.ramp_up = 1.0;
  spec.forcing_end = 2.5;
  auto tank = cases::buildPeriodicWaveTank(spec);
  const double end = 16.0;
  const auto rec = cases::runAndRecord(tank, end, tank.period / 50.0);

  const double k = 2.0 * M_PI / tank.wavelength;
  const double cg = fluid::waves::groupSpeed(k, tank.depth, 9.81);
  std::vector<double> travelled, height;
  for (double a = spec.forcing_end; a + tank.period <= end + 1e-9; a += tank.period) {
    double h = 0.0;
    for (const auto& eta : rec.eta) h += cases::meanWaveHeight(rec.t, eta, tank.period, a, a + tank.period);
    travelled.push_back(cg * (a + 0.5 * tank.period - spec.forcing_end) / tank.wavelength);
    height.push_back(h / rec.eta.size());
  }
  ASSERT_GE(height.size(), 3u);
  std::printf("%zu particles, depth %.4f m\n", tank.sim->fluid().size(), tank.depth);
  std::printf("wavelengths travelled  H [m]  H/H0\n");
  for (std::size_t i = 0; i < height.size(); ++i)
    std::printf("%8.2f  %.5f  %.4f\n", travelled[i], height[i], height[i] / height.front());
  const double rate = logLossRate(travelled, height);
  std::printf("loss rate %.4f per wavelength: %.1f%% of the height left after 10 wavelengths\n", rate,
              100.0 * std::exp(-10.0 * rate));

  EXPECT_GE(travelled.back(), 9.5);
  EXPECT_GE(std::exp(-10.0 * rate), 0.95);
  EXPECT_GE(height.back() / height.front(), 0.95);
}
