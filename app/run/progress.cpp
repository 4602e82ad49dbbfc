#include "progress.hpp"

#include <algorithm>

#include <unistd.h>

#include <cstdio>

namespace moorsph::app {
namespace {

std::string duration(double seconds) {
  char text[32];
  if (seconds < 120.0) std::snprintf(text, sizeof text, "%.0f s", seconds);
  else if (seconds < 7200.0) std::snprintf(text, sizeof text, "%.1f min", seconds / 60.0);
  else std::snprintf(text, sizeof text, "%.1f h", seconds / 3600.0);
  return text;
}

}  // namespace

Progress::Progress(RunLog& log, double start_time, double end_time, double log_interval)
    : log_(log), start_time_(start_time), end_time_(end_time), log_interval_(log_interval),
      tty_(isatty(fileno(stdout)) != 0), wall_start_(std::chrono::steady_clock::now()), last_print_(wall_start_),
      last_logged_(wall_start_) {}

std::string Progress::describe(double time, std::size_t steps, double dt) const {
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start_).count();
  const double simulated = time - start_time_;
  const double rate = wall > 0.0 ? static_cast<double>(steps - start_steps_) / wall : 0.0;
  const double factor = wall > 0.0 ? simulated / wall : 0.0;  // simulated seconds per wall second
  const double eta = simulated > 0.0 ? (end_time_ - time) * wall / simulated : 0.0;
  char text[200];
  std::snprintf(text, sizeof text, "t = %.4f / %.4g s (%3.0f%%)  %.0f steps/s  dt = %.2e s  real-time factor %.3g  ETA %s",
                time, end_time_, 100.0 * time / end_time_, rate, dt, factor, duration(eta).c_str());
  return text;
}

void Progress::update(double time, std::size_t steps, double dt) {
  if (!started_) {
    started_ = true;
    start_steps_ = steps > 0 ? steps - 1 : 0;
  }
  const auto now = std::chrono::steady_clock::now();
  const double since = std::chrono::duration<double>(now - last_print_).count();
  if (since < (tty_ ? 0.5 : log_interval_)) return;
  last_print_ = now;
  if (tty_) {
    std::printf("\r\033[K%s", describe(time, steps, dt).c_str());
    std::fflush(stdout);
    line_shown_ = true;
    // log.txt gets a line every log_interval also when the terminal shows the live line.
    if (std::chrono::duration<double>(now - last_logged_).count() >= log_interval_) {
      last_logged_ = now;
      log_.fileOnly(describe(time, steps, dt));
    }
  } else {
    log_.line(describe(time, steps, dt));
  }
}

namespace {

/// Seconds to three figures without an exponent: "1198", "50.0", "0.344".
std::string seconds3(double s) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, s >= 100.0 ? "%.0f" : s >= 10.0 ? "%.1f" : s >= 1.0 ? "%.2f" : "%.3f", s);
  return buffer;
}

}  // namespace

std::string describePhases(const std::vector<std::string>& names, const std::vector<double>& seconds, double wall) {
  std::vector<std::size_t> order(names.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return seconds[a] > seconds[b]; });
  const auto share = [&](double s) { return wall > 0.0 ? 100.0 * s / wall : 0.0; };
  const auto item = [&](const std::string& name, double s) {
    char percent[16];
    std::snprintf(percent, sizeof percent, " (%.0f%%)", share(s));
    return name + " " + seconds3(s) + " s" + percent;
  };
  std::string text = "time by phase (" + seconds3(wall) + " s wall):";
  double listed = 0.0;
  const char* separator = " ";
  for (const std::size_t k : order) {
    if (share(seconds[k]) < 1.0) break;
    text += separator + item(names[k], seconds[k]);
    listed += seconds[k];
    separator = ", ";
  }
  return text + separator + item("other", std::max(0.0, wall - listed));
}

void Progress::clear() {
  if (tty_ && line_shown_) {
    std::printf("\r\033[K");
    std::fflush(stdout);
    line_shown_ = false;
  }
}

}  // namespace moorsph::app
