#include <moorsph/fluid/wave_height_controller.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace moorsph::fluid {

WaveHeightController::WaveHeightController(WaveHeightControllerSpec spec)
    : spec_(spec), old_gain_(spec.initial_gain), new_gain_(spec.initial_gain), period_start_(spec.start_time) {
  if (!(spec_.target_height > 0.0)) throw std::invalid_argument("wave height controller: target height must be positive");
  if (!(spec_.period > 0.0)) throw std::invalid_argument("wave height controller: period must be positive");
  if (!(spec_.delay >= 0.0)) throw std::invalid_argument("wave height controller: delay must not be negative");
  if (spec_.update_periods < 1) throw std::invalid_argument("wave height controller: window of at least one period");
  if (!(spec_.beta > 0.0 && spec_.beta <= 1.0)) throw std::invalid_argument("wave height controller: beta in (0, 1]");
  if (!(spec_.initial_gain > 0.0 && spec_.min_gain > 0.0 && spec_.max_gain >= spec_.min_gain))
    throw std::invalid_argument("wave height controller: gains must be positive and min <= max");
}

double WaveHeightController::gainAt(double t) const {
  const double s = (t - change_time_) / spec_.period;
  if (s >= 1.0) return new_gain_;
  if (s <= 0.0) return old_gain_;
  return old_gain_ + s * (new_gain_ - old_gain_);
}

double WaveHeightController::gainRate(double t) const {
  const double s = (t - change_time_) / spec_.period;
  return (s > 0.0 && s < 1.0) ? (new_gain_ - old_gain_) / spec_.period : 0.0;
}

void WaveHeightController::closePeriod() {
  double sum = 0.0;
  for (std::size_t g = 0; g < lo_.size(); ++g) sum += hi_[g] - lo_[g];
  height_sum_ += sum / static_cast<double>(lo_.size());
  ++periods_in_window_;
  std::fill(lo_.begin(), lo_.end(), std::numeric_limits<double>::infinity());
  std::fill(hi_.begin(), hi_.end(), -std::numeric_limits<double>::infinity());
}

bool WaveHeightController::addSample(double t, const std::vector<double>& eta) {
  if (t < spec_.start_time || t < period_start_ || eta.empty()) return false;
  if (lo_.empty()) {
    lo_.assign(eta.size(), std::numeric_limits<double>::infinity());
    hi_.assign(eta.size(), -std::numeric_limits<double>::infinity());
  }
  if (eta.size() != lo_.size()) throw std::invalid_argument("wave height controller: gauge count changed");
  bool updated = false;
  if (t >= period_start_ + spec_.period) {
    closePeriod();
    period_start_ += spec_.period;
    if (periods_in_window_ == spec_.update_periods) {
      last_height_ = height_sum_ / periods_in_window_;
      height_sum_ = 0.0;
      periods_in_window_ = 0;
      if (t < spec_.stop_time && last_height_ > 0.0) {
        old_gain_ = gainAt(t);
        const double g = old_gain_ * std::pow(spec_.target_height / last_height_, spec_.beta);
        new_gain_ = std::clamp(g, spec_.min_gain, spec_.max_gain);
        change_time_ = t;
        ++updates_;
        updated = true;
        // The next window opens once the new gain is in place and its wave has arrived.
        period_start_ = t + spec_.period + spec_.delay;
        std::fill(lo_.begin(), lo_.end(), std::numeric_limits<double>::infinity());
        std::fill(hi_.begin(), hi_.end(), -std::numeric_limits<double>::infinity());
        return updated;
      }
    }
  }
  for (std::size_t g = 0; g < eta.size(); ++g) {
    lo_[g] = std::min(lo_[g], eta[g]);
    hi_[g] = std::max(hi_[g], eta[g]);
  }
  return updated;
}

}  // namespace moorsph::fluid
