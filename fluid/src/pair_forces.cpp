#include <moorsph/fluid/pair_forces.hpp>

#include <stdexcept>
#include <type_traits>
#include <vector>
#include <Eigen/LU>
#include <moorsph/fluid/pair_terms.hpp>

namespace moorsph::fluid {
namespace {

template <int D, bool Periodic, class Viscosity, class Xsph, class Diffusion>
class PairForcesImpl final : public PairForces<D> {
  static constexpr bool kViscosity = !std::is_same_v<Viscosity, NoTerm>;
  static constexpr bool kXsph = !std::is_same_v<Xsph, NoTerm>;
  static constexpr bool kDiffusion = !std::is_same_v<Diffusion, NoTerm>;
  static constexpr bool kRenormalised = std::is_same_v<Diffusion, RenormalisedDensityDiffusionTerm<D>>;

 public:
  PairForcesImpl(Viscosity viscosity, Xsph xsph, Diffusion diffusion)
      : viscosity_(viscosity), xsph_(xsph), diffusion_(diffusion) {}

  std::uint64_t lastInteractions() const override { return interactions_; }

  void evaluate(FluidContext<D>& ctx) override {
    FluidParticles<D>& f = ctx.fluid;
    const std::size_t n = f.size();
    const TaitEos eos = ctx.eos;
    // Per-particle quotients computed once, so the pair loop divides at most once a pair.
    if (p_over_rho2_.size() != n) {
      p_over_rho2_.resize(n);
      inv_rho_.resize(n);
      volume_.resize(n);
    }
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) {
      f.p[i] = eos.pressure(f.rho[i]);
      inv_rho_[i] = 1.0 / f.rho[i];
      p_over_rho2_[i] = f.p[i] * inv_rho_[i] * inv_rho_[i];
      volume_[i] = f.m[i] * inv_rho_[i];
    }
    if constexpr (kRenormalised) densityGradients(ctx);
    interactions_ = sumPairs(ctx);
  }

 private:
  /// G_i of RenormalisedDensityDiffusionTerm: the renormalised density gradient.
  void densityGradients(FluidContext<D>& ctx) {
    const FluidParticles<D>& f = ctx.fluid;
    const NeighbourList& list = ctx.neighbours.fluidFluid();
    const Domain<D> domain = ctx.setup.domain;
    const double inv_h = 1.0 / ctx.kernel.h();
    const double support2 = ctx.kernel.supportSquared();
    const double grad_scale = -10.0 * ctx.kernel.alpha() * inv_h * inv_h;
    // det of sum_j V_j r_ji (x) grad_i W_ij on a full neighbourhood: ~1 (it is the
    // identity for an exact quadrature), so min_det is a fraction of one.
    const double min_det = diffusion_.min_det;
    const std::size_t n = f.size();
    grad_rho_.resize(n);
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) {
      Eigen::Matrix<double, D, D> moment = Eigen::Matrix<double, D, D>::Zero();
      Vec<D> sum = Vec<D>::Zero();
      for (std::uint64_t s = list.begin[i]; s < list.begin[i + 1]; ++s) {
        const std::uint32_t j = list.index[s];
        Vec<D> rij = f.r[i] - f.r[j];
        if constexpr (Periodic) rij = domain.minimumImage(rij);
        const double r2 = rij.squaredNorm();
        if (r2 >= support2) continue;
        const double t = 2.0 - std::sqrt(r2) * inv_h;
        const double F = grad_scale * t * t * t * volume_[j];  // V_j grad_i W_ij = F r_ij
        moment -= F * rij * rij.transpose();                   // r_ji (x) grad_i W_ij V_j
        sum += (f.rho[j] - f.rho[i]) * F * rij;
      }
      grad_rho_[i] = moment.determinant() > min_det ? Vec<D>(moment.inverse() * sum) : diffusion_.hydrostatic;
    }
  }

  std::uint64_t sumPairs(FluidContext<D>& ctx) const {
    FluidParticles<D>& f = ctx.fluid;
    const NeighbourList& list = ctx.neighbours.fluidFluid();
    const Domain<D> domain = ctx.setup.domain;
    const WendlandKernel<D> kernel = ctx.kernel;
    const double inv_h = 1.0 / kernel.h();
    const double support2 = kernel.supportSquared();
    const double grad_scale = -10.0 * kernel.alpha() * inv_h * inv_h;
    const double alpha = kernel.alpha();
    const auto* r = f.r.data();
    const auto* v = f.v.data();
    const double* rho = f.rho.data();
    const double* m = f.m.data();
    const double* p_over_rho2 = p_over_rho2_.data();
    const double* inv_rho = inv_rho_.data();
    const double* volume = volume_.data();
    const std::size_t n = f.size();
    std::uint64_t interactions = 0;

#pragma omp parallel for schedule(static) reduction(+ : interactions)
    for (std::size_t i = 0; i < n; ++i) {
      const Vec<D> ri = r[i];
      const Vec<D> vi = v[i];
      const double rhoi = rho[i];
      const double p_over_rho2_i = p_over_rho2[i];
      const double inv_rhoi = inv_rho[i];
      Vec<D> acc = Vec<D>::Zero();
      Vec<D> xsph_sum = Vec<D>::Zero();
      double xsph_weight = 0.0;
      double drho = 0.0;
      std::uint32_t count = 0;
      for (std::uint64_t s = list.begin[i]; s < list.begin[i + 1]; ++s) {
        const std::uint32_t j = list.index[s];
        Vec<D> rij = ri - r[j];
        if constexpr (Periodic) rij = domain.minimumImage(rij);
        const double r2 = rij.squaredNorm();
        if (r2 >= support2) continue;
        ++count;
        const double dist = std::sqrt(r2);
        const double q = dist * inv_h;
        const double t = 2.0 - q;
        const double t3 = t * t * t;
        const double F = grad_scale * t3;  // grad_i W_ij = F r_ij
        const Vec<D> vij = vi - v[j];
        const double vr = vij.dot(rij);
        const double mj = m[j];
        drho += mj * vr * F;
        double coef = p_over_rho2_i + p_over_rho2[j];
        if constexpr (kViscosity)
          coef -= viscosity_.xi_mu_eff * vr * inv_rhoi * inv_rho[j] / (r2 + viscosity_.beta2);
        acc -= (mj * coef * F) * rij;
        if constexpr (kXsph) {
          const double w = alpha * t3 * t * (1.0 + 2.0 * q) * volume[j];
          xsph_sum += w * v[j];
          xsph_weight += w;
        }
        if constexpr (kDiffusion) {
          double jump = rhoi - rho[j];
          if constexpr (kRenormalised) jump -= 0.5 * (grad_rho_[i] + grad_rho_[j]).dot(rij);
          else jump -= diffusion_.hydrostatic.dot(rij);
          drho += diffusion_.coefficient * jump * F * r2 / (r2 + diffusion_.eta2) * volume[j];
        }
      }
      interactions += count;
      f.dvdt[i] = acc;
      f.drhodt[i] = drho;
      if constexpr (kXsph) {
        if (xsph_.form == XsphForm::Reference) {
          const double self = kernel.valueAtZero() * volume[i];  // the sum includes j = i
          f.drdt[i] = (1.0 - xsph_.eps) * vi + xsph_.eps * (xsph_sum + self * vi);
        } else {
          f.drdt[i] = vi + xsph_.eps * (xsph_sum - xsph_weight * vi);
        }
      } else {
        (void)xsph_weight;
        f.drdt[i] = vi;
      }
    }
    return interactions;
  }

  Viscosity viscosity_;
  Xsph xsph_;
  Diffusion diffusion_;
  std::uint64_t interactions_ = 0;
  std::vector<double> p_over_rho2_, inv_rho_, volume_;
  std::vector<Vec<D>> grad_rho_;  ///< renormalised density gradients (kRenormalised only)
};

// Compile-time composition: pick each term's type from the scene's list, one branch
// per term, resolved once here.
template <int D, bool Periodic, class V, class X>
std::unique_ptr<PairForces<D>> withDiffusion(const FluidSetup<D>& s, V v, X x) {
  if (s.has("density_diffusion") && s.method.density_diffusion_form == DensityDiffusionForm::Renormalised)
    return std::make_unique<PairForcesImpl<D, Periodic, V, X, RenormalisedDensityDiffusionTerm<D>>>(
        v, x, RenormalisedDensityDiffusionTerm<D>(s));
  if (s.has("density_diffusion"))
    return std::make_unique<PairForcesImpl<D, Periodic, V, X, DensityDiffusionTerm<D>>>(v, x, DensityDiffusionTerm<D>(s));
  return std::make_unique<PairForcesImpl<D, Periodic, V, X, NoTerm>>(v, x, NoTerm{});
}

template <int D, bool Periodic, class V>
std::unique_ptr<PairForces<D>> withXsph(const FluidSetup<D>& s, V v) {
  if (s.has("xsph")) return withDiffusion<D, Periodic>(s, v, XsphTerm(s));
  return withDiffusion<D, Periodic>(s, v, NoTerm{});
}

template <int D, bool Periodic>
std::unique_ptr<PairForces<D>> withViscosity(const FluidSetup<D>& s) {
  if (s.has("viscosity")) return withXsph<D, Periodic>(s, ViscosityTerm(s));
  return withXsph<D, Periodic>(s, NoTerm{});
}

}  // namespace

template <int D>
std::unique_ptr<PairForces<D>> makePairForces(const FluidSetup<D>& setup) {
  if (!setup.has("pressure"))
    throw std::invalid_argument("effects: 'pressure' is required (the fluid's pressure and continuity terms)");
  if (setup.domain.anyPeriodic()) return withViscosity<D, true>(setup);
  return withViscosity<D, false>(setup);
}

template std::unique_ptr<PairForces<2>> makePairForces<2>(const FluidSetup<2>&);
template std::unique_ptr<PairForces<3>> makePairForces<3>(const FluidSetup<3>&);

}  // namespace moorsph::fluid
