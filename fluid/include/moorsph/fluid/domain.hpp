#pragma once
// The region particles may occupy: an axis-aligned box whose directions are either
// periodic (positions wrap, distances use the minimum image) or bounded (a fluid
// particle outside the box has escaped: the run stops with a diagnostic).
#include <array>
#include <cmath>
#include <moorsph/fluid/vec.hpp>

namespace moorsph::fluid {

template <int D>
struct Domain {
  Vec<D> lower = Vec<D>::Zero();
  Vec<D> upper = Vec<D>::Ones();
  std::array<bool, D> periodic{};

  Vec<D> length() const { return upper - lower; }
  bool anyPeriodic() const {
    for (bool p : periodic) if (p) return true;
    return false;
  }

  /// Shortest separation vector under the periodic directions (minimum image).
  Vec<D> minimumImage(Vec<D> d) const {
    for (int k = 0; k < D; ++k) {
      if (periodic[k]) {
        const double L = upper[k] - lower[k];
        d[k] -= L * std::nearbyint(d[k] / L);
      }
    }
    return d;
  }

  /// Position wrapped into [lower, upper) along the periodic directions.
  Vec<D> wrap(Vec<D> r) const {
    for (int k = 0; k < D; ++k) {
      if (periodic[k]) {
        const double L = upper[k] - lower[k];
        r[k] -= L * std::floor((r[k] - lower[k]) / L);
        if (r[k] >= upper[k]) r[k] -= L;  // guard against round-off at the top edge
      }
    }
    return r;
  }

  /// True if r lies inside the box along every bounded direction.
  bool contains(const Vec<D>& r) const {
    for (int k = 0; k < D; ++k) {
      if (!periodic[k] && (r[k] < lower[k] || r[k] > upper[k])) return false;
    }
    return true;
  }
};

/// Domain::minimumImage for loops over many pairs: the periods' reciprocals are taken
/// once, so a pair multiplies where minimumImage divides (a division costs as much as
/// the rest of a list candidate's test). The shift is the same unless d lies within
/// round-off of half a period, which no pair within a list radius comes near.
template <int D>
struct MinimumImage {
  Vec<D> period = Vec<D>::Zero();      ///< L along the periodic axes, 0 along the bounded ones
  Vec<D> inv_period = Vec<D>::Zero();  ///< 1/L along the periodic axes, 0 (no shift) along the bounded ones
  explicit MinimumImage(const Domain<D>& domain) {
    for (int k = 0; k < D; ++k) {
      if (!domain.periodic[k]) continue;
      period[k] = domain.upper[k] - domain.lower[k];
      inv_period[k] = 1.0 / period[k];
    }
  }
  Vec<D> operator()(Vec<D> d) const {
    for (int k = 0; k < D; ++k) d[k] -= period[k] * std::nearbyint(d[k] * inv_period[k]);
    return d;
  }
};

}  // namespace moorsph::fluid
