#pragma once
// Wendland C2 smoothing kernel with compact support 2h (METHOD.md section 1).
//
//   W(r,h) = alpha_D (2 - q)^4 (1 + 2q),  q = r/h <= 2, else 0
//   alpha_2 = 7/(64 pi h^2),  alpha_3 = 21/(256 pi h^3)   [1/m^D]
//
// Its gradient has a closed form without a division by r:
//   dW/dr = -10 alpha_D q (2 - q)^3 / h,  so  grad_i W_ij = F(r) r_ij  with
//   F(r) = -10 alpha_D (2 - q)^3 / h^2   [1/m^(D+2)]
// which the pair loops use directly (r_ij = r_i - r_j).
#include <cmath>

namespace moorsph::fluid {

template <int D>
class WendlandKernel {
 public:
  static_assert(D == 2 || D == 3, "2D or 3D only");

  explicit WendlandKernel(double h)
      : h_(h), inv_h_(1.0 / h), alpha_(normalisation(h)), grad_scale_(-10.0 * alpha_ / (h * h)) {}

  double h() const { return h_; }
  double support() const { return 2.0 * h_; }
  double supportSquared() const { return 4.0 * h_ * h_; }
  double alpha() const { return alpha_; }

  /// W(r) [1/m^D].
  double value(double r) const {
    const double q = r * inv_h_;
    if (q >= 2.0) return 0.0;
    const double t = 2.0 - q;
    const double t2 = t * t;
    return alpha_ * t2 * t2 * (1.0 + 2.0 * q);
  }

  /// W(0), the self contribution.
  double valueAtZero() const { return 16.0 * alpha_; }

  /// F(r) such that grad_i W_ij = F(r) (r_i - r_j).
  double gradientFactor(double r) const {
    const double q = r * inv_h_;
    if (q >= 2.0) return 0.0;
    const double t = 2.0 - q;
    return grad_scale_ * t * t * t;
  }

  static double normalisation(double h) {
    constexpr double pi = 3.14159265358979323846;
    if constexpr (D == 2) return 7.0 / (64.0 * pi * h * h);
    else return 21.0 / (256.0 * pi * h * h * h);
  }

 private:
  double h_;
  double inv_h_;
  double alpha_;
  double grad_scale_;
};

}  // namespace moorsph::fluid
