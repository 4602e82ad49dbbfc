// A free regular wave in a periodic tank (issue 6 item 4; the study is in
// docs/validation/wave-propagation.md). A forcing region makes the wave, then stops at
// t = 2.5 s. The wave runs freely for 6.5 s, 4.1 wavelengths at the group speed. Its
// period must be the one the linear dispersion relation gives for the tank's
// wavenumber (k = 2 pi / L), to 3%. Stokes' amplitude dispersion, of order (ka)^2 with
// ka = 0.16 at the start, shortens the period of a finite wave by a few percent, and
// by less as the wave decays. Measured from the study's runs: +0.1% here, -1.1% at
// 9.6 particles per height and -2.7% with density diffusion. The height loss is measured and printed: 0.207 per
// wavelength at this resolution (3.4 particles per height). That is far from the 5% in
// 10 wavelengths issue 6 asks for, so the loss is reported, not asserted;
// see the study for its causes.
//
// The second test runs the low-dissipation settings of the session-7/8/16/18 studies
// (h = 2 dx, the symplectic integrator, no XSPH, renormalised density diffusion, mirror
// floor) at 4 particles per height: an inviscid wave keeps its height (water's viscosity
// takes 1e-4 of it per wavelength), and these settings must keep 95% of it over 1.27
// wavelengths; they keep 97.5% (97.3% with predictor fraction 0.55; 97.6% with the
// midpoint predictor, which lets particle noise grow over longer runs; 95.0% with a floor
// of wall particles, the reference method 71%; docs/validation/wave-propagation.md).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <moorsph/fluid/waves/dispersion.hpp>
#include "wave_tanks.hpp"

using namespace moorsph;

TEST(WavePropagation, FreeWaveKeepsTheDispersionPeriod) {
  cases::PeriodicWaveTankSpec spec;  // T = 0.836 s, d = 0.25 m, lambda = 1.0 m, H = 0.05 m
  spec.fluid.dx = 0.0125;
  spec.amplitude = 0.025;
  spec.ramp_up = 1.0;
  spec.forcing_end = 2.5;
  auto tank = cases::buildPeriodicWaveTank(spec);
  const double end = 9.0;
  const auto rec = cases::runAndRecord(tank, end, tank.period / 50.0);

  // The free wave's frequency: the peak of the periodogram sum_gauges |sum_j eta_j
  // exp(i w t_j)|^2 over the free part of the record (zero crossings would be fooled
  // by particle noise once the wave is small).
  const double w0 = 2.0 * M_PI / tank.period;
  double best_w = 0.0, best_power = -1.0;
  for (double w = 0.8 * w0; w <= 1.2 * w0; w += 0.0005 * w0) {
    double power = 0.0;
    for (const auto& eta : rec.eta) {
      double mean = 0.0;
      int n = 0;
      for (std::size_t j = 0; j < rec.t.size(); ++j)
        if (rec.t[j] > spec.forcing_end) { mean += eta[j]; ++n; }
      mean /= n;
      double re = 0.0, im = 0.0;
      for (std::size_t j = 0; j < rec.t.size(); ++j) {
        if (rec.t[j] <= spec.forcing_end) continue;
        re += (eta[j] - mean) * std::cos(w * rec.t[j]);
        im += (eta[j] - mean) * std::sin(w * rec.t[j]);
      }
      power += re * re + im * im;
    }
    if (power > best_power) { best_power = power; best_w = w; }
  }
  const double measured = 2.0 * M_PI / best_w;
  const double k = 2.0 * M_PI / tank.wavelength;
  const double theory = 2.0 * M_PI / fluid::waves::angularFrequencyFromWaveNumber(k, tank.depth);
  std::printf("free-wave period %.4f s, dispersion relation %.4f s (%+.2f%%)\n", measured, theory,
              100.0 * (measured / theory - 1.0));
  EXPECT_NEAR(measured / theory, 1.0, 0.03);

  double h0 = 0.0, h_end = 0.0;
  for (const auto& eta : rec.eta) {
    h0 += cases::meanWaveHeight(rec.t, eta, tank.period, spec.forcing_end, spec.forcing_end + tank.period);
    h_end += cases::meanWaveHeight(rec.t, eta, tank.period, end - tank.period, end);
  }
  h0 /= rec.eta.size();
  h_end /= rec.eta.size();
  std::printf("height %.4f m after the forcing, %.4f m 4.1 wavelengths later\n", h0, h_end);
}

TEST(WavePropagation, LowDissipationSettingsKeepTheHeight) {
  cases::PeriodicWaveTankSpec spec;
  spec.fluid = cases::lowDissipationWaveFluid(0.0125);
  spec.floor = "mirror";
  spec.amplitude = 0.025;
  spec.ramp_up = 1.0;
  spec.forcing_end = 2.5;
  auto tank = cases::buildPeriodicWaveTank(spec);
  const double first = spec.forcing_end, last = spec.forcing_end + 2.0 * tank.period;
  const auto rec = cases::runAndRecord(tank, last + tank.period, tank.period / 50.0);
  double h0 = 0.0, h1 = 0.0;
  for (const auto& eta : rec.eta) {
    h0 += cases::meanWaveHeight(rec.t, eta, tank.period, first, first + tank.period);
    h1 += cases::meanWaveHeight(rec.t, eta, tank.period, last, last + tank.period);
  }
  const double k = 2.0 * M_PI / tank.wavelength;
  const double travelled = fluid::waves::groupSpeed(k, tank.depth, 9.81) * (last - first) / tank.wavelength;
  std::printf("low-dissipation settings: H %.4f m -> %.4f m over %.2f wavelengths (%.1f%% kept)\n",
              h0 / rec.eta.size(), h1 / rec.eta.size(), travelled, 100.0 * h1 / h0);
  EXPECT_GT(h1 / h0, 0.95);
}
