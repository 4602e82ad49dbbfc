#include <moorsph/fluid/outflow.hpp>

#include <algorithm>
#include <cmath>

namespace moorsph::fluid {

template <int D>
Outflow<D>::Outflow(const WallExtent<D>& walls, double speed_limit)
    : walls_(walls), speed_limit_(speed_limit), lowest_top_(walls.top()) {
  for (int a = 0; a < D; ++a)
    if (a != 1) lowest_top_ = std::min({lowest_top_, walls.lower_side_top[a], walls.upper_side_top[a]});
}

template <int D>
bool Outflow<D>::qualifies(const FluidParticles<D>& f, std::size_t i, const Domain<D>& domain) const {
  const Vec<D>& r = f.r[i];
  if (!(r[1] > lowest_top_)) return false;
  bool over = !domain.contains(r) && r[1] > walls_.top();
  for (int a = 0; a < D && !over; ++a) {
    if (a == 1 || domain.periodic[a]) continue;
    over = (r[a] < walls_.lower[a] && r[1] > walls_.lower_side_top[a]) ||
           (r[a] > walls_.upper[a] && r[1] > walls_.upper_side_top[a]);
  }
  if (!over) return false;
  return r.allFinite() && f.v[i].allFinite() && std::isfinite(f.rho[i]) && f.rho[i] > 0.0 &&
         f.v[i].norm() < speed_limit_;
}

template <int D>
std::size_t Outflow<D>::apply(FluidParticles<D>& f, const Domain<D>& domain, const Vec<D>& gravity, const TaitEos& eos,
                              double time) {
  const std::size_t n = f.size();
  // One cheap pass finds whether anything left; removals are rare events.
  std::size_t first = n;
#pragma omp parallel for schedule(static) reduction(min : first)
  for (std::size_t i = 0; i < n; ++i)
    if (qualifies(f, i, domain)) first = std::min(first, i);
  if (first == n) return 0;

  std::size_t kept = first;
  for (std::size_t i = first; i < n; ++i) {
    if (qualifies(f, i, domain)) {
      ++tally_.particles;
      tally_.mass += f.m[i];
      tally_.energy += f.m[i] * (0.5 * f.v[i].squaredNorm() - gravity.dot(f.r[i]) + eos.elasticEnergy(f.rho[i]));
      if (std::isnan(tally_.first_time)) tally_.first_time = time;
      continue;
    }
    f.r[kept] = f.r[i];
    f.v[kept] = f.v[i];
    f.rho[kept] = f.rho[i];
    f.m[kept] = f.m[i];
    f.id[kept] = f.id[i];
    ++kept;
  }
  f.r.resize(kept);
  f.v.resize(kept);
  f.rho.resize(kept);
  f.m.resize(kept);
  f.id.resize(kept);
  return n - kept;
}

template class Outflow<2>;
template class Outflow<3>;

}  // namespace moorsph::fluid
