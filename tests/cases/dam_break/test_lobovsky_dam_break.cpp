// The Lobovsky et al. (2014) dam break, H = 300 mm (cases/dam_break/lobovsky_h300_2d.yaml)
// at the coarse dx = 10 mm (H/30, 1,800 fluid particles), against the measured pressure at
// their sensor 2 (far wall, z = 15 mm). Outside numbers, from the 100-repeat statistics in
// ../shared/refdata/lobovsky2014/ (p in rho g H, t in T = sqrt(H/g)):
//  - the median first exceeds 0.1 at t/T = 2.46 (the front's arrival; it depends on the
//    collapse and the run along the floor, not on the impact's details);
//  - the median's mean over t/T 3.5-5.5 is 0.589 (the wall carrying the run-up: a
//    quasi-static load);
//  - the median's trailing mean over 4 H / c_s = 34.3 ms (the scene's probe moving_mean)
//    peaks at 1.76 over the first impact.
// Asserted: the run finishes (no particle escapes: the run guards would stop it); the
// arrival within 0.1 T of the median's; the plateau between 0.6 and 1.2 times the median's;
// the smoothed first impact is an impact (above 1.5 times the plateau) and no acoustic
// blow-up (below 1.5 times the median's 1.76).
// Why the plateau's bounds are that wide: after the impact the flow is chaotic, and one
// run's plateau is one draw. Ten 10 mm runs that differed only in the time step (CFL
// 0.2-0.5), the integrator or the thread count (summation order) gave 0.366-0.558, mean
// 0.463 (docs/validation/lobovsky-dam-break.md, session 35); the experiment's own
// repeats spread 0.471-0.704 (its 2.5-97.5 % curves averaged over the window). The former
// bound (10% of the median) passed only for the time step it was set at. The bounds still
// catch a lost wall load or a density drift such as particle shifting's (+45% here).
// Measured at this setting (CFL 0.3, two threads): arrival 2.485, plateau 0.524, smoothed
// peak 0.99.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <moorsph/io/csv_export.hpp>
#include "run/run_scene.hpp"
#include "run_support.hpp"

using namespace moorsph;

namespace {
constexpr double kH = 0.3, kG = 9.81, kRho = 1000.0;
const double kT = std::sqrt(kH / kG), kP = kRho * kG * kH;

double meanOver(const test_support::ExportedSeries& s, double from, double to) {
  double sum = 0.0;
  int n = 0;
  for (std::size_t k = 0; k < s.time.size(); ++k)
    if (s.time[k] / kT >= from && s.time[k] / kT <= to) sum += s.value[k], ++n;
  return n ? sum / n / kP : std::nan("");
}
}  // namespace

TEST(LobovskyDamBreak, ArrivalPlateauAndImpactAtSensor2AgainstTheExperiment) {
  const std::string source = std::getenv("MOORSPH_SOURCE_DIR") ? std::getenv("MOORSPH_SOURCE_DIR") : ".";
  app::RunOptions o;
  o.scene = source + "/cases/dam_break/lobovsky_h300_2d.yaml";
  o.out = testing::TempDir() + "moorsph_lobovsky";
  o.threads = 2;
  o.sets = {"resolution.dx=0.01", "resolution.boundary_spacing=0.01", "output.particles_interval=0"};
  std::filesystem::remove_all(o.out);
  ASSERT_EQ(app::runScene(o), app::kSuccess);
  ASSERT_GT(io::exportSeriesCsv(o.out).size(), 0u);
  const auto raw = test_support::exportedSeries(o.out, "probes.P2_interpolated");
  const auto smooth = test_support::exportedSeries(o.out, "probes.P2_interpolated_mean");
  ASSERT_GT(raw.time.size(), 2000u);
  ASSERT_NEAR(raw.time.back() / kT, 7.15, 0.01);

  double arrival = std::nan("");
  for (std::size_t k = 0; k < raw.time.size(); ++k)
    if (raw.value[k] > 0.1 * kP) {
      arrival = raw.time[k] / kT;
      break;
    }
  const double plateau = meanOver(raw, 3.5, 5.5);
  double peak = 0.0;
  for (std::size_t k = 0; k < smooth.time.size(); ++k)
    if (smooth.time[k] / kT >= 1.8 && smooth.time[k] / kT <= 3.2) peak = std::max(peak, smooth.value[k] / kP);
  std::printf("sensor 2 at dx = 10 mm: arrival t/T %.3f (measured 2.46), plateau %.3f rho g H (0.589), "
              "34 ms mean peak %.2f (1.76)\n", arrival, plateau, peak);
  EXPECT_NEAR(arrival, 2.46, 0.1);
  EXPECT_GT(plateau, 0.6 * 0.589);
  EXPECT_LT(plateau, 1.2 * 0.589);
  EXPECT_GT(peak, 1.5 * plateau);
  EXPECT_LT(peak, 1.5 * 1.76);
}
