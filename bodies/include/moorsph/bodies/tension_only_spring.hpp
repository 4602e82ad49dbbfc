#pragma once
// The reference cable of METHOD.md section 5: a massless, tension-only linear spring.
//
//   L = |x_f - x_a|,  e = (x_f - x_a)/L,  Ldot = e . (v_f - v_a)
//   T = max(0, k (L - L0) + c Ldot)   if L > L0,   T = 0 otherwise
//   F_fairlead = -T e,  F_anchor = +T e,  E = k (L - L0)^2 / 2 for L > L0
//
// k in N/m, L0 in m, c in N s/m. Damping acts only while taut, and the total
// tension is clamped at zero so the damper can never push. The rest length is given
// directly or derived from a pretension T0 at the initial pose: L0 = L_init - T0/k.

#include <moorsph/bodies/mooring_line.hpp>

#include <limits>

namespace moorsph::bodies {

struct TensionOnlySpringParams {
  double stiffness = 0.0;  ///< k, N/m (> 0)
  /// L0, m. Give exactly one of restLength and pretension.
  double restLength = std::numeric_limits<double>::quiet_NaN();
  /// T0 at the initial pose, N (>= 0).
  double pretension = std::numeric_limits<double>::quiet_NaN();
  double damping = 0.0;  ///< c, N s/m (>= 0), active only while taut
};

class TensionOnlySpring final : public MooringLine {
 public:
  explicit TensionOnlySpring(const TensionOnlySpringParams& params);

  std::string modelName() const override { return "tension_only_spring"; }
  void initialize(const LineEnds& ends) override;
  LineForces calcForces(const LineEnds& ends) const override;
  double calcPotentialEnergy(const LineEnds& ends) const override;
  std::vector<Eigen::Vector3d> calcShape(const LineEnds& ends) const override;
  bool dissipates() const override { return params_.damping > 0.0; }

  /// Rest length in use (resolved from the pretension after initialize()).
  double restLength() const { return params_.restLength; }
  double stiffness() const { return params_.stiffness; }

 private:
  TensionOnlySpringParams params_;
};

}  // namespace moorsph::bodies
