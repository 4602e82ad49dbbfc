#pragma once
// The "forcing_region" effect (METHOD.md section 4a): inside a region of length L_w,
// from a little above the floor up to the still surface, each fluid particle is
// pushed toward the target velocity v_c of a wave field:
//   F_i / m_i = 10^kappa mu (v_c - v_i) / rho_i          (kappa = 7 in the reference)
// i.e. a relaxation at rate 10^kappa mu / rho_i [1/s] (10 1/s for water). The target is
// an Airy or Stokes 2nd-order field (fluid/waves), with y measured up from the floor.
#include <functional>
#include <limits>
#include <moorsph/fluid/counted.hpp>
#include <moorsph/fluid/fluid_effect.hpp>

namespace moorsph::fluid {

struct ForcingRegionSpec {
  double x_start = 0.0;      ///< [m]
  double length = 1.0;       ///< L_w [m]
  double floor = 0.0;        ///< y of the tank floor [m]
  double bottom_gap = 0.0;   ///< region starts this far above the floor [m]
  double still_level = 1.0;  ///< y of the still surface [m]
  double kappa = 7.0;
  double mu = 1.0e-3;        ///< dynamic viscosity in the forcing law [Pa s]
  /// The target is multiplied by the half-cosine ramp (1 - cos(pi t / ramp_up)) / 2 for
  /// t < ramp_up [s], so the water is not jerked from rest (0: no ramp, METHOD.md).
  double ramp_up = 0.0;
  /// The forcing stops at this time [s] (infinity: never); a free-decay run switches
  /// the maker off once the wave is made.
  double end_time = std::numeric_limits<double>::infinity();
  /// Multiplies the target velocity (the amplitude calibration of issue 6 item 5,
  /// see wave_height_controller.hpp); 1 is the reference.
  double gain = 1.0;
};

template <int D>
class ForcingRegion final : public FluidEffect<D>, public Counted<ForcingRegion<D>> {
 public:
  /// (x, height above the floor, t) -> target (v_x, v_y) [m/s].
  using TargetField = std::function<Eigen::Vector2d(double, double, double)>;
  /// Throws std::invalid_argument for an empty region or a relaxation too fast for max_dt.
  ForcingRegion(ForcingRegionSpec spec, TargetField target, double max_dt);
  const char* name() const override { return "forcing_region"; }
  void addRates(FluidContext<D>& ctx) override;
  bool contains(const Vec<D>& r) const;
  /// Factor on the target at time t: gain x ramp (0 after end_time).
  double targetScale(double t) const;
  /// Change the gain during a run (active correction from a gauge).
  void setGain(double gain) { spec_.gain = gain; }
  double gain() const { return spec_.gain; }

 private:
  ForcingRegionSpec spec_;
  TargetField target_;
  double strength_;  // 10^kappa mu [Pa s]
};

/// METHOD.md section 4a: the particle spacing that fits a periodic length L exactly,
/// p = floor(L / (10 h_f dx_target)), dx = L / (10 p h_f). Throws if L < 10 h_f dx_target.
double periodicSpacing(double length, double dx_target, double h_factor);

}  // namespace moorsph::fluid
