#include <moorsph/fluid/particle_shifting.hpp>

#include <cmath>
#include <stdexcept>
#include <moorsph/fluid/wendland_kernel.hpp>

namespace moorsph::fluid {

template <int D>
ParticleShifting<D>::ParticleShifting(const ShiftingParameters& parameters, double dx, double h,
                                      const BoundaryParticles<D>* boundary)
    : p_(parameters), h_(h), inv_w_dx_(1.0 / WendlandKernel<D>(h).value(dx)), boundary_(boundary) {
  if (!(p_.coefficient > 0.0)) throw std::invalid_argument("particle_shifting: the coefficient must be positive");
  if (!(p_.cap > 0.0)) throw std::invalid_argument("particle_shifting: the cap must be positive");
  if (p_.anti_clustering < 0.0) throw std::invalid_argument("particle_shifting: the anti-clustering factor must be >= 0");
  if (p_.surface_divergence < 0.0) p_.surface_divergence = D - 0.4;
  if (p_.splash_divergence < 0.0) p_.splash_divergence = 0.5 * D;
  if (p_.splash_divergence > p_.surface_divergence)
    throw std::invalid_argument("particle_shifting: the splash threshold must not exceed the surface threshold");
}

template <int D>
void ParticleShifting<D>::addRates(FluidContext<D>& ctx) {
  const std::size_t n = ctx.fluid.size();
  grad_c_.resize(n);
  normal_.resize(n);
  div_r_.resize(n);
  region_.resize(n);
  measureConcentration(ctx);
  classify(ctx);
  applyShift(ctx);
}

// grad C with the anti-clustering bracket of (1), the plain grad C (its direction is the
// surface normal) and div r, over the fluid neighbours only.
template <int D>
void ParticleShifting<D>::measureConcentration(const FluidContext<D>& ctx) {
  const FluidParticles<D>& f = ctx.fluid;
  const NeighbourList& list = ctx.neighbours.fluidFluid();
  const Domain<D>& domain = ctx.setup.domain;
  const bool periodic = domain.anyPeriodic();
  const WendlandKernel<D>& kernel = ctx.kernel;
  const double support2 = kernel.supportSquared();
  const std::size_t n = f.size();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    Vec<D> grad = Vec<D>::Zero(), grad_plain = Vec<D>::Zero();
    double div = 0.0;
    for (std::uint64_t s = list.begin[i]; s < list.begin[i + 1]; ++s) {
      const std::uint32_t j = list.index[s];
      Vec<D> rij = f.r[i] - f.r[j];
      if (periodic) rij = domain.minimumImage(rij);
      const double r2 = rij.squaredNorm();
      if (r2 >= support2) continue;
      const double dist = std::sqrt(r2);
      const double volume = f.m[j] / f.rho[j];
      const double F = kernel.gradientFactor(dist);  // grad_i W_ij = F r_ij
      const double w_ratio = kernel.value(dist) * inv_w_dx_;
      double w_power = 1.0;
      for (int k = 0; k < p_.anti_clustering_power; ++k) w_power *= w_ratio;
      const double bracket = 1.0 + p_.anti_clustering * w_power;
      grad_plain += (volume * F) * rij;
      grad += (volume * F * bracket) * rij;
      div -= volume * F * r2;
    }
    grad_c_[i] = grad;
    const double g = grad_plain.norm();
    normal_[i] = g > 0.0 ? Vec<D>(-grad_plain / g) : Vec<D>::Zero();
    div_r_[i] = div;
  }
}

template <int D>
void ParticleShifting<D>::classify(const FluidContext<D>& ctx) {
  const std::size_t n = ctx.fluid.size();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    region_[i] = div_r_[i] < p_.splash_divergence    ? Region::Splash
                 : div_r_[i] < p_.surface_divergence ? Region::Surface
                                                     : Region::Bulk;
  }
  // The surface normal is the kernel-weighted mean of the surface particles' own normals
  // within 2h: a particle's own grad C is tilted by its own displacement, the mean is not.
  // Bulk particles with a surface particle within 2h take it too (the near-surface band).
  // Written to separate arrays so no thread reads what another writes.
  const NeighbourList& list = ctx.neighbours.fluidFluid();
  const Domain<D>& domain = ctx.setup.domain;
  const bool periodic = domain.anyPeriodic();
  const double support2 = ctx.kernel.supportSquared();
  const double self_weight = ctx.kernel.valueAtZero();
  const auto& r = ctx.fluid.r;
  band_normal_.resize(n);
  near_surface_.assign(n, 0);
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    if (region_[i] == Region::Splash) continue;
    Vec<D> sum = region_[i] == Region::Surface ? Vec<D>(self_weight * normal_[i]) : Vec<D>::Zero();
    for (std::uint64_t s = list.begin[i]; s < list.begin[i + 1]; ++s) {
      const std::uint32_t j = list.index[s];
      if (region_[j] != Region::Surface) continue;
      Vec<D> rij = r[i] - r[j];
      if (periodic) rij = domain.minimumImage(rij);
      const double r2 = rij.squaredNorm();
      if (r2 < support2) sum += ctx.kernel.value(std::sqrt(r2)) * normal_[j];
    }
    const double norm = sum.norm();
    if (norm > 0.0) {
      band_normal_[i] = sum / norm;
      near_surface_[i] = 1;
    }
  }
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    if (!near_surface_[i]) continue;
    normal_[i] = band_normal_[i];
    if (region_[i] == Region::Bulk) region_[i] = Region::NearSurface;
  }
}

template <int D>
void ParticleShifting<D>::applyShift(FluidContext<D>& ctx) const {
  FluidParticles<D>& f = ctx.fluid;
  const std::size_t n = f.size();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    if (region_[i] == Region::Splash) continue;
    const double speed = f.v[i].norm();
    if (speed == 0.0) continue;
    Vec<D> shift = (-p_.coefficient * h_ * speed) * grad_c_[i];
    if (region_[i] != Region::Bulk) shift -= shift.dot(normal_[i]) * normal_[i];
    shift = withoutWallComponents(ctx, i, shift);
    const double size = shift.norm(), limit = p_.cap * speed;
    if (size > limit) shift *= limit / size;
    f.drdt[i] += shift;
  }
}

template <int D>
Vec<D> ParticleShifting<D>::withoutWallComponents(const FluidContext<D>& ctx, std::size_t i, Vec<D> shift) const {
  if (!boundary_) return shift;
  const NeighbourList& list = ctx.neighbours.fluidBoundary();
  const Domain<D>& domain = ctx.setup.domain;
  const double support2 = ctx.kernel.supportSquared();
  const BoundaryParticles<D>& b = *boundary_;
  for (std::uint64_t s = list.begin[i]; s < list.begin[i + 1]; ++s) {
    const std::uint32_t k = list.index[s];
    if (domain.minimumImage(ctx.fluid.r[i] - b.r[k]).squaredNorm() >= support2) continue;
    for (std::uint32_t a = b.normal_begin[k]; a < b.normal_begin[k + 1]; ++a) {
      const double into_wall = shift.dot(b.normals[a]);  // normals point into the fluid
      if (into_wall < 0.0) shift -= into_wall * b.normals[a];
    }
  }
  return shift;
}

template class ParticleShifting<2>;
template class ParticleShifting<3>;

}  // namespace moorsph::fluid
