#include <moorsph/fluid/cubic_spline.hpp>

#include <algorithm>
#include <stdexcept>

namespace moorsph::fluid {

// Second derivatives from the tridiagonal system of continuity of the first
// derivative at the interior knots (Thomas algorithm), m_0 = m_n = 0.
CubicSpline::CubicSpline(std::vector<double> t, std::vector<double> x) : t_(std::move(t)), x_(std::move(x)) {
  const std::size_t n = t_.size();
  if (n < 2 || x_.size() != n) throw std::invalid_argument("cubic spline needs at least two (t, x) samples of equal count");
  for (std::size_t i = 1; i < n; ++i)
    if (!(t_[i] > t_[i - 1])) throw std::invalid_argument("cubic spline times must increase strictly");
  m_.assign(n, 0.0);
  if (n < 3) return;
  std::vector<double> diag(n, 0.0), rhs(n, 0.0), upper(n, 0.0);
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const double h0 = t_[i] - t_[i - 1], h1 = t_[i + 1] - t_[i];
    diag[i] = 2.0 * (h0 + h1);
    upper[i] = h1;
    rhs[i] = 6.0 * ((x_[i + 1] - x_[i]) / h1 - (x_[i] - x_[i - 1]) / h0);
    if (i > 1) {  // eliminate the lower entry h0 using row i-1
      const double f = h0 / diag[i - 1];
      diag[i] -= f * upper[i - 1];
      rhs[i] -= f * rhs[i - 1];
    }
  }
  for (std::size_t i = n - 2; i >= 1; --i) {
    m_[i] = (rhs[i] - upper[i] * m_[i + 1]) / diag[i];
    if (i == 1) break;
  }
}

std::size_t CubicSpline::interval(double t) const {
  const auto it = std::upper_bound(t_.begin(), t_.end(), t);
  const std::size_t i = static_cast<std::size_t>(std::max<std::ptrdiff_t>(1, it - t_.begin()));
  return std::min(i, t_.size() - 1) - 1;
}

double CubicSpline::value(double t) const {
  if (t <= t_.front()) return x_.front();
  if (t >= t_.back()) return x_.back();
  const std::size_t i = interval(t);
  const double h = t_[i + 1] - t_[i];
  const double a = (t_[i + 1] - t) / h, b = (t - t_[i]) / h;
  return a * x_[i] + b * x_[i + 1] + ((a * a * a - a) * m_[i] + (b * b * b - b) * m_[i + 1]) * h * h / 6.0;
}

double CubicSpline::derivative(double t) const {
  if (t <= t_.front() || t >= t_.back()) return 0.0;
  const std::size_t i = interval(t);
  const double h = t_[i + 1] - t_[i];
  const double a = (t_[i + 1] - t) / h, b = (t - t_[i]) / h;
  return (x_[i + 1] - x_[i]) / h + ((1.0 - 3.0 * a * a) * m_[i] + (3.0 * b * b - 1.0) * m_[i + 1]) * h / 6.0;
}

}  // namespace moorsph::fluid
