#include <moorsph/fluid/wave_gauge.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace moorsph::fluid {
namespace {

// Horizontal separation of a particle from the gauge line (y dropped), minimum image.
template <int D>
double horizontalDistanceSquared(const Domain<D>& domain, const Vec<D>& line, const Vec<D>& r) {
  Vec<D> d = domain.minimumImage(r - line);
  d[1] = 0.0;
  return d.squaredNorm();
}

// Wendland C2 with h = 1 (support 2): W(q) = alpha (2 - q)^4 (1 + 2q).
template <int D>
double unitKernel(double q) {
  return q >= 2.0 ? 0.0 : WendlandKernel<D>::normalisation(1.0) * std::pow(2.0 - q, 4) * (1.0 + 2.0 * q);
}

// P(z): the unit kernel integrated over the line (2D) or plane (3D) at distance |z|
// from its centre. 3D in closed form through q^2 = rho^2 + z^2: 2 pi int_|z|^2 q W dq;
// 2D by Simpson's rule over the chord (the integrand is smooth: W is C2 and vanishes at 2).
template <int D>
double projectedKernel(double z) {
  const double a = std::abs(z);
  if (a >= 2.0) return 0.0;
  constexpr int n = 200;  // even
  double sum = 0.0;
  if constexpr (D == 3) {
    const double hq = (2.0 - a) / n;
    for (int k = 0; k <= n; ++k) {
      const double q = a + k * hq;
      sum += (k == 0 || k == n ? 1.0 : (k % 2 ? 4.0 : 2.0)) * q * unitKernel<3>(q);
    }
    return 2.0 * M_PI * sum * hq / 3.0;
  } else {
    const double half_chord = std::sqrt(4.0 - a * a);
    const double hx = half_chord / n;
    for (int k = 0; k <= n; ++k) {
      const double x = k * hx;
      sum += (k == 0 || k == n ? 1.0 : (k % 2 ? 4.0 : 2.0)) * unitKernel<2>(std::sqrt(x * x + a * a));
    }
    return 2.0 * sum * hx / 3.0;
  }
}

}  // namespace

template <int D>
double halfSpaceThresholdDepth(double threshold) {
  if (!(threshold > 0.0 && threshold < 1.0)) throw std::invalid_argument("wave gauge: threshold must lie in (0, 1)");
  // xi at depth s below the face = int_{-2}^{s} P(z) dz (P is even and integrates to 1):
  // march s up from -2 by the trapezoidal rule until xi passes the threshold.
  constexpr int n = 4000;
  const double ds = 4.0 / n;
  double xi = 0.0, p_prev = 0.0;
  for (int k = 1; k <= n; ++k) {
    const double s = -2.0 + k * ds;
    const double p = projectedKernel<D>(s);
    const double xi_next = xi + 0.5 * (p + p_prev) * ds;
    if (xi_next >= threshold) return s - ds * (xi_next - threshold) / (xi_next - xi);
    xi = xi_next;
    p_prev = p;
  }
  return 2.0;
}

template <int D>
WaveGauge<D>::WaveGauge(WaveGaugeSpec<D> spec) : spec_(std::move(spec)) {
  if (!(spec_.top > spec_.bottom)) throw std::invalid_argument("wave gauge: top must lie above bottom");
  if (!(spec_.threshold > 0.0)) throw std::invalid_argument("wave gauge: threshold must be positive");
  if (!(spec_.step_fraction > 0.0)) throw std::invalid_argument("wave gauge: step fraction must be positive");
  edge_depth_ = spec_.volume_edge ? halfSpaceThresholdDepth<D>(spec_.threshold) : 0.0;
}

template <int D>
void WaveGauge<D>::addCandidate(const FluidParticles<D>& fluid, const Domain<D>& domain, double support,
                                std::size_t i) const {
  const double r2h = horizontalDistanceSquared(domain, spec_.position, fluid.r[i]);
  if (r2h >= support * support) return;
  candidates_.push_back({fluid.r[i][1], r2h, fluid.m[i] / fluid.rho[i]});
}

template <int D>
double WaveGauge<D>::read(const FluidSimulation<D>& sim) const {
  const CellGrid<D>& grid = sim.neighbours().grid();
  const NeighbourSearch<D>& search = sim.neighbours();
  const FluidParticles<D>& fluid = sim.fluid();
  const Domain<D>& domain = sim.setup().domain;
  const double support = sim.kernel().support();
  // Before the first step nothing is sorted by cell yet: scan every particle.
  if (search.rebuildCount() == 0) return read(fluid, domain, sim.kernel(), sim.setup().dx);

  // The cells of the column around the line between bottom - 2h and top + 2h: the
  // block around the cell of each layer's centre. A cell is at least 2h + skin wide
  // and no particle has moved more than skin/2 since the last re-sort, so every
  // particle within 2h of the line is in one of them.
  cells_.clear();
  const double layer = grid.cellSize()[1];
  const double y_low = std::max(domain.lower[1], spec_.bottom - support);
  const double y_high = std::min(domain.upper[1], spec_.top + support);
  Vec<D> point = spec_.position;
  for (double y = y_low; y < y_high + layer; y += layer) {
    point[1] = std::min(y, domain.upper[1]);
    const int cell = grid.cellOf(point);
    cells_.insert(cells_.end(), grid.neighbourCellsBegin(cell), grid.neighbourCellsEnd(cell));
  }
  std::sort(cells_.begin(), cells_.end());
  cells_.erase(std::unique(cells_.begin(), cells_.end()), cells_.end());

  candidates_.clear();
  for (const std::uint32_t c : cells_) {
    const int cell = static_cast<int>(c);
    for (std::uint32_t i = search.cellStart(cell); i < search.cellStart(cell + 1); ++i)
      addCandidate(fluid, domain, support, i);
  }
  return searchDown(sim.kernel(), sim.setup().dx);
}

template <int D>
double WaveGauge<D>::read(const FluidParticles<D>& fluid, const Domain<D>& domain, const WendlandKernel<D>& kernel,
                          double dx) const {
  candidates_.clear();
  for (std::size_t i = 0; i < fluid.size(); ++i) addCandidate(fluid, domain, kernel.support(), i);
  return searchDown(kernel, dx);
}

template <int D>
double WaveGauge<D>::searchDown(const WendlandKernel<D>& kernel, double dx) const {
  std::sort(candidates_.begin(), candidates_.end(),
            [](const Candidate& a, const Candidate& b) { return a.y < b.y; });
  const double support = kernel.support();
  const auto xiAt = [&](double y) {
    const auto first = std::lower_bound(candidates_.begin(), candidates_.end(), y - support,
                                        [](const Candidate& c, double v) { return c.y < v; });
    double xi = 0.0;
    for (auto c = first; c != candidates_.end() && c->y < y + support; ++c) {
      const double dy = c->y - y;
      xi += c->volume * kernel.value(std::sqrt(c->r2h + dy * dy));
    }
    return xi;
  };

  const double threshold = spec_.threshold;
  const double step = spec_.step_fraction * dx;
  double y_above = spec_.top;
  double xi_above = xiAt(y_above);
  if (xi_above >= threshold) return spec_.top;  // water over the whole line
  if (candidates_.empty()) return spec_.bottom;
  // Nothing can be wet above the highest candidate + 2h: start there if lower.
  const double start = std::min(spec_.top, candidates_.back().y + support);
  if (start < y_above) {
    y_above = start;
    xi_above = xiAt(y_above);  // zero, up to round-off
  }
  while (y_above > spec_.bottom) {
    const double y = std::max(spec_.bottom, y_above - step);
    const double xi = xiAt(y);
    if (xi >= threshold) {
      // Linear interpolation of xi between the two samples that bracket xi_t.
      const double fraction = (threshold - xi_above) / (xi - xi_above);
      const double crossing = y_above - fraction * (y_above - y);
      return std::min(spec_.top, crossing + edge_depth_ * kernel.h());
    }
    y_above = y;
    xi_above = xi;
  }
  return spec_.bottom;  // dry
}

template <int D>
double WaveGauge<D>::particleDensity(const FluidParticles<D>& fluid, const Domain<D>& domain,
                                     const WendlandKernel<D>& kernel, const Vec<D>& point) {
  double xi = 0.0;
  for (std::size_t i = 0; i < fluid.size(); ++i)
    xi += fluid.m[i] / fluid.rho[i] * kernel.value(domain.minimumImage(fluid.r[i] - point).norm());
  return xi;
}

template class WaveGauge<2>;
template class WaveGauge<3>;
template double halfSpaceThresholdDepth<2>(double);
template double halfSpaceThresholdDepth<3>(double);

}  // namespace moorsph::fluid
