#pragma once
// Convergence analysis of a resolution study (Roache 1998, "Verification and
// Validation in Computational Science and Engineering", ch. 5; Celik et al. 2008,
// J. Fluids Eng. 130:078001, the grid convergence procedure).
//
// With a quantity f(h) = f0 + C h^p + higher order, spacings h1 > h2 > h3:
//  - observed order from two errors against a known f0:   p = ln(e1/e2) / ln(h1/h2);
//  - from three values alone, p solves
//        (f1 - f2) / (f2 - f3) = (h1^p - h2^p) / (h2^p - h3^p)            (Celik eq. 3)
//    (for a constant ratio r = h1/h2 = h2/h3: p = ln((f1-f2)/(f2-f3)) / ln r), and the
//    Richardson extrapolate is f0 = f3 + (f3 - f2) / ((h2/h3)^p - 1)       (Celik eq. 4).
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace moorsph::app::study {

/// Orders from consecutive pairs: element k compares run k and k+1 (h decreasing).
/// NaN where an error is zero or the pair does not shrink the error.
std::vector<double> observedOrders(const std::vector<double>& h, const std::vector<double>& errors);

struct Richardson {
  double order = 0.0;      ///< observed order p
  double estimate = 0.0;   ///< extrapolated f0
};

/// From the three finest of (h, f) (h decreasing). Empty, with `why` set, when the
/// three values do not converge monotonically (then no extrapolate exists).
std::optional<Richardson> richardsonFromFinest(const std::vector<double>& h, const std::vector<double>& f,
                                               std::string* why = nullptr);

}  // namespace moorsph::app::study
