#pragma once
// The "damping_zone" effect (METHOD.md section 4b): in x_start <= x <= x_end the
// horizontal velocity of fluid particles relaxes toward zero,
//   dv_x/dt += -k(x) v_x,   k(x) = k_max s^2,  s = (x - x_start)/(x_end - x_start),
// a quadratic ramp so incoming waves meet no sudden change and are absorbed rather
// than reflected. k_max [1/s] of a few wave frequencies absorbs over about a
// wavelength. The step stays stable while k_max dt < 1 (checked at construction
// against the CFL step).
#include <moorsph/fluid/counted.hpp>
#include <moorsph/fluid/fluid_effect.hpp>

namespace moorsph::fluid {

template <int D>
class DampingZone final : public FluidEffect<D>, public Counted<DampingZone<D>> {
 public:
  /// Throws std::invalid_argument for an empty zone, k_max <= 0 or k_max max_dt >= 1.
  DampingZone(double x_start, double x_end, double k_max, double max_dt);
  const char* name() const override { return "damping_zone"; }
  void addRates(FluidContext<D>& ctx) override;
  /// k(x) [1/s].
  double rate(double x) const;

 private:
  double x_start_, x_end_, k_max_;
};

}  // namespace moorsph::fluid
