// Density diffusion forms (pair_terms.hpp), one evaluation of the pair loop on a fluid at
// rest, so drho/dt is the diffusion term alone (the continuity term needs motion).
// The renormalised (delta-SPH, Antuono et al. 2010) form gives no flux for a linear
// density field anywhere, the free surface included, while Fourtakas' form (which
// removes only the hydrostatic gradient) leaks at the surface; both still damp a
// particle-scale density ripple.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <moorsph/fluid/box_geometry.hpp>
#include <moorsph/fluid/fluid_simulation.hpp>
#include <moorsph/fluid/pair_forces.hpp>

using namespace moorsph::fluid;

namespace {

constexpr double kDx = 0.01, kRho0 = 1000.0, kSound = 20.0;

/// A block [0, 0.2] x [0, 0.1], free on all sides, its particles
/// jittered by up to 0.1 dx (so no lattice symmetry hides an error), at rest.
struct DiffusionProbe {
  FluidSetup<2> setup;
  FluidParticles<2> fluid;

  explicit DiffusionProbe(DensityDiffusionForm form) {
    setup.dx = kDx;
    setup.sound_speed = kSound;
    setup.effects = {"pressure", "density_diffusion"};
    setup.method.density_diffusion_form = form;
    setup.domain.lower = Vec<2>(-0.1, -0.1);
    setup.domain.upper = Vec<2>(0.3, 0.2);
    fillBox<2>(fluid, Vec<2>(0.0, 0.0), Vec<2>(0.2, 0.1), kDx, TaitEos(kRho0, kSound, 7.0), 0.0, 0.0);
    std::mt19937 gen(7);
    std::uniform_real_distribution<double> jitter(-0.1 * kDx, 0.1 * kDx);
    for (auto& r : fluid.r) r += Vec<2>(jitter(gen), jitter(gen));
  }

  /// drho/dt of every particle for the density field `rho(r)`.
  template <class Field>
  std::vector<double> rates(Field rho) {
    for (std::size_t i = 0; i < fluid.size(); ++i) fluid.rho[i] = rho(fluid.r[i]);
    fluid.allocateWorkArrays();
    NeighbourSearch<2> search(setup.domain, 2.0 * setup.h(), 0.3 * setup.h());
    search.rebuild(fluid, nullptr, {});
    WendlandKernel<2> kernel(setup.h());
    TaitEos eos(kRho0, kSound, 7.0);
    FluidContext<2> ctx{fluid, search, kernel, eos, setup, 0.0};
    makePairForces<2>(setup)->evaluate(ctx);
    return {fluid.drhodt.begin(), fluid.drhodt.end()};
  }
  bool nearSurface(std::size_t i) const {
    const Vec<2>& r = fluid.r[i];
    const double band = 2.0 * setup.h();
    return r[0] < band || r[0] > 0.2 - band || r[1] < band || r[1] > 0.1 - band;
  }
};

/// A linear field that is not hydrostatic: gradient (30, -50) kg/m^4 (gravity is -y).
double linearField(const Vec<2>& r) { return kRho0 + 30.0 * r[0] - 50.0 * r[1]; }

double largestRate(const std::vector<double>& rates, const DiffusionProbe& p, bool surface) {
  double largest = 0.0;
  for (std::size_t i = 0; i < rates.size(); ++i)
    if (p.nearSurface(i) == surface) largest = std::max(largest, std::abs(rates[i]));
  return largest;
}

}  // namespace

TEST(DensityDiffusion, RenormalisedFormGivesNoFluxForALinearField) {
  DiffusionProbe p(DensityDiffusionForm::Renormalised);
  const auto rates = p.rates(linearField);
  // Scale of a one-sided flux: 2 delta h c_s |G| / h = 2 delta c_s |G| = 233 kg/m^3/s.
  const double scale = 2.0 * p.setup.method.density_diffusion_delta * kSound * std::hypot(30.0, 50.0);
  EXPECT_LT(largestRate(rates, p, true), 1e-9 * scale);
  EXPECT_LT(largestRate(rates, p, false), 1e-9 * scale);
}

TEST(DensityDiffusion, FourtakasFormLeaksALinearFieldAtTheSurface) {
  DiffusionProbe p(DensityDiffusionForm::Fourtakas);
  const auto rates = p.rates(linearField);
  const double scale = 2.0 * p.setup.method.density_diffusion_delta * kSound * std::hypot(30.0, 50.0);
  EXPECT_GT(largestRate(rates, p, true), 0.1 * scale);  // the loss the renormalised form removes
}

TEST(DensityDiffusion, BothFormsDampAParticleScaleRipple) {
  for (auto form : {DensityDiffusionForm::Fourtakas, DensityDiffusionForm::Renormalised}) {
    DiffusionProbe p(form);
    const double k = 2.0 * std::acos(-1.0) / (4.0 * kDx);  // a ripple 4 spacings long, along x
    const auto rates = p.rates([&](const Vec<2>& r) { return kRho0 + 0.5 * std::cos(k * r[0]); });
    // Interior particles: drho/dt opposes the ripple (a diffusion: rate ~ -D k^2 ripple).
    double work = 0.0, norm = 0.0;
    for (std::size_t i = 0; i < rates.size(); ++i) {
      if (p.nearSurface(i)) continue;
      const double ripple = 0.5 * std::cos(k * p.fluid.r[i][0]);
      work += rates[i] * ripple;
      norm += ripple * ripple;
    }
    const double D = 2.0 * p.setup.method.density_diffusion_delta * p.setup.h() * kSound;
    // Decay rate of the ripple: between 0.1 and 2 times D k^2 (the discrete operator
    // is not the continuous Laplacian at 4 spacings per wavelength).
    EXPECT_GT(-work / norm, 0.1 * D * k * k) << static_cast<int>(form);
    EXPECT_LT(-work / norm, 2.0 * D * k * k) << static_cast<int>(form);
  }
}
