#pragma once
// Tait equation of state (METHOD.md section 1):
//   P = P0 [ (rho/rho0)^gamma - 1 ],   gamma P0 / rho0 = c_s^2
// and its stored elastic energy per unit mass (for the energy ledger):
//   e(rho) = int_rho0^rho P/rho'^2 drho'
//          = P0 [ (rho^(gamma-1)/rho0^gamma - 1/rho0)/(gamma-1) + 1/rho - 1/rho0 ]   [J/kg]
#include <cmath>

namespace moorsph::fluid {

class TaitEos {
 public:
  TaitEos(double rho0, double sound_speed, double gamma = 7.0)
      : rho0_(rho0), c_(sound_speed), gamma_(gamma), p0_(rho0 * sound_speed * sound_speed / gamma) {}

  double rho0() const { return rho0_; }
  double soundSpeed() const { return c_; }
  double gamma() const { return gamma_; }
  double p0() const { return p0_; }

  /// Pressure [Pa] from density [kg/m^3].
  double pressure(double rho) const {
    const double ratio = rho / rho0_;
    if (gamma_ == 7.0) {  // the common case: three multiplications instead of pow()
      const double r2 = ratio * ratio;
      return p0_ * (r2 * r2 * r2 * ratio - 1.0);
    }
    return p0_ * (std::pow(ratio, gamma_) - 1.0);
  }

  /// Density [kg/m^3] giving pressure p [Pa] (inverse of pressure()).
  double density(double p) const { return rho0_ * std::pow(1.0 + p / p0_, 1.0 / gamma_); }

  /// Stored elastic energy per unit mass [J/kg], zero at rho0.
  double elasticEnergy(double rho) const {
    const double g1 = gamma_ - 1.0;
    return p0_ * ((std::pow(rho, g1) / std::pow(rho0_, gamma_) - 1.0 / rho0_) / g1 + 1.0 / rho - 1.0 / rho0_);
  }

 private:
  double rho0_;
  double c_;
  double gamma_;
  double p0_;
};

}  // namespace moorsph::fluid
