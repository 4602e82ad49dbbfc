#include "study/convergence.hpp"

#include <cmath>
#include <limits>

namespace moorsph::app::study {

std::vector<double> observedOrders(const std::vector<double>& h, const std::vector<double>& errors) {
  std::vector<double> orders;
  for (std::size_t k = 0; k + 1 < h.size() && k + 1 < errors.size(); ++k) {
    const double e1 = std::abs(errors[k]), e2 = std::abs(errors[k + 1]);
    const bool usable = e1 > 0.0 && e2 > 0.0 && std::isfinite(e1) && std::isfinite(e2) && h[k] > h[k + 1];
    orders.push_back(usable ? std::log(e1 / e2) / std::log(h[k] / h[k + 1]) : std::numeric_limits<double>::quiet_NaN());
  }
  return orders;
}

std::optional<Richardson> richardsonFromFinest(const std::vector<double>& h, const std::vector<double>& f,
                                               std::string* why) {
  auto fail = [why](const char* reason) -> std::optional<Richardson> {
    if (why) *why = reason;
    return std::nullopt;
  };
  const std::size_t n = h.size();
  if (n < 3 || f.size() != n) return fail("needs at least three resolutions");
  const double h1 = h[n - 3], h2 = h[n - 2], h3 = h[n - 1];
  const double f1 = f[n - 3], f2 = f[n - 2], f3 = f[n - 1];
  if (!(h1 > h2 && h2 > h3 && h3 > 0.0)) return fail("the spacings must decrease");
  if (f2 == f3) return fail("the two finest values are equal (converged, or insensitive to dx): no order to observe");
  const double ratio = (f1 - f2) / (f2 - f3);
  if (!(ratio > 0.0)) return fail("the three finest values do not converge monotonically (oscillatory): no extrapolate");
  // g(p) = (s1^p - s2^p) / (s2^p - 1) with s = h / h3 increases with p from
  // ln(s1/s2)/ln(s2) at p -> 0; solve g(p) = ratio by bisection in log space.
  const double s1 = h1 / h3, s2 = h2 / h3;
  auto g = [&](double p) { return (std::pow(s1, p) - std::pow(s2, p)) / (std::pow(s2, p) - 1.0); };
  double lo = 1e-3, hi = 20.0;
  if (ratio <= g(lo)) return fail("the values diverge or converge slower than order 0.001: no extrapolate");
  if (ratio >= g(hi)) return fail("apparent order above 20: the values are not in the asymptotic range");
  for (int it = 0; it < 200; ++it) {
    const double mid = 0.5 * (lo + hi);
    (g(mid) < ratio ? lo : hi) = mid;
  }
  Richardson r;
  r.order = 0.5 * (lo + hi);
  r.estimate = f3 + (f3 - f2) / (std::pow(s2, r.order) - 1.0);
  return r;
}

}  // namespace moorsph::app::study
