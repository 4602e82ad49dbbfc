#pragma once
// Active amplitude correction of a wave maker (issue 6 item 5: the reference's
// generated waves came out smaller than requested). A controller watches the
// trough-to-crest height H at one or more gauges and scales the maker (the forcing
// region's target velocity, or the piston's stroke) by a gain G until H matches the
// requested height:
//
//   every `update_periods` periods after start_time, with H_m the mean height over
//   that window (max - min per period and gauge, averaged),
//     G_new = clamp(G_old (H_target / H_m)^beta, min_gain, max_gain),
//
// a multiplicative integral controller: at a fixed point H_m = H_target. The new gain
// is reached linearly over the next period (gainAt, gainRate), so a piston's
// displacement G(t) X0(t) stays continuous, and the next window only opens `delay`
// seconds after that (the time the changed wave needs to reach the gauges, e.g.
// their distance from the maker over the group speed): each window then sees one
// gain, and for a linear maker H = k G the error shrinks by (1 - beta) per update.
//
// Units: t [s], heights [m], the gain [-].
#include <vector>

namespace moorsph::fluid {

struct WaveHeightControllerSpec {
  double target_height = 0.0;  ///< requested trough-to-crest height H [m]
  double period = 1.0;         ///< wave period T [s]
  double start_time = 0.0;     ///< first window starts here (after the maker's ramp-up) [s]
  int update_periods = 2;      ///< window length in periods
  double beta = 0.5;           ///< exponent of the correction, in (0, 1]
  double initial_gain = 1.0;   ///< e.g. a gain calibrated beforehand
  double min_gain = 0.5, max_gain = 2.5;
  double stop_time = 1e300;    ///< no updates after this time [s] (then G is held)
  double delay = 0.0;          ///< wait after each gain change before the next window [s]
};

class WaveHeightController {
 public:
  /// Throws std::invalid_argument for a non-positive height, period or window, or beta outside (0, 1].
  explicit WaveHeightController(WaveHeightControllerSpec spec);

  /// Feed the surface elevations [m] of the watched gauges at time t [s] (increasing
  /// t, same gauge count each call). Returns true when a window closed and the gain
  /// was updated.
  bool addSample(double t, const std::vector<double>& eta);

  /// G(t): the gain to apply at time t (linear over one period after each update).
  double gainAt(double t) const;
  /// dG/dt at time t [1/s].
  double gainRate(double t) const;
  /// The mean height of the last closed window [m] (0 before the first).
  double lastHeight() const { return last_height_; }
  int updates() const { return updates_; }

 private:
  void closePeriod();

  WaveHeightControllerSpec spec_;
  double old_gain_, new_gain_, change_time_ = -1e300;
  double period_start_;
  std::vector<double> lo_, hi_;   // per gauge, current period
  double height_sum_ = 0.0;       // sum of period heights in the window
  int periods_in_window_ = 0;
  double last_height_ = 0.0;
  int updates_ = 0;
};

}  // namespace moorsph::fluid
