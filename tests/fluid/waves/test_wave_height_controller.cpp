// The wave-height controller (issue 6 item 5) against a plant with a known transfer:
// a maker whose wave comes out with height H = k G H_req (k = 0.8, a 20% deficit)
// and reaches the gauge one period late. The multiplicative integral law must bring
// the gain to 1/k and the height to H_req, with the gain continuous in time; with the
// controller's delay set to the plant's, the error halves at each update (beta = 1/2).
#include <gtest/gtest.h>

#include <cmath>
#include <moorsph/fluid/wave_height_controller.hpp>

using namespace moorsph::fluid;

TEST(WaveHeightController, ConvergesToTheInverseTransfer) {
  WaveHeightControllerSpec spec;
  spec.target_height = 0.05;
  spec.period = 1.0;
  spec.start_time = 2.0;
  spec.delay = 1.0;  // the plant's delay: each window sees one gain
  WaveHeightController c(spec);
  const double k = 0.8, dt = 0.01;
  double previous_gain = c.gainAt(0.0);
  for (double t = 0.0; t < 40.0; t += dt) {
    const double gain_late = c.gainAt(t - spec.period);  // the gauge sees the maker a period late
    const double eta = 0.5 * k * gain_late * spec.target_height * std::sin(2.0 * M_PI * t);
    c.addSample(t, {eta, 0.9 * eta + 0.1 * eta});  // two gauges, same wave
    EXPECT_LT(std::abs(c.gainAt(t) - previous_gain), 0.5 * dt) << "t = " << t;  // continuous, bounded rate
    previous_gain = c.gainAt(t);
  }
  EXPECT_GE(c.updates(), 8);
  EXPECT_NEAR(c.gainAt(40.0), 1.0 / k, 1e-3);
  EXPECT_NEAR(c.lastHeight(), spec.target_height, 1e-4);
}

TEST(WaveHeightController, HoldsTheGainAfterStopAndRejectsBadInput) {
  WaveHeightControllerSpec spec;
  spec.target_height = 0.02;
  spec.period = 0.5;
  spec.stop_time = 2.2;
  WaveHeightController c(spec);
  for (double t = 0.0; t < 10.0; t += 0.005) c.addSample(t, {0.005 * std::sin(4.0 * M_PI * t)});  // H = 0.01
  // An update multiplies by sqrt(2) (beta = 1/2): the window [0, 1] s closes at 1 s;
  // the next opens after the gain's one-period ramp, at 1.5 s, and would close at
  // 2.5 s, after the stop.
  EXPECT_EQ(c.updates(), 1);
  EXPECT_NEAR(c.gainAt(10.0), std::sqrt(2.0), 1e-12);
  spec.beta = 1.5;
  EXPECT_THROW(WaveHeightController{spec}, std::invalid_argument);
  spec.beta = 0.5;
  spec.target_height = 0.0;
  EXPECT_THROW(WaveHeightController{spec}, std::invalid_argument);
}
