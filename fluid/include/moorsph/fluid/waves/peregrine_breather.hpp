#pragma once
// Peregrine breathers of orders 1 and 2 of the deep-water nonlinear Schroedinger equation
// (METHOD.md section 4c; order 1: Peregrine 1983, J. Austral. Math. Soc. B 25, 16-43;
// order 2: Akhmediev, Ankiewicz & Soto-Crespo 2009, Phys. Rev. E 80, 026601).
//
// Carrier: amplitude a0 [m], wave number k0 [rad/m], omega0 = sqrt(g k0) [rad/s].
// Scaled variables (dimensionless):
//   psi0 = sqrt(2) k0 a0,   T = -(omega0 / 8) |psi0|^2 t,   X = (k0 x - (omega0 / 2) t) |psi0|
// Envelope [m] and elevation [m]:
//   psi_j(X,T) = a0 [(-1)^j + (G_j + i H_j) / D_j] exp(2 i T)
//   eta(x,t)   = Re{ psi_j(X,T) exp(i (k0 x - omega0 t)) }
//   Order 1: G1 = 4, H1 = 16 T, D1 = 1 + 4X^2 + 16T^2                    (peak |psi|/a0 = 3)
//   Order 2: G2 = 3/4 - (X^2 + 4T^2 + 3/4)(X^2 + 20T^2 + 3/4)
//            H2 = 2T (3X^2 - 4T^2 - 2(X^2 + 4T^2)^2 + 15/8)
//            D2 = (X^2 + 4T^2)^3/3 + (X^2 - 12T^2)^2/4 + 3(12X^2 + 176T^2 + 1)/64  (peak 5)
// The +15/8 in H2 and the 12X^2 in D2 correct two misprints of the form published in the
// reference work; with them psi_j / a0 solves i psi_T + psi_XX + 2|psi|^2 psi = 0 exactly
// (tested by finite differences). Far from the focus |psi_j| -> a0 (the background sea).
// The focus is at x = 0, t = 0; shift x and t to place it elsewhere.
#include <complex>

#include <moorsph/fluid/waves/dispersion.hpp>

namespace moorsph::fluid::waves {

/// psi_j(X,T) / a0 for order j = 1 or 2 (dimensionless); throws std::invalid_argument
/// for another order.
std::complex<double> peregrineNormalizedEnvelope(int order, double X, double T);

class PeregrineBreather {
 public:
  /// order 1 or 2, carrier amplitude a0 [m], carrier wave number k0 [rad/m].
  PeregrineBreather(int order, double carrierAmplitude, double carrierWaveNumber,
                    double gravity = kGravity);

  int order() const { return order_; }
  double carrierAmplitude() const { return a0_; }
  double carrierWaveNumber() const { return k0_; }
  /// omega0 = sqrt(g k0) [rad/s].
  double carrierAngularFrequency() const { return omega0_; }
  /// Carrier steepness a0 k0 [-] (METHOD: breaking above about 0.12 for order 1, 0.06 for 2).
  double steepness() const { return a0_ * k0_; }
  /// psi0 = sqrt(2) k0 a0 [-].
  double psi0() const { return psi0_; }
  /// Peak amplification |psi_j(0,0)| / a0: 3 for order 1, 5 for order 2 [-].
  double peakAmplification() const { return 2.0 * order_ + 1.0; }

  /// Scaled space X(x,t) [-] and time T(t) [-].
  double scaledX(double x, double t) const;
  double scaledT(double t) const;

  /// Complex envelope psi_j(X,T) [m] at the scaled variables.
  std::complex<double> envelope(double X, double T) const;
  /// Free-surface elevation eta(x,t) [m], focus at x = 0, t = 0.
  double elevation(double x, double t) const;
  /// Local envelope amplitude |psi_j| [m] at (x,t).
  double envelopeAmplitude(double x, double t) const;

 private:
  int order_;
  double a0_;
  double k0_;
  double omega0_;
  double psi0_;
};

}  // namespace moorsph::fluid::waves
