#include <moorsph/fluid/damping_zone.hpp>

#include <stdexcept>

namespace moorsph::fluid {

template <int D>
DampingZone<D>::DampingZone(double x_start, double x_end, double k_max, double max_dt)
    : x_start_(x_start), x_end_(x_end), k_max_(k_max) {
  if (!(x_end > x_start)) throw std::invalid_argument("damping_zone: x_end must exceed x_start");
  if (!(k_max > 0.0)) throw std::invalid_argument("damping_zone: the damping rate must be positive");
  if (k_max * max_dt >= 1.0) throw std::invalid_argument("damping_zone: rate x time step must stay below 1 for stability");
}

template <int D>
double DampingZone<D>::rate(double x) const {
  if (x <= x_start_) return 0.0;
  const double s = x >= x_end_ ? 1.0 : (x - x_start_) / (x_end_ - x_start_);
  return k_max_ * s * s;
}

template <int D>
void DampingZone<D>::addRates(FluidContext<D>& ctx) {
  FluidParticles<D>& f = ctx.fluid;
  const std::size_t n = f.size();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    const double k = rate(f.r[i][0]);
    if (k > 0.0) f.dvdt[i][0] -= k * f.v[i][0];
  }
}

template class DampingZone<2>;
template class DampingZone<3>;

}  // namespace moorsph::fluid
