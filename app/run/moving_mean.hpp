#pragma once
// Trailing moving mean of a sampled signal: the mean of the samples whose times lie in
// (t - window, t]. The pressure sensors of METHOD.md 6.5 are reported raw and smoothed
// with a 0.3 s moving mean; here the samples are the recorded outputs, so the window
// should span several output intervals. Not checkpointed: after a restart the mean
// starts again from the first sample.
#include <deque>
#include <utility>

namespace moorsph::app {

class MovingMean {
 public:
  explicit MovingMean(double window) : window_(window) {}
  /// Add the sample (t, value) and return the mean over the window ending at t.
  double add(double t, double value) {
    samples_.emplace_back(t, value);
    sum_ += value;
    while (!samples_.empty() && samples_.front().first <= t - window_) {
      sum_ -= samples_.front().second;
      samples_.pop_front();
    }
    return sum_ / static_cast<double>(samples_.size());
  }

 private:
  double window_;
  std::deque<std::pair<double, double>> samples_;
  double sum_ = 0.0;
};

}  // namespace moorsph::app
