#include <moorsph/fluid/packing_probe.hpp>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <moorsph/fluid/fluid_near_point.hpp>

namespace moorsph::fluid {

namespace {

/// Grid points at the centres of the cells of size ~spacing that tile [lower, upper]
/// (the count per axis rounded, at least one, so the points stay inside the box).
template <int D>
std::vector<Vec<D>> gridPoints(const PackingProbeSpec<D>& s) {
  Eigen::Array<long, D, 1> n;
  Vec<D> step;
  for (int a = 0; a < D; ++a) {
    const double edge = s.upper[a] - s.lower[a];
    n[a] = std::max(1L, std::lround(edge / s.spacing));
    step[a] = edge / static_cast<double>(n[a]);
  }
  std::vector<Vec<D>> out;
  out.reserve(static_cast<std::size_t>(n.prod()));
  Eigen::Array<long, D, 1> i = Eigen::Array<long, D, 1>::Zero();
  while (true) {
    Vec<D> p;
    for (int a = 0; a < D; ++a) p[a] = s.lower[a] + (static_cast<double>(i[a]) + 0.5) * step[a];
    out.push_back(p);
    int a = 0;
    while (a < D && ++i[a] == n[a]) i[a++] = 0;
    if (a == D) break;
  }
  return out;
}

}  // namespace

template <int D>
PackingProbe<D>::PackingProbe(PackingProbeSpec<D> spec) : spec_(spec) {
  if (!(spec_.spacing > 0.0)) throw std::invalid_argument("packing probe: spacing must be > 0");
  if (!(spec_.min_fill > 0.0 && spec_.min_fill < 1.0))
    throw std::invalid_argument("packing probe: min_fill must lie in (0, 1)");
  for (int a = 0; a < D; ++a)
    if (!(spec_.upper[a] > spec_.lower[a])) throw std::invalid_argument("packing probe: upper must exceed lower");
  const double cells = (spec_.upper - spec_.lower).prod() / std::pow(spec_.spacing, D);
  if (cells > 1e7) throw std::invalid_argument("packing probe: more than 1e7 grid points; give a larger spacing");
  points_ = gridPoints(spec_);
}

template <int D>
PackingReading PackingProbe<D>::read(const FluidSimulation<D>& sim) const {
  double sum = 0.0, sum2 = 0.0;
  long wet = 0;
  const long n = static_cast<long>(points_.size());
#pragma omp parallel for schedule(static) reduction(+ : sum, sum2, wet)
  for (long k = 0; k < n; ++k) {
    double xi = 0.0;
    forEachFluidNear(sim, points_[static_cast<std::size_t>(k)], [&](std::size_t, double w) { xi += w; });
    if (xi < spec_.min_fill) continue;
    sum += xi;
    sum2 += xi * xi;
    ++wet;
  }
  PackingReading r;
  r.wet_fraction = static_cast<double>(wet) / static_cast<double>(n);
  if (wet == 0) {
    r.mean = r.spread = std::numeric_limits<double>::quiet_NaN();
    return r;
  }
  r.mean = sum / static_cast<double>(wet);
  r.spread = std::sqrt(std::max(0.0, sum2 / static_cast<double>(wet) - r.mean * r.mean));
  return r;
}

template class PackingProbe<2>;
template class PackingProbe<3>;

}  // namespace moorsph::fluid
