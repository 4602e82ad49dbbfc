// The 2D dam break of cases/dam_break/martin_moyce_2d.yaml (column a = 0.1 m wide, 2a
// high, dry floor 20a long) at dx = a/20 (800 fluid particles), against the surge front
// Martin & Moyce (1952, Fig. 3) measured for n^2 = 2, a = 2.25 in
// (cases/dam_break/martin_moyce_1952_a2.25in.csv; Z = x/a against T = t sqrt(2g/a)).
// The model's wall is free-slip and its release instantaneous; the experiment had bed
// friction and a gate that took time to clear. So the computed front must lie between
// the measured one (it cannot lag it by more than the 3% digitising scatter) and Ritter's
// inviscid shallow-water front Z = 1 + 2T (Ritter 1892; it ignores the column's fall),
// at every measured time up to T = 9.2 (t = 0.66 s, Z = 14).
// Measured at a/20 (docs/accuracy-cost.md): Z / Z_measured 1.05-1.20, about 0.2-0.4 in T
// ahead; the front speed over T 5.1-9.2 is dZ/dT 1.93 against the measured 1.69.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>
#include "run/run_scene.hpp"
#include "study/run_data.hpp"

using namespace moorsph;

namespace {
constexpr double kA = 0.1, kG = 9.81, kDx = 0.005;
const double kTPerSecond = std::sqrt(2.0 * kG / kA);
}  // namespace

TEST(MartinMoyceDamBreak, FrontLiesBetweenTheMeasuredFrontAndRitter) {
  const std::string source = std::getenv("MOORSPH_SOURCE_DIR") ? std::getenv("MOORSPH_SOURCE_DIR") : ".";
  // T,Z rows; the comment and header lines are skipped as in a study's reference file.
  const auto table = app::study::readCsvSeries(source + "/cases/dam_break/martin_moyce_1952_a2.25in.csv");
  const std::vector<double>& T = table.time;
  const std::vector<double>& Z = table.value;
  ASSERT_EQ(T.size(), 15u) << "the measured table did not load";

  app::RunOptions o;
  o.scene = source + "/cases/dam_break/martin_moyce_2d.yaml";
  o.out = testing::TempDir() + "moorsph_martin_moyce";
  o.threads = 2;
  o.sets = {"resolution.dx=0.005", "resolution.boundary_spacing=0.005"};
  std::filesystem::remove_all(o.out);
  ASSERT_EQ(app::runScene(o), app::kSuccess);
  const auto front = app::study::readFrontSeries(o.out, 0.0, 2.0 * kDx);
  ASSERT_GT(front.time.size(), 60u);

  std::vector<double> computed;
  for (std::size_t k = 0; k < T.size(); ++k) {
    const double t = T[k] / kTPerSecond;
    ASSERT_LE(t, front.time.back());
    const double z = app::study::valueAt(front, t) / kA;
    computed.push_back(z);
    std::printf("T %.3f  Z measured %.3f  computed %.3f (x %.3f)  Ritter %.2f\n", T[k], Z[k], z,
                z / Z[k], 1.0 + 2.0 * T[k]);
    EXPECT_GE(z, 0.97 * Z[k]) << "front behind the measured one at T = " << T[k];
    EXPECT_LE(z, 1.0 + 2.0 * T[k] + kDx / kA) << "front beyond Ritter's at T = " << T[k];
  }
  const std::size_t first = 7, last = T.size() - 1;  // T = 5.09 .. 9.24, the free run
  const double speed_measured = (Z[last] - Z[first]) / (T[last] - T[first]);
  const double speed = (computed[last] - computed[first]) / (T[last] - T[first]);
  std::printf("front speed dZ/dT over T %.2f-%.2f: computed %.3f, measured %.3f, Ritter 2\n", T[first],
              T[last], speed, speed_measured);
  EXPECT_LE(speed, 2.0) << "faster than Ritter's front";
}
