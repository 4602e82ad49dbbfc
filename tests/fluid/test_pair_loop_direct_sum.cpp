// The pair loop (fluid/src/pair_forces.cpp) against a direct O(n^2) sum of METHOD.md
// section 1's equations, written out here from the formulas and not from the loop:
//   drho_i/dt = sum_j m_j (v_i - v_j) . grad_i W_ij
//             + 2 delta h c_s sum_j psi_ij (r_ij . grad_i W_ij) / (r_ij^2 + eta^2) V_j
//   dv_i/dt   = - sum_j m_j (P_i/rho_i^2 + P_j/rho_j^2 + Pi_ij) grad_i W_ij,
//               Pi_ij = -xi 2 mu (v_ij . r_ij) / (rho_i rho_j (r_ij^2 + beta^2))
//   dr_i/dt   = XSPH, METHOD.md's form or Monaghan's.
// The loop takes each pair once in 2D and sums every row in vector lanes in 3D or a
// periodic domain; both must give these sums. A jittered block with random velocities
// and densities (no symmetry hides an error), every term on, bounded and periodic.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <Eigen/LU>
#include <moorsph/fluid/box_geometry.hpp>
#include <moorsph/fluid/fluid_simulation.hpp>
#include <moorsph/fluid/pair_forces.hpp>

using namespace moorsph::fluid;

namespace {

constexpr double kDx = 0.01, kRho0 = 1000.0, kSound = 20.0;

template <int D>
struct Rates {
  std::vector<Vec<D>> dvdt, drdt;
  std::vector<double> drhodt;
};

template <int D>
struct Block {
  FluidSetup<D> setup;
  FluidParticles<D> fluid;

  Block(bool periodic, XsphForm xsph, DensityDiffusionForm diffusion) {
    setup.dx = kDx;
    setup.sound_speed = kSound;
    setup.mu = 5e-2;  // large, so the viscous term is well above round-off
    setup.effects = {"pressure", "viscosity", "xsph", "density_diffusion"};
    setup.method.xsph_form = xsph;
    setup.method.density_diffusion_form = diffusion;
    const double side = 0.1;  // periodic: at least 3 cells of the list radius
    if (periodic) {
      setup.domain.lower = Vec<D>::Zero();
      setup.domain.upper = Vec<D>::Constant(side);
      setup.domain.periodic.fill(true);
    } else {
      setup.domain.lower = Vec<D>::Constant(-0.05);
      setup.domain.upper = Vec<D>::Constant(side + 0.05);
    }
    fillBox<D>(fluid, Vec<D>::Zero(), Vec<D>::Constant(side), kDx, TaitEos(kRho0, kSound), 0.0, 0.0);
    std::mt19937 gen(11);
    std::uniform_real_distribution<double> jitter(-0.15 * kDx, 0.15 * kDx);
    std::normal_distribution<double> noise(0.0, 1.0);
    for (std::size_t i = 0; i < fluid.size(); ++i) {
      for (int a = 0; a < D; ++a) {
        fluid.r[i][a] += jitter(gen);
        fluid.v[i][a] = 0.5 * noise(gen);
      }
      if (periodic) fluid.r[i] = setup.domain.wrap(fluid.r[i]);
      fluid.rho[i] = kRho0 * (1.0 + 0.003 * noise(gen));
    }
    fluid.allocateWorkArrays();
  }

  Rates<D> loopRates() {
    NeighbourSearch<D> search(setup.domain, 2.0 * setup.h(), 0.3 * setup.h());
    search.rebuild(fluid, nullptr, {});  // sorts the particles by cell
    WendlandKernel<D> kernel(setup.h());
    TaitEos eos(kRho0, kSound);
    FluidContext<D> ctx{fluid, search, kernel, eos, setup, 0.0};
    makePairForces<D>(setup)->evaluate(ctx);
    return {fluid.dvdt, fluid.drdt, fluid.drhodt};
  }

  /// The renormalised density gradient G_i (Antuono et al. 2010, eq. 10), directly.
  std::vector<Vec<D>> densityGradients(const WendlandKernel<D>& kernel) const {
    const std::size_t n = fluid.size();
    std::vector<Vec<D>> G(n);
    const Vec<D> hydrostatic = setup.rho0 * setup.gravity / (kSound * kSound);
    for (std::size_t i = 0; i < n; ++i) {
      Eigen::Matrix<double, D, D> L = Eigen::Matrix<double, D, D>::Zero();
      Vec<D> sum = Vec<D>::Zero();
      for (std::size_t j = 0; j < n; ++j) {
        if (j == i) continue;
        const Vec<D> r = setup.domain.minimumImage(fluid.r[i] - fluid.r[j]);
        const Vec<D> grad = kernel.gradientFactor(r.norm()) * r;
        const double V = fluid.m[j] / fluid.rho[j];
        L += V * (-r) * grad.transpose();
        sum += (fluid.rho[j] - fluid.rho[i]) * V * grad;
      }
      G[i] = L.determinant() > 0.1 ? Vec<D>(L.inverse() * sum) : hydrostatic;
    }
    return G;
  }

  Rates<D> directRates() const {
    const std::size_t n = fluid.size();
    const WendlandKernel<D> kernel(setup.h());
    const TaitEos eos(kRho0, kSound);
    const double xi_mu = setup.method.viscosity_xi * 2.0 * setup.mu;
    const double beta2 = std::pow(setup.method.viscosity_beta_factor * kDx, 2);
    const double eta2 = 0.01 * setup.h() * setup.h();
    const double delta_coefficient = 2.0 * setup.method.density_diffusion_delta * setup.h() * kSound;
    const double eps = setup.method.xsph_eps;
    const auto form = setup.method.density_diffusion_form;
    const Vec<D> hydrostatic = form == DensityDiffusionForm::Fourtakas
                                   ? Vec<D>(setup.rho0 * setup.gravity / (kSound * kSound))
                                   : Vec<D>(Vec<D>::Zero());
    const std::vector<Vec<D>> G =
        form == DensityDiffusionForm::Renormalised ? densityGradients(kernel) : std::vector<Vec<D>>(n, Vec<D>::Zero());
    Rates<D> out{std::vector<Vec<D>>(n), std::vector<Vec<D>>(n), std::vector<double>(n)};
    for (std::size_t i = 0; i < n; ++i) {
      const double Pi_rho2 = eos.pressure(fluid.rho[i]) / (fluid.rho[i] * fluid.rho[i]);
      Vec<D> acc = Vec<D>::Zero(), smoothed = Vec<D>::Zero();
      double drho = 0.0;
      for (std::size_t j = 0; j < n; ++j) {
        if (j == i) continue;
        const Vec<D> r = setup.domain.minimumImage(fluid.r[i] - fluid.r[j]);
        const double dist = r.norm();
        const Vec<D> grad = kernel.gradientFactor(dist) * r;
        const Vec<D> vij = fluid.v[i] - fluid.v[j];
        const double Vj = fluid.m[j] / fluid.rho[j];
        const double Pj_rho2 = eos.pressure(fluid.rho[j]) / (fluid.rho[j] * fluid.rho[j]);
        const double viscous = -xi_mu * vij.dot(r) / (fluid.rho[i] * fluid.rho[j] * (r.squaredNorm() + beta2));
        acc -= fluid.m[j] * (Pi_rho2 + Pj_rho2 + viscous) * grad;
        double psi = fluid.rho[i] - fluid.rho[j] - hydrostatic.dot(r);
        if (form == DensityDiffusionForm::Renormalised) psi = fluid.rho[i] - fluid.rho[j] - 0.5 * (G[i] + G[j]).dot(r);
        drho += fluid.m[j] * vij.dot(grad) + delta_coefficient * psi * r.dot(grad) / (r.squaredNorm() + eta2) * Vj;
        const double W = kernel.value(dist);
        smoothed += setup.method.xsph_form == XsphForm::Reference ? Vec<D>(Vj * W * fluid.v[j])
                                                                  : Vec<D>(Vj * W * (fluid.v[j] - fluid.v[i]));
      }
      const double self = kernel.valueAtZero() * fluid.m[i] / fluid.rho[i];
      out.dvdt[i] = acc;
      out.drhodt[i] = drho;
      out.drdt[i] = setup.method.xsph_form == XsphForm::Reference
                        ? Vec<D>((1.0 - eps) * fluid.v[i] + eps * (smoothed + self * fluid.v[i]))
                        : Vec<D>(fluid.v[i] + eps * smoothed);
    }
    return out;
  }
};

template <int D>
double largestNorm(const std::vector<Vec<D>>& a) {
  double m = 0.0;
  for (const auto& x : a) m = std::max(m, x.norm());
  return m;
}

template <int D>
void expectLoopEqualsDirectSum(bool periodic, XsphForm xsph, DensityDiffusionForm diffusion) {
  Block<D> block(periodic, xsph, diffusion);
  const Rates<D> loop = block.loopRates();
  const Rates<D> direct = block.directRates();  // of the sorted particles the loop left
  const std::size_t n = block.fluid.size();
  ASSERT_GT(n, 40u);
  const double acc_scale = largestNorm<D>(direct.dvdt), vel_scale = largestNorm<D>(direct.drdt);
  double rho_scale = 0.0;
  for (double x : direct.drhodt) rho_scale = std::max(rho_scale, std::abs(x));
  ASSERT_GT(acc_scale, 1.0);
  ASSERT_GT(rho_scale, 1.0);
  for (std::size_t i = 0; i < n; ++i) {
    ASSERT_LT((loop.dvdt[i] - direct.dvdt[i]).norm(), 1e-11 * acc_scale) << "dv/dt of particle " << i;
    ASSERT_LT(std::abs(loop.drhodt[i] - direct.drhodt[i]), 1e-11 * rho_scale) << "drho/dt of particle " << i;
    ASSERT_LT((loop.drdt[i] - direct.drdt[i]).norm(), 1e-11 * vel_scale) << "dr/dt of particle " << i;
  }
}

}  // namespace

// 2D bounded: each pair once for both particles.
TEST(PairLoop, Bounded2DEqualsDirectSum) {
  expectLoopEqualsDirectSum<2>(false, XsphForm::Monaghan, DensityDiffusionForm::Fourtakas);
}
// 2D periodic and 3D: rows in vector lanes.
TEST(PairLoop, Periodic2DEqualsDirectSum) {
  expectLoopEqualsDirectSum<2>(true, XsphForm::Reference, DensityDiffusionForm::MolteniColagrossi);
}
TEST(PairLoop, Bounded3DEqualsDirectSum) {
  expectLoopEqualsDirectSum<3>(false, XsphForm::Monaghan, DensityDiffusionForm::Fourtakas);
}
TEST(PairLoop, Periodic3DEqualsDirectSum) {
  expectLoopEqualsDirectSum<3>(true, XsphForm::Reference, DensityDiffusionForm::Fourtakas);
}
TEST(PairLoop, Renormalised3DEqualsDirectSum) {
  expectLoopEqualsDirectSum<3>(false, XsphForm::Monaghan, DensityDiffusionForm::Renormalised);
}
TEST(PairLoop, Renormalised2DEqualsDirectSum) {
  expectLoopEqualsDirectSum<2>(false, XsphForm::Reference, DensityDiffusionForm::Renormalised);
}
