#include <moorsph/fluid/forcing_region.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace moorsph::fluid {

template <int D>
ForcingRegion<D>::ForcingRegion(ForcingRegionSpec spec, TargetField target, double max_dt)
    : spec_(spec), target_(std::move(target)), strength_(std::pow(10.0, spec.kappa) * spec.mu) {
  if (!(spec_.length > 0.0)) throw std::invalid_argument("forcing_region: length must be positive");
  if (!(spec_.ramp_up >= 0.0)) throw std::invalid_argument("forcing_region: ramp_up must not be negative");
  if (!(spec_.gain > 0.0)) throw std::invalid_argument("forcing_region: gain must be positive");
  if (!(spec_.still_level > spec_.floor + spec_.bottom_gap))
    throw std::invalid_argument("forcing_region: the still level must lie above the region's bottom");
  // Relaxation rate strength/rho; explicit stepping needs rate * dt < 1 (METHOD.md:
  // a larger kappa "overshoots and shrinks dt").
  if (strength_ / 1000.0 * max_dt >= 1.0)
    throw std::invalid_argument("forcing_region: 10^kappa mu / rho x dt >= 1: lower kappa or the time step");
}

template <int D>
bool ForcingRegion<D>::contains(const Vec<D>& r) const {
  return r[0] >= spec_.x_start && r[0] <= spec_.x_start + spec_.length && r[1] >= spec_.floor + spec_.bottom_gap &&
         r[1] <= spec_.still_level;
}

template <int D>
double ForcingRegion<D>::targetScale(double t) const {
  if (t >= spec_.end_time) return 0.0;
  const double ramp = t >= spec_.ramp_up ? 1.0 : 0.5 * (1.0 - std::cos(M_PI * std::max(t, 0.0) / spec_.ramp_up));
  return spec_.gain * ramp;
}

template <int D>
void ForcingRegion<D>::addRates(FluidContext<D>& ctx) {
  FluidParticles<D>& f = ctx.fluid;
  const std::size_t n = f.size();
  const double t = ctx.time;
  if (t >= spec_.end_time) return;
  const double scale = targetScale(t);
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    if (!contains(f.r[i])) continue;
    const Eigen::Vector2d vc = scale * target_(f.r[i][0], f.r[i][1] - spec_.floor, t);
    const double rate = strength_ / f.rho[i];
    f.dvdt[i][0] += rate * (vc[0] - f.v[i][0]);
    f.dvdt[i][1] += rate * (vc[1] - f.v[i][1]);
  }
}

double periodicSpacing(double length, double dx_target, double h_factor) {
  const double p = std::floor(length / (10.0 * h_factor * dx_target));
  if (p < 1.0) throw std::invalid_argument("periodic length shorter than 10 h_f dx: cannot fit whole cells");
  return length / (10.0 * p * h_factor);
}

template class ForcingRegion<2>;
template class ForcingRegion<3>;

}  // namespace moorsph::fluid
