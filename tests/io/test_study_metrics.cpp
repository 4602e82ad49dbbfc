// The pieces of `moorsph study` on synthetic data with known answers: each metric,
// the observed order and the Richardson extrapolate (Celik et al. 2008), the front of
// a particle snapshot, the reference CSV reader, argument parsing and the analysis.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <stdexcept>
#include "study/convergence.hpp"
#include "study/metrics.hpp"
#include "study/run_data.hpp"
#include "study/series_expression.hpp"
#include "study/study.hpp"

namespace st = moorsph::app::study;

namespace {

const double kPi = 3.14159265358979323846;

st::Series sample(const std::function<double(double)>& f, double t0, double t1, double dt) {
  st::Series s;
  const long n = std::lround((t1 - t0) / dt);
  for (long k = 0; k <= n; ++k) {
    const double t = t0 + static_cast<double>(k) * dt;
    s.time.push_back(t);
    s.value.push_back(f(t));
  }
  return s;
}

}  // namespace

TEST(StudyMetrics, ValueAtInterpolatesLinearlyAndRefusesOutsideTheSpan) {
  const auto s = sample([](double t) { return 2.0 * t + 1.0; }, 0.0, 1.0, 0.1);
  EXPECT_NEAR(st::valueAt(s, 0.35), 1.7, 1e-12);
  EXPECT_NEAR(st::valueAt(s, 0.0), 1.0, 1e-12);
  EXPECT_NEAR(st::valueAt(s, 1.0), 3.0, 1e-12);
  EXPECT_THROW(st::valueAt(s, 1.2), std::invalid_argument);
}

TEST(StudyMetrics, MeanValueIsTheTimeAverageOverTheWindow) {
  // Linear: the trapezoidal rule is exact; 3 + t on [0, 2] averages 4.
  EXPECT_NEAR(st::meanValue(sample([](double t) { return 3.0 + t; }, 0.0, 5.0, 0.01), {0.0, 2.0}), 4.0, 1e-9);
  // A whole number of periods of a sine about 0.25 averages 0.25 (an equilibrium draught).
  const auto heave = sample([](double t) { return 0.25 + 0.1 * std::sin(2.0 * kPi * t / 0.8); }, 0.0, 10.0, 1e-3);
  EXPECT_NEAR(st::meanValue(heave, {2.0, 6.0}), 0.25, 1e-6);
}

TEST(StudyMetrics, CycleMeanRemovesTheBiasOfAFractionalWindow) {
  // A draught of 0.05 m heaving 11 mm with period 0.72 s: over 1.5-3 s (2.08 periods)
  // the plain mean is off by up to a / (pi N); over whole cycles it is not.
  const auto draught = sample([](double t) { return 0.05 + 0.011 * std::sin(2.0 * kPi * t / 0.72 + 0.7); }, 0.0, 3.0, 0.01);
  const st::Window w{1.5, 3.0};
  EXPECT_GT(std::abs(st::meanValue(draught, w) - 0.05), 3e-4);
  EXPECT_NEAR(st::cycleMean(draught, w), 0.05, 2e-5);
  // A decaying oscillation about a level: the whole-cycle mean stays near the level.
  const auto decay = sample([](double t) { return 0.2 + 0.01 * std::exp(-t / 2.0) * std::cos(2.0 * kPi * t / 0.75); }, 0.0, 6.0, 0.01);
  EXPECT_NEAR(st::cycleMean(decay, {2.0, 6.0}), 0.2, 1e-4);
  EXPECT_THROW(st::cycleMean(draught, {1.5, 1.8}), std::invalid_argument);  // less than one cycle
}

TEST(StudyMetrics, RelaxedLevelIsThePlateauOfACreepingMean) {
  // A held body's buoyancy: 46 N relaxing to 39.5 N with tau = 1.5 s, under a 0.45 s
  // slosh of 2 N. Any window mean depends on where the window sits; the fit does not.
  const auto creep = [](double t) { return 39.5 + 6.5 * std::exp(-t / 1.5) + 2.0 * std::sin(2.0 * kPi * t / 0.45); };
  const auto s = sample(creep, 0.0, 6.0, 0.005);
  EXPECT_GT(st::meanValue(s, {1.0, 6.0}) - 39.5, 0.5);
  // (11.1 slosh periods: the fractional one leaves ~0.15 N, 2% of the relaxation.)
  EXPECT_NEAR(st::relaxedLevel(s, {1.0, 6.0}), 39.5, 0.2);
  EXPECT_NEAR(st::relaxedLevel(sample([](double t) { return 2.0 - 0.3 * std::exp(-t / 0.7); }, 0.0, 4.0, 0.01), {0.5, 4.0}),
              2.0, 1e-6);
  // Steady: a constant under an oscillation gives its mean.
  const auto steady = sample([](double t) { return 5.0 + 0.2 * std::cos(2.0 * kPi * t / 0.3); }, 0.0, 3.0, 0.002);
  EXPECT_NEAR(st::relaxedLevel(steady, {0.0, 3.0}), 5.0, 0.01);
  // Not half-way there: a steady ramp (or tau = 4 s seen over 1.5 s) is refused.
  EXPECT_THROW(st::relaxedLevel(sample([](double t) { return 1.0 - 0.1 * t; }, 0.0, 2.0, 0.01), {0.0, 2.0}),
               std::invalid_argument);
  const auto smooth = sample([](double t) { return 39.5 + 6.5 * std::exp(-t / 1.5); }, 0.0, 6.0, 0.005);
  EXPECT_THROW(st::relaxedLevel(smooth, {1.0, 1.6}), std::invalid_argument);
  EXPECT_NEAR(st::relaxedLevel(smooth, {1.0, 3.2}), 39.5, 1e-6);  // tau = 1.5 s < 2.2 s / ln 2
}

TEST(StudyMetrics, PeakAmplitudeIsTheLargestExcursionFromTheWindowStart) {
  const auto s = sample([](double t) { return 2.0 + 0.5 * std::sin(2.0 * kPi * t); }, 0.0, 3.0, 1e-3);
  EXPECT_NEAR(st::peakAmplitude(s, {0.0, 1.0}), 0.5, 1e-9);
  // Starting at the crest (t = 0.25), the largest excursion is crest to trough.
  EXPECT_NEAR(st::peakAmplitude(s, {0.25, 1.25}), 1.0, 1e-4);  // the crest sample may fall just outside
}

TEST(StudyMetrics, MaxValueAndItsTimeOfAnImpactPulse) {
  // A Gaussian pulse 1.87 high at t = 0.455 s on a 0.58 plateau after it (a wall pressure
  // history's shape): the window's maximum and its time, and only inside the window.
  const auto pulse = [](double t) {
    return 1.87 * std::exp(-std::pow((t - 0.455) / 0.01, 2)) + (t > 0.5 ? 0.58 : 0.0);
  };
  const auto s = sample(pulse, 0.0, 1.2, 1e-4);
  EXPECT_NEAR(st::maxValue(s, {}), 1.87, 1e-6);
  EXPECT_NEAR(st::timeOfMax(s, {}), 0.455, 1e-4);
  EXPECT_NEAR(st::maxValue(s, {0.6, 1.2}), 0.58, 1e-12);
  EXPECT_NEAR(st::evaluateMetric("time_of_max", s, {std::numeric_limits<double>::quiet_NaN(), {0.3, 0.6}}), 0.455, 1e-4);
  EXPECT_THROW(st::maxValue(s, {2.0, 3.0}), std::invalid_argument);
}

TEST(StudyMetrics, FirstPeakOfADampedOscillation) {
  // x = exp(-a t) cos(b t) starts at its top (t = 0, not a peak: nothing rises into it);
  // its first maximum after that is where tan(b t) = -a/b, near t = 2 pi / b.
  const double zeta = 0.05, omega = 2.0 * kPi, a = zeta * omega, b = omega * std::sqrt(1.0 - zeta * zeta);
  const auto x = [&](double t) { return std::exp(-a * t) * std::cos(b * t); };
  const double t_peak = (2.0 * kPi - std::atan(a / b)) / b;
  const auto s = sample(x, 0.0, 5.0, 1e-4);
  EXPECT_NEAR(st::firstPeak(s, {}, 0.2), x(t_peak), 1e-6);
  // Starting in a trough: the first peak of -cos(2 pi t) is 1 at t = 0.5.
  EXPECT_NEAR(st::firstPeak(sample([](double t) { return -std::cos(2.0 * kPi * t); }, 0.0, 2.0, 1e-3), {}, 0.1), 1.0, 1e-5);
  // A monotone series has no peak.
  EXPECT_THROW(st::firstPeak(sample([](double t) { return t; }, 0.0, 1.0, 0.01), {}, 0.1), std::invalid_argument);
}

TEST(StudyMetrics, WaveHeightAndPeriodFromZeroUpCrossings) {
  // eta = 0.1 + 0.3 sin(2 pi t / 0.8): H = 0.6 crest to trough, T = 0.8 s, whatever the mean.
  const auto eta = sample([](double t) { return 0.1 + 0.3 * std::sin(2.0 * kPi * t / 0.8); }, 0.0, 8.0, 1e-3);
  EXPECT_NEAR(st::waveHeight(eta, {1.0, 7.0}), 0.6, 1e-5);
  EXPECT_NEAR(st::periodBetweenPeaks(eta, {1.0, 7.0}), 0.8, 1e-3);  // crests on the 1 ms grid
  // A non-sinusoidal wave, sin x - 0.2 sin 3x = sin x (0.4 + 0.8 sin^2 x) (x = 2 pi t):
  // one up-crossing per period, crest 1.2 at x = pi/2, trough -1.2: H = 2.4, T = 1 s.
  const auto two = sample([](double t) { return std::sin(2.0 * kPi * t) - 0.2 * std::sin(6.0 * kPi * t); }, 0.0, 6.0, 1e-4);
  EXPECT_NEAR(st::waveHeight(two, {0.5, 5.5}), 2.4, 1e-6);
  EXPECT_NEAR(st::periodBetweenPeaks(two, {0.5, 5.5}), 1.0, 1e-3);
  EXPECT_THROW(st::waveHeight(sample([](double t) { return t; }, 0.0, 1.0, 0.01), {}), std::invalid_argument);
}

TEST(StudyMetrics, RmsDifferenceAgainstAReferenceSeries) {
  const auto run = sample([](double t) { return 2.0 * t; }, 0.0, 2.0, 0.01);
  // A reference offset by 0.05 at its own (coarser, unaligned) times: RMS 0.05 exactly,
  // counting only reference samples in the window and in the run's span.
  const auto ref = sample([](double t) { return 2.0 * t + 0.05; }, 0.013, 3.0, 0.07);
  EXPECT_NEAR(st::rmsDifference(run, ref, {}), 0.05, 1e-12);
  EXPECT_NEAR(st::evaluateMetric("gauge_rms", run, {}, &ref), 0.05, 1e-12);
  EXPECT_THROW(st::evaluateMetric("gauge_rms", run, {}), std::invalid_argument);
  EXPECT_THROW(st::rmsDifference(run, ref, {5.0, 6.0}), std::invalid_argument);
}

TEST(StudyMetrics, RegistryNamesEveryMetric) {
  for (const char* name : {"front_position", "value_at", "mean_value", "cycle_mean", "relaxed_level", "peak_amplitude", "first_peak", "max_value", "time_of_max", "wave_height",
                           "period_between_peaks", "gauge_rms"})
    EXPECT_NE(st::findMetric(name), nullptr) << name;
  EXPECT_EQ(st::findMetric("front"), nullptr);
  EXPECT_THROW(st::evaluateMetric("nonsense", sample([](double t) { return t; }, 0, 1, 0.1), {}), std::invalid_argument);
}

TEST(StudyConvergence, ObservedOrderOfSyntheticErrors) {
  const std::vector<double> h = {0.04, 0.02, 0.01, 0.005};
  std::vector<double> e;
  for (double x : h) e.push_back(3.0 * x * x);
  for (double p : st::observedOrders(h, e)) EXPECT_NEAR(p, 2.0, 1e-12);
  // Unequal ratios: e = 0.5 h^1.3.
  const std::vector<double> h2 = {0.05, 0.03, 0.01};
  for (double p : st::observedOrders(h2, {0.5 * std::pow(0.05, 1.3), 0.5 * std::pow(0.03, 1.3), 0.5 * std::pow(0.01, 1.3)}))
    EXPECT_NEAR(p, 1.3, 1e-12);
  EXPECT_TRUE(std::isnan(st::observedOrders({0.02, 0.01}, {0.1, 0.0})[0]));
}

TEST(StudyConvergence, RichardsonRecoversTheLimitAndOrder) {
  // f = 1.5 + 0.7 h^1.5 (first run coarser than the three used).
  std::vector<double> h = {0.08, 0.04, 0.02, 0.01}, f;
  for (double x : h) f.push_back(1.5 + 0.7 * std::pow(x, 1.5));
  auto r = st::richardsonFromFinest(h, f);
  ASSERT_TRUE(r);
  EXPECT_NEAR(r->order, 1.5, 1e-9);
  EXPECT_NEAR(r->estimate, 1.5, 1e-9);
  // Unequal ratios, converging from below: f = 2 - 4 h^2.
  h = {0.03, 0.02, 0.01};
  f.clear();
  for (double x : h) f.push_back(2.0 - 4.0 * x * x);
  r = st::richardsonFromFinest(h, f);
  ASSERT_TRUE(r);
  EXPECT_NEAR(r->order, 2.0, 1e-9);
  EXPECT_NEAR(r->estimate, 2.0, 1e-9);
  // Oscillatory convergence has no extrapolate, and says so.
  std::string why;
  EXPECT_FALSE(st::richardsonFromFinest({0.04, 0.02, 0.01}, {1.0, 1.2, 1.1}, &why));
  EXPECT_NE(why.find("monotonically"), std::string::npos) << why;
  EXPECT_FALSE(st::richardsonFromFinest({0.02, 0.01}, {1.0, 1.1}, &why));
}

TEST(StudyRunData, FrontOfASnapshotIgnoresBoundaryAndHighParticles) {
  // (x, y, z) per particle; type 0 fluid, 1 boundary.
  const std::vector<double> pos = {0.10, 0.005, 0, 0.30, 0.005, 0,  // fluid in the band
                                   0.35, 0.05, 0,                    // fluid above the band (a splash)
                                   0.40, 0.0, 0};                    // a wall particle
  const std::vector<double> type = {0, 0, 0, 1};
  EXPECT_DOUBLE_EQ(st::frontOfSnapshot(pos, type, 1, 0.0, 0.01), 0.30);
  EXPECT_THROW(st::frontOfSnapshot(pos, type, 1, -1.0, 0.01), std::runtime_error);
}

TEST(StudyRunData, ReadsAReferenceCsvWithAHeader) {
  const std::string path = testing::TempDir() + "study_reference.csv";
  std::ofstream(path) << "time [s],front [m]\n0.0,0.1\n0.1, 0.2\n0.2,0.35\n";
  const auto s = st::readCsvSeries(path);
  ASSERT_EQ(s.time.size(), 3u);
  EXPECT_DOUBLE_EQ(s.value[1], 0.2);
  std::ofstream(path) << "t,v\n0.0,0.1\n0.0,0.2\n";
  EXPECT_THROW(st::readCsvSeries(path), std::runtime_error);  // times must increase
  EXPECT_THROW(st::readCsvSeries(path + ".missing"), std::runtime_error);
}

TEST(StudySeriesExpression, ParsesTermsAndRejectsMalformedSums) {
  const auto terms = st::parseSeriesExpression("gauges/G_left - body_box/y + 0.05");
  ASSERT_EQ(terms.size(), 3u);
  EXPECT_EQ(terms[0].name, "gauges/G_left");
  EXPECT_EQ(terms[1].sign, -1.0);
  EXPECT_EQ(terms[1].name, "body_box/y");
  EXPECT_TRUE(terms[2].name.empty());
  EXPECT_DOUBLE_EQ(terms[2].constant, 0.05);
  EXPECT_EQ(st::parseSeriesExpression("probes/P-1").size(), 1u);        // a name may hold a '-'
  EXPECT_DOUBLE_EQ(st::parseSeriesExpression("front - 1e-3")[1].constant, 1e-3);
  EXPECT_THROW(st::parseSeriesExpression(""), std::invalid_argument);
  EXPECT_THROW(st::parseSeriesExpression("gauges/G -"), std::invalid_argument);   // dangling sign
  EXPECT_THROW(st::parseSeriesExpression("gauges/G body/y"), std::invalid_argument);  // no sign between
  EXPECT_THROW(st::parseSeriesExpression("- - gauges/G"), std::invalid_argument);
  EXPECT_THROW(st::parseSeriesExpression("0.05 + 1"), std::invalid_argument);      // no series
}

TEST(StudySeriesExpression, ADraughtFromAGaugeAndABodyHeight) {
  // A box (half-height 0.05 m) heaving 8 mm about a centre 0.205 m in water whose level
  // sloshes 2 mm about 0.207 m, sampled at other times (and over a shorter span): the
  // draught level - (y - 0.05) averages 0.207 - 0.205 + 0.05 = 0.052 m over whole periods.
  const auto level = sample([](double t) { return 0.207 + 0.002 * std::sin(2.0 * kPi * t / 0.45); }, 0.0, 3.0, 0.01);
  const auto centre = sample([](double t) { return 0.205 + 0.008 * std::cos(2.0 * kPi * t / 0.75); }, 0.005, 2.905, 0.01);
  const auto load = [&](const std::string& name) {
    if (name == "gauges/G") return level;
    if (name == "body_box/y") return centre;
    throw std::runtime_error("unknown " + name);
  };
  const auto draught = st::combineSeries(st::parseSeriesExpression("gauges/G - body_box/y + 0.05"), load);
  EXPECT_DOUBLE_EQ(draught.time.front(), 0.01);  // the first base time both cover
  EXPECT_DOUBLE_EQ(draught.time.back(), 2.9);
  const double t = 1.0;
  EXPECT_NEAR(st::valueAt(draught, t), st::valueAt(level, t) - st::valueAt(centre, t) + 0.05, 1e-12);
  EXPECT_NEAR(st::meanValue(draught, {0.45, 2.7}), 0.052, 2e-6);  // 5 and 3 whole periods
  EXPECT_THROW(st::combineSeries(st::parseSeriesExpression("gauges/G + other/x"), load), std::runtime_error);
}

TEST(StudySeriesExpression, FactorsMakeAMeanOfGauges) {
  // METHOD.md 6.1's surrounding level: the mean of eight gauges, here two for brevity,
  // 0.5*G1 + 0.5*G2 - body/y + R. G1 = 0.21 + 0.01 sin, G2 = 0.21 - 0.01 sin (a sloshing
  // mode the mean cancels), body at 0.20: 0.21 - 0.20 + 0.1 = 0.11 at every time.
  const auto g1 = sample([](double t) { return 0.21 + 0.01 * std::sin(2.0 * kPi * t); }, 0.0, 2.0, 0.01);
  const auto g2 = sample([](double t) { return 0.21 - 0.01 * std::sin(2.0 * kPi * t); }, 0.0, 2.0, 0.01);
  const auto body = sample([](double) { return 0.20; }, 0.0, 2.0, 0.01);
  const auto load = [&](const std::string& name) {
    if (name == "gauges/G1") return g1;
    if (name == "gauges/G2") return g2;
    if (name == "body_s/y") return body;
    throw std::runtime_error("unknown " + name);
  };
  const auto terms = st::parseSeriesExpression("0.5*gauges/G1 + 0.5*gauges/G2 - body_s/y + 0.1");
  ASSERT_EQ(terms.size(), 4u);
  EXPECT_EQ(terms[0].name, "gauges/G1");
  EXPECT_DOUBLE_EQ(terms[0].factor, 0.5);
  EXPECT_DOUBLE_EQ(terms[2].factor, 1.0);
  const auto level = st::combineSeries(terms, load);
  for (std::size_t i = 0; i < level.time.size(); i += 37) EXPECT_NEAR(level.value[i], 0.11, 1e-12);
  const auto starred = st::parseSeriesExpression("probes/a*b")[0];  // not a number: part of the name
  EXPECT_EQ(starred.name, "probes/a*b");
  EXPECT_DOUBLE_EQ(starred.factor, 1.0);
  EXPECT_EQ(st::parseSeriesExpression("1e-1*gauges/G1")[0].factor, 0.1);
  EXPECT_THROW(st::parseSeriesExpression("0.5* + gauges/G1"), std::invalid_argument);  // factor without a series
  EXPECT_THROW(st::parseSeriesExpression("0.5*"), std::invalid_argument);
}

TEST(StudyArguments, DxListVaryAndSplitting) {
  EXPECT_EQ(st::parseDxList("0.005, 0.02,0.01"), (std::vector<double>{0.02, 0.01, 0.005}));
  EXPECT_THROW(st::parseDxList("0.01"), std::invalid_argument);
  EXPECT_THROW(st::parseDxList("0.01,abc"), std::invalid_argument);
  EXPECT_THROW(st::parseDxList("0.01,-0.005"), std::invalid_argument);
  EXPECT_THROW(st::parseDxList("0.01,0.01"), std::invalid_argument);
  EXPECT_EQ(st::splitTopLevel("[a,b],c"), (std::vector<std::string>{"[a,b]", "c"}));
  const auto v = st::varyCombinations({"method.cfl=0.25,0.5", "effects=[pressure,walls],[pressure,walls,xsph]"});
  ASSERT_EQ(v.size(), 4u);
  EXPECT_EQ(v[1], (std::vector<std::string>{"method.cfl=0.25", "effects=[pressure,walls,xsph]"}));
  EXPECT_EQ(st::varyCombinations({}).size(), 1u);
  EXPECT_THROW(st::varyCombinations({"method.cfl"}), std::invalid_argument);
}

TEST(StudyAnalysis, ErrorsOrdersAndAdviceFromSyntheticRuns) {
  // value = 0.3 - 2 dx^1.5 (exact 0.3), wall ~ dx^-3.
  std::vector<st::StudyRow> rows;
  for (double dx : {0.04, 0.02, 0.01, 0.005}) {
    st::StudyRow r;
    r.dx = dx;
    r.value = 0.3 - 2.0 * std::pow(dx, 1.5);
    r.wall_seconds = 1e-6 * std::pow(dx, -3.0);
    r.fluid_particles = static_cast<std::size_t>(1.0 / (dx * dx));
    r.steps = static_cast<std::size_t>(1.0 / dx);
    rows.push_back(r);
  }
  auto richardson_rows = rows;
  const auto s = st::analyseStudy(richardson_rows, std::nullopt, false, NAN);
  ASSERT_EQ(s.size(), 1u);
  EXPECT_NEAR(s[0].reference, 0.3, 1e-9);
  EXPECT_NEAR(*s[0].richardson_order, 1.5, 1e-9);
  for (std::size_t k = 1; k < rows.size(); ++k) EXPECT_NEAR(richardson_rows[k].order, 1.5, 1e-6);
  EXPECT_NEAR(richardson_rows[0].relative_error, 2.0 * std::pow(0.04, 1.5) / 0.3, 1e-9);

  st::analyseStudy(rows, 0.3, false, NAN);
  // Relative errors: 5.3%, 1.9%, 0.67%, 0.24%.
  const auto advice = st::adviceLines(rows, "front_position", 0.2);
  ASSERT_EQ(advice.size(), 4u);
  EXPECT_EQ(advice[0].rfind("for front_position within 10% use dx <= 0.04 m; it costs 0.0156 s wall", 0), 0u) << advice[0];
  EXPECT_NE(advice[1].find("within 5% use dx <= 0.02 m"), std::string::npos) << advice[1];
  EXPECT_NE(advice[3].find("within 1% use dx <= 0.01 m"), std::string::npos) << advice[3];
  // 0.1% is beyond the finest run: extrapolated with order 1.5 and cost exponent 3.
  rows.pop_back();
  rows.pop_back();
  const auto far = st::adviceLines(rows, "x", 1.0);
  const double dx_needed = 0.02 * std::pow(0.01 / (2.0 * std::pow(0.02, 1.5) / 0.3), 1.0 / 1.5);
  char expected[64];
  std::snprintf(expected, sizeof expected, "within 1%% use dx <= %.3g m", dx_needed);
  EXPECT_NE(far[3].find(expected), std::string::npos) << far[3];
  EXPECT_NE(far[3].find("extrapolated"), std::string::npos) << far[3];
}

TEST(StudyAnalysis, WithoutAnExtrapolateTheFinestRunIsTheReference) {
  // The three finest values oscillate (0.26, 0.283, 0.282): no Richardson extrapolate.
  std::vector<st::StudyRow> rows;
  const double dx[] = {0.02, 0.01, 0.005, 0.0025}, value[] = {0.24, 0.26, 0.283, 0.282};
  for (int k = 0; k < 4; ++k) {
    st::StudyRow r;
    r.dx = dx[k];
    r.value = value[k];
    r.wall_seconds = 0.1 * std::pow(8.0, k);
    rows.push_back(r);
  }
  const auto s = st::analyseStudy(rows, std::nullopt, false, NAN);
  ASSERT_EQ(s.size(), 1u);
  EXPECT_TRUE(s[0].finest_is_reference);
  EXPECT_DOUBLE_EQ(s[0].reference, 0.282);
  EXPECT_NE(s[0].reference_source.find("differ by 0.35%"), std::string::npos) << s[0].reference_source;
  EXPECT_TRUE(std::isnan(rows[3].error));
  EXPECT_NEAR(rows[2].relative_error, 0.001 / 0.282, 1e-12);
  EXPECT_NEAR(rows[1].order, std::log((0.282 - 0.24) / (0.282 - 0.26)) / std::log(2.0), 1e-12);
  const auto advice = st::adviceLines(rows, "f", 1.0);
  ASSERT_EQ(advice.size(), 4u);
  EXPECT_NE(advice[3].find("within 1% use dx <= 0.005 m; it costs 6.4 s wall"), std::string::npos) << advice[3];
}
