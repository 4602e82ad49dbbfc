#include <moorsph/fluid/lattice_packing.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <stdexcept>
#include <tuple>
#include <moorsph/fluid/neighbour_search.hpp>
#include <moorsph/fluid/wendland_kernel.hpp>

namespace moorsph::fluid {

template <int D>
std::vector<MirrorPlane> packingMirrors(const Vec<D>& lower, const Vec<D>& upper, const Domain<D>& domain) {
  std::vector<MirrorPlane> planes;
  for (int a = 0; a < D; ++a) {
    const double period = domain.upper[a] - domain.lower[a];
    const bool spans_period = domain.periodic[a] && upper[a] - lower[a] >= period - 1e-9 * period;
    if (spans_period) continue;
    planes.push_back(MirrorPlane{a, lower[a], +1});
    planes.push_back(MirrorPlane{a, upper[a], -1});
  }
  return planes;
}

namespace {

// The concentration and its gradient at one particle, images included.
template <int D>
struct Concentration {
  double c = 0.0;
  Vec<D> grad = Vec<D>::Zero();
};

template <int D>
class Packer {
 public:
  Packer(FluidParticles<D>& block, const Vec<D>& lower, const Vec<D>& upper, const Domain<D>& domain, double dx,
         double h)
      : f_(block), domain_(domain), dx_(dx), kernel_(h),
        volume_(std::pow(dx, D)), planes_(packingMirrors<D>(lower, upper, domain)),
        search_(domain, 2.0 * h, 0.5 * dx) {}

  void jitter(const PackingSpec& spec) {
    std::mt19937_64 random(spec.seed);
    std::uniform_real_distribution<double> u(-spec.jitter * dx_, spec.jitter * dx_);
    for (auto& r : f_.r) {
      for (int a = 0; a < D; ++a) r[a] += u(random);
      r = keptInside(r);
    }
  }

  /// One Jacobi step of (1); returns the rms move [m].
  double descend(const PackingSpec& spec) {
    refreshLists();
    const std::size_t n = f_.size();
    shift_.resize(n);
    const double gain = spec.step * kernel_.h() * kernel_.h(), cap = spec.max_shift * dx_;
    double sum2 = 0.0;
#pragma omp parallel for schedule(static) reduction(+ : sum2)
    for (std::size_t i = 0; i < n; ++i) {
      Vec<D> s = -gain * concentrationAt(i).grad;
      const double size = s.norm();
      if (size > cap) s *= cap / size;
      shift_[i] = s;
      sum2 += s.squaredNorm();
    }
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) f_.r[i] = keptInside(f_.r[i] + shift_[i]);
    return std::sqrt(sum2 / static_cast<double>(n));
  }

  /// Mean and rms spread of C over the particles at least 2h from every mirror face.
  std::pair<double, double> interiorStatistics() {
    refreshLists();
    double sum = 0.0, sum2 = 0.0;
    std::size_t count = 0;
    for (std::size_t i = 0; i < f_.size(); ++i) {
      if (nearMirror(f_.r[i])) continue;
      const double c = concentrationAt(i).c;
      sum += c;
      sum2 += c * c;
      ++count;
    }
    if (count == 0) return {0.0, 0.0};
    const double mean = sum / static_cast<double>(count);
    return {mean, std::sqrt(std::max(0.0, sum2 / static_cast<double>(count) - mean * mean))};
  }

 private:
  void refreshLists() {
    if (search_.needsRebuild(f_, nullptr, 0.0)) search_.rebuild(f_, nullptr, no_tracking_);
  }

  bool nearMirror(const Vec<D>& r) const {
    for (const MirrorPlane& p : planes_)
      if (std::abs(r[p.axis] - p.position) < kernel_.support()) return true;
    return false;
  }

  void add(Concentration<D>& out, const Vec<D>& rij) const {
    const double r2 = rij.squaredNorm();
    if (r2 >= kernel_.supportSquared()) return;
    const double dist = std::sqrt(r2);
    out.c += volume_ * kernel_.value(dist);
    out.grad += (volume_ * kernel_.gradientFactor(dist)) * rij;  // grad_i W_ij = F r_ij
  }

  // The image of r across every plane in `mask` (bit k: planes_[k]).
  Vec<D> reflected(Vec<D> r, unsigned mask) const {
    for (std::size_t k = 0; k < planes_.size(); ++k)
      if (mask & (1u << k)) r[planes_[k].axis] = planes_[k].mirrored(r[planes_[k].axis]);
    return r;
  }

  Concentration<D> concentrationAt(std::size_t i) const {
    Concentration<D> out;
    out.c = volume_ * kernel_.valueAtZero();
    // Planes within reach of i; a mask combines at most one plane per axis.
    unsigned near = 0;
    for (std::size_t k = 0; k < planes_.size(); ++k)
      if (std::abs(f_.r[i][planes_[k].axis] - planes_[k].position) < kernel_.support()) near |= 1u << k;
    std::array<unsigned, 1u << (2 * D)> masks{};
    std::size_t count = 0;
    for (unsigned m = near; m != 0; m = (m - 1) & near) {
      unsigned axes = 0;
      bool twice = false;
      for (std::size_t k = 0; k < planes_.size(); ++k) {
        if (!(m & (1u << k))) continue;
        twice = twice || (axes & (1u << planes_[k].axis));
        axes |= 1u << planes_[k].axis;
      }
      if (!twice) masks[count++] = m;
    }
    const NeighbourList& list = search_.fluidFluid();
    for (std::size_t k = 0; k < count; ++k) add(out, f_.r[i] - reflected(f_.r[i], masks[k]));  // i's own images
    for (std::uint64_t s = list.begin[i]; s < list.begin[i + 1]; ++s) {
      const std::uint32_t j = list.index[s];
      add(out, domain_.minimumImage(f_.r[i] - f_.r[j]));
      // An image is never nearer than the particle itself (both on the same side), so
      // the list holds every image within reach.
      for (std::size_t k = 0; k < count; ++k) add(out, domain_.minimumImage(f_.r[i] - reflected(f_.r[j], masks[k])));
    }
    return out;
  }

  Vec<D> keptInside(Vec<D> r) const {
    for (const MirrorPlane& p : planes_)
      if (p.outside(r[p.axis])) r[p.axis] = p.mirrored(r[p.axis]);
    return domain_.wrap(r);
  }

  FluidParticles<D>& f_;
  Domain<D> domain_;
  double dx_;
  WendlandKernel<D> kernel_;
  double volume_;
  std::vector<MirrorPlane> planes_;
  NeighbourSearch<D> search_;
  std::vector<char> no_tracking_;
  std::vector<Vec<D>> shift_;
};

}  // namespace

template <int D>
PackingReport packBlock(FluidParticles<D>& block, const Vec<D>& lower, const Vec<D>& upper, const Domain<D>& domain,
                        double dx, double h, const PackingSpec& spec) {
  if (spec.iterations < 0) throw std::invalid_argument("packing: iterations must be >= 0");
  if (!(spec.step > 0.0) || !(spec.max_shift > 0.0) || spec.jitter < 0.0)
    throw std::invalid_argument("packing: step and max_shift must be positive, jitter >= 0");
  PackingReport report;
  if (block.size() == 0) return report;
  Packer<D> packer(block, lower, upper, domain, dx, h);
  std::tie(report.mean_before, report.spread_before) = packer.interiorStatistics();
  packer.jitter(spec);
  for (int k = 0; k < spec.iterations; ++k) report.last_rms_shift = packer.descend(spec) / dx;
  report.iterations = spec.iterations;
  std::tie(report.mean_after, report.spread_after) = packer.interiorStatistics();
  return report;
}

template std::vector<MirrorPlane> packingMirrors<2>(const Vec<2>&, const Vec<2>&, const Domain<2>&);
template std::vector<MirrorPlane> packingMirrors<3>(const Vec<3>&, const Vec<3>&, const Domain<3>&);
template PackingReport packBlock<2>(FluidParticles<2>&, const Vec<2>&, const Vec<2>&, const Domain<2>&, double, double,
                                    const PackingSpec&);
template PackingReport packBlock<3>(FluidParticles<3>&, const Vec<3>&, const Vec<3>&, const Domain<3>&, double, double,
                                    const PackingSpec&);

}  // namespace moorsph::fluid
