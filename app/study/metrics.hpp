#pragma once
// Scalar measures of one run's time series, for `moorsph study` (docs/accuracy-cost.md).
// Each is a small function of a sampled series (time [s], value in the series' SI unit)
// and an optional time window [from, to]; each is tested on synthetic series with a
// known answer (tests/io/test_study_metrics.cpp).
//
// Waves and oscillations are split by zero up-crossings of the series about its mean
// over the window (the zero-crossing analysis of wave records, e.g. Goda 2000,
// "Random Seas and Design of Maritime Structures", ch. 2): a "wave" runs from one
// up-crossing to the next; its crest is its maximum, its trough its minimum.
#include <limits>
#include <string>
#include <vector>

namespace moorsph::app::study {

struct Series {
  std::vector<double> time;   ///< [s], increasing
  std::vector<double> value;  ///< same length
};

struct Window {
  double from = -std::numeric_limits<double>::infinity();  ///< [s]
  double to = std::numeric_limits<double>::infinity();     ///< [s]
};

/// Linear interpolation at t; throws std::invalid_argument outside the series' time span.
double valueAt(const Series& s, double t);
/// Time average over the window (trapezoidal rule on the samples inside it).
double meanValue(const Series& s, const Window& w);
/// Time average over the whole zero-up-crossing cycles in the window: from the first
/// up-crossing of the window mean to the last (crossing times interpolated linearly).
/// The equilibrium of an oscillating quantity (a heaving body's draught, a moored
/// body's mean offset) without the bias a window of a fractional number of periods
/// leaves (up to amplitude / (pi x cycles)). Throws without a complete cycle.
double cycleMean(const Series& s, const Window& w);
/// The level a relaxing quantity settles to: v(t) ~ v_inf + A exp(-(t - from) / tau)
/// fitted to the samples in the window by least squares (time-weighted; tau by a
/// search in log tau, v_inf and A linear for each tau), returning v_inf. For a
/// quantity whose mean still creeps towards equilibrium after the start has rung out
/// (a held body's buoyancy while the water next to it re-packs, a gauge's set-down),
/// where any window mean depends on where the window sits. A superposed oscillation
/// averages out when the window holds several periods. A series that does not relax
/// (the exponential does not fit it better than a constant by 1%) gives the window
/// mean. Throws when more than half the fitted relaxation lies beyond the window
/// (tau > span / ln 2): the plateau would be an extrapolation.
double relaxedLevel(const Series& s, const Window& w);
/// Largest |v - v(start of window)|: the excursion from the state at the window start
/// (e.g. a released body's largest heave displacement, a gauge's largest rise).
double peakAmplitude(const Series& s, const Window& w);
/// Largest value in the window (e.g. an impact pressure peak).
double maxValue(const Series& s, const Window& w);
/// Time of the largest value in the window (the first sample holding it): an arrival
/// or impact time.
double timeOfMax(const Series& s, const Window& w);
/// Value of the first local maximum in the window: the first sample that is the
/// largest of all samples within +-width [s] of it (and at least width before the
/// window end, so it is confirmed). Throws when there is none.
double firstPeak(const Series& s, const Window& w, double width);
/// Mean crest-to-trough height of the complete zero-up-crossing waves in the window.
double waveHeight(const Series& s, const Window& w);
/// Mean time between the crests of consecutive complete zero-up-crossing waves.
double periodBetweenPeaks(const Series& s, const Window& w);
/// Root-mean-square of run(t) - reference(t) over the reference's samples inside the
/// window and inside the run's time span (the run linearly interpolated).
double rmsDifference(const Series& run, const Series& reference, const Window& w);

/// The metrics `moorsph study --metric NAME` knows.
struct MetricInfo {
  std::string name;
  std::string summary;
  bool needs_time = false;             ///< needs --time
  bool is_error = false;               ///< the value is itself an error against a reference series
  std::string default_series;          ///< series used when --series is not given ("" = must be given)
};
const std::vector<MetricInfo>& metrics();
/// nullptr when unknown.
const MetricInfo* findMetric(const std::string& name);

struct MetricParams {
  double time = std::numeric_limits<double>::quiet_NaN();   ///< [s] for value-at metrics
  Window window;
  double width = std::numeric_limits<double>::quiet_NaN();  ///< [s] for first_peak; NaN: 5% of the span
};

/// The named metric of a series. `reference` is needed by error metrics (gauge_rms).
/// Throws std::invalid_argument with the reason when the series does not allow it.
double evaluateMetric(const std::string& name, const Series& s, const MetricParams& p, const Series* reference = nullptr);

}  // namespace moorsph::app::study
