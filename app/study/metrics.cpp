#include "study/metrics.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace moorsph::app::study {
namespace {

std::string num(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", x);
  return text;
}

void requireSamples(const Series& s) {
  if (s.time.size() != s.value.size()) throw std::invalid_argument("time and value columns differ in length");
  if (s.time.empty()) throw std::invalid_argument("the series is empty");
}

/// The samples inside the window, in order.
Series clip(const Series& s, const Window& w) {
  requireSamples(s);
  Series c;
  for (std::size_t k = 0; k < s.time.size(); ++k)
    if (s.time[k] >= w.from && s.time[k] <= w.to) {
      c.time.push_back(s.time[k]);
      c.value.push_back(s.value[k]);
    }
  if (c.time.size() < 2)
    throw std::invalid_argument("fewer than 2 samples in the window [" + num(w.from) + ", " + num(w.to) + "] s");
  return c;
}

double average(const Series& c) {
  double area = 0.0;
  for (std::size_t k = 1; k < c.time.size(); ++k)
    area += 0.5 * (c.value[k] + c.value[k - 1]) * (c.time[k] - c.time[k - 1]);
  const double span = c.time.back() - c.time.front();
  return span > 0.0 ? area / span : c.value.front();
}

struct Wave {
  double crest, trough, crest_time;
};

/// Complete waves between consecutive up-crossings of the window mean. The crossing
/// index k is the first sample at or above the mean after one below it.
std::vector<Wave> upCrossingWaves(const Series& s, const Window& w) {
  const Series c = clip(s, w);
  const double mean = average(c);
  std::vector<std::size_t> ups;
  for (std::size_t k = 1; k < c.value.size(); ++k)
    if (c.value[k - 1] < mean && c.value[k] >= mean) ups.push_back(k);
  std::vector<Wave> waves;
  for (std::size_t n = 1; n < ups.size(); ++n) {
    Wave wave{c.value[ups[n - 1]], c.value[ups[n - 1]], c.time[ups[n - 1]]};
    for (std::size_t k = ups[n - 1]; k < ups[n]; ++k) {
      if (c.value[k] > wave.crest) {
        wave.crest = c.value[k];
        wave.crest_time = c.time[k];
      }
      wave.trough = std::min(wave.trough, c.value[k]);
    }
    waves.push_back(wave);
  }
  return waves;
}

/// Trapezoidal time weights of the samples: sum_k w_k v_k is the trapezoidal integral, so
/// the weighted mean is average() and uneven sampling does not bias a fit.
std::vector<double> trapezoidWeights(const Series& c) {
  const std::size_t n = c.time.size();
  std::vector<double> weight(n, 0.0);
  for (std::size_t k = 0; k + 1 < n; ++k) {
    weight[k] += 0.5 * (c.time[k + 1] - c.time[k]);
    weight[k + 1] += 0.5 * (c.time[k + 1] - c.time[k]);
  }
  return weight;
}

/// Least-squares fit of v ~ level + amplitude exp(-(t - t0) / tau) for one tau.
struct RelaxationFit {
  double level = 0.0, amplitude = 0.0, tau = 0.0, squared_error = 0.0;
};

RelaxationFit fitRelaxation(const Series& c, const std::vector<double>& weight, double tau) {
  const std::size_t n = c.time.size();
  double sw = 0, se = 0, see = 0, sv = 0, sev = 0;
  std::vector<double> e(n);
  for (std::size_t k = 0; k < n; ++k) {
    e[k] = std::exp(-(c.time[k] - c.time.front()) / tau);
    sw += weight[k];
    se += weight[k] * e[k];
    see += weight[k] * e[k] * e[k];
    sv += weight[k] * c.value[k];
    sev += weight[k] * e[k] * c.value[k];
  }
  RelaxationFit fit;
  fit.tau = tau;
  const double det = sw * see - se * se;
  fit.amplitude = det > 0.0 ? (sw * sev - se * sv) / det : 0.0;
  fit.level = (sv - fit.amplitude * se) / sw;
  for (std::size_t k = 0; k < n; ++k) {
    const double r = c.value[k] - fit.level - fit.amplitude * e[k];
    fit.squared_error += weight[k] * r * r;
  }
  return fit;
}

}  // namespace

double relaxedLevel(const Series& s, const Window& w) {
  const Series c = clip(s, w);
  const double span = c.time.back() - c.time.front();
  if (!(span > 0.0)) throw std::invalid_argument("the window holds no time span");
  const std::vector<double> weight = trapezoidWeights(c);
  const auto squaredError = [&](double log_tau) { return fitRelaxation(c, weight, std::exp(log_tau)).squared_error; };
  // Coarse search over tau from span/200 to 20 span, then golden section around the best.
  const int steps = 120;
  const double lo = std::log(span / 200.0), hi = std::log(20.0 * span);
  int best = 0;
  double best_error = std::numeric_limits<double>::infinity();
  for (int k = 0; k <= steps; ++k) {
    const double err = squaredError(lo + (hi - lo) * k / steps);
    if (err < best_error) {
      best_error = err;
      best = k;
    }
  }
  double a = lo + (hi - lo) * std::max(best - 1, 0) / steps, b = lo + (hi - lo) * std::min(best + 1, steps) / steps;
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  for (int it = 0; it < 60; ++it) {
    const double x1 = b - g * (b - a), x2 = a + g * (b - a);
    if (squaredError(x1) < squaredError(x2))
      b = x2;
    else
      a = x1;
  }
  const RelaxationFit fit = fitRelaxation(c, weight, std::exp(0.5 * (a + b)));
  // A constant fits (nearly) as well: the series is steady in the window.
  const double mean = average(c);
  double steady_error = 0.0;
  for (std::size_t k = 0; k < c.time.size(); ++k) steady_error += weight[k] * (c.value[k] - mean) * (c.value[k] - mean);
  if (fit.squared_error >= 0.99 * steady_error) return mean;
  if (fit.tau > span / std::log(2.0))
    throw std::invalid_argument("the series has not gone half-way to its plateau in the window [" + num(w.from) + ", " +
                                num(w.to) + "] s (fitted time constant " + num(fit.tau) + " s > span / ln 2): run longer");
  return fit.level;
}

double valueAt(const Series& s, double t) {
  requireSamples(s);
  if (!(t >= s.time.front() && t <= s.time.back()))
    throw std::invalid_argument("time " + num(t) + " s is outside the series' span [" + num(s.time.front()) + ", " +
                                num(s.time.back()) + "] s");
  const auto hi = std::lower_bound(s.time.begin(), s.time.end(), t);
  const std::size_t k = static_cast<std::size_t>(hi - s.time.begin());
  if (k == 0 || s.time[k] == t) return s.value[k];
  const double f = (t - s.time[k - 1]) / (s.time[k] - s.time[k - 1]);
  return s.value[k - 1] + f * (s.value[k] - s.value[k - 1]);
}

double meanValue(const Series& s, const Window& w) { return average(clip(s, w)); }

double cycleMean(const Series& s, const Window& w) {
  const Series c = clip(s, w);
  const double mean = average(c);
  std::vector<double> ups;  // interpolated times where the series rises through the mean
  for (std::size_t k = 1; k < c.value.size(); ++k)
    if (c.value[k - 1] < mean && c.value[k] >= mean)
      ups.push_back(c.time[k - 1] + (mean - c.value[k - 1]) / (c.value[k] - c.value[k - 1]) * (c.time[k] - c.time[k - 1]));
  if (ups.size() < 2) throw std::invalid_argument("no complete zero-up-crossing cycle in the window");
  // Trapezoidal average over [ups.front(), ups.back()], the ends interpolated.
  Series whole;
  whole.time.push_back(ups.front());
  whole.value.push_back(valueAt(c, ups.front()));
  for (std::size_t k = 0; k < c.time.size(); ++k)
    if (c.time[k] > ups.front() && c.time[k] < ups.back()) {
      whole.time.push_back(c.time[k]);
      whole.value.push_back(c.value[k]);
    }
  whole.time.push_back(ups.back());
  whole.value.push_back(valueAt(c, ups.back()));
  return average(whole);
}

double peakAmplitude(const Series& s, const Window& w) {
  const Series c = clip(s, w);
  double peak = 0.0;
  for (double v : c.value) peak = std::max(peak, std::abs(v - c.value.front()));
  return peak;
}

namespace {
std::size_t indexOfMax(const Series& c) {
  return static_cast<std::size_t>(std::max_element(c.value.begin(), c.value.end()) - c.value.begin());
}
}  // namespace

double maxValue(const Series& s, const Window& w) {
  const Series c = clip(s, w);
  return c.value[indexOfMax(c)];
}

double timeOfMax(const Series& s, const Window& w) {
  const Series c = clip(s, w);
  return c.time[indexOfMax(c)];
}

double firstPeak(const Series& s, const Window& w, double width) {
  const Series c = clip(s, w);
  if (!(width > 0.0)) width = 0.05 * (c.time.back() - c.time.front());
  std::size_t lo = 0, hi = 0;  // samples within [t_k - width, t_k + width] are [lo, hi)
  for (std::size_t k = 0; k < c.time.size() && c.time[k] + width <= c.time.back(); ++k) {
    while (c.time[lo] < c.time[k] - width) ++lo;
    while (hi < c.time.size() && c.time[hi] <= c.time[k] + width) ++hi;
    // A peak, not the window's starting edge: something lower must come before it.
    const bool rises_into = k > 0 && c.value[k - 1] < c.value[k];
    if (rises_into && *std::max_element(c.value.begin() + static_cast<long>(lo), c.value.begin() + static_cast<long>(hi)) <=
                          c.value[k])
      return c.value[k];
  }
  throw std::invalid_argument("no local maximum (largest within +-" + num(width) + " s) in the window");
}

double waveHeight(const Series& s, const Window& w) {
  const auto waves = upCrossingWaves(s, w);
  if (waves.empty()) throw std::invalid_argument("no complete zero-up-crossing wave in the window");
  double sum = 0.0;
  for (const auto& wave : waves) sum += wave.crest - wave.trough;
  return sum / static_cast<double>(waves.size());
}

double periodBetweenPeaks(const Series& s, const Window& w) {
  const auto waves = upCrossingWaves(s, w);
  if (waves.size() < 2) throw std::invalid_argument("fewer than 2 complete zero-up-crossing waves in the window");
  return (waves.back().crest_time - waves.front().crest_time) / static_cast<double>(waves.size() - 1);
}

double rmsDifference(const Series& run, const Series& reference, const Window& w) {
  requireSamples(run);
  requireSamples(reference);
  double sum = 0.0;
  std::size_t n = 0;
  for (std::size_t k = 0; k < reference.time.size(); ++k) {
    const double t = reference.time[k];
    if (t < w.from || t > w.to || t < run.time.front() || t > run.time.back()) continue;
    const double d = valueAt(run, t) - reference.value[k];
    sum += d * d;
    ++n;
  }
  if (n == 0) throw std::invalid_argument("no reference sample inside both the window and the run's time span");
  return std::sqrt(sum / static_cast<double>(n));
}

const std::vector<MetricInfo>& metrics() {
  static const std::vector<MetricInfo> list = {
      {"front_position", "surge front x [m] at --time (dam break); from particles.h5 or a 'front' series", true, false, "front"},
      {"value_at", "series value at --time", true, false, ""},
      {"mean_value", "time average over [--from, --to] (e.g. equilibrium draught)", false, false, ""},
      {"cycle_mean", "time average over the whole zero-up-crossing cycles in the window (an oscillating equilibrium)", false,
       false, ""},
      {"relaxed_level", "plateau of v_inf + A exp(-t/tau) fitted over the window (a quantity still creeping to equilibrium)",
       false, false, ""},
      {"peak_amplitude", "largest |v - v(--from)| over the window", false, false, ""},
      {"max_value", "largest value in the window (e.g. an impact pressure peak)", false, false, ""},
      {"time_of_max", "time [s] of the largest value in the window (an arrival or impact time)", false, false, ""},
      {"first_peak", "value of the first local maximum in the window (largest within +- --width)", false, false, ""},
      {"wave_height", "mean crest-to-trough height of the zero-up-crossing waves in the window", false, false, ""},
      {"period_between_peaks", "mean time between crests of the zero-up-crossing waves in the window", false, false, ""},
      {"gauge_rms", "RMS difference from the --reference series (CSV time,value) over the window", false, true, ""},
  };
  return list;
}

const MetricInfo* findMetric(const std::string& name) {
  for (const auto& m : metrics())
    if (m.name == name) return &m;
  return nullptr;
}

double evaluateMetric(const std::string& name, const Series& s, const MetricParams& p, const Series* reference) {
  if (name == "front_position" || name == "value_at") {
    if (std::isnan(p.time)) throw std::invalid_argument(name + " needs --time");
    return valueAt(s, p.time);
  }
  if (name == "mean_value") return meanValue(s, p.window);
  if (name == "cycle_mean") return cycleMean(s, p.window);
  if (name == "relaxed_level") return relaxedLevel(s, p.window);
  if (name == "peak_amplitude") return peakAmplitude(s, p.window);
  if (name == "max_value") return maxValue(s, p.window);
  if (name == "time_of_max") return timeOfMax(s, p.window);
  if (name == "first_peak") return firstPeak(s, p.window, p.width);
  if (name == "wave_height") return waveHeight(s, p.window);
  if (name == "period_between_peaks") return periodBetweenPeaks(s, p.window);
  if (name == "gauge_rms") {
    if (!reference) throw std::invalid_argument("gauge_rms needs a reference series (--reference FILE)");
    return rmsDifference(s, *reference, p.window);
  }
  throw std::invalid_argument("unknown metric '" + name + "'");
}

}  // namespace moorsph::app::study
