#include <moorsph/fluid/pair_forces.hpp>

#include <omp.h>

#include <cmath>
#include <stdexcept>
#include <type_traits>
#include <vector>
#include <Eigen/LU>
#include <moorsph/fluid/pair_terms.hpp>

namespace moorsph::fluid {
namespace {

template <int D, bool Periodic, class Viscosity, class Xsph, class Diffusion, class Mirror>
class PairForcesImpl final : public PairForces<D> {
  static constexpr bool kViscosity = !std::is_same_v<Viscosity, NoTerm>;
  static constexpr bool kXsph = !std::is_same_v<Xsph, NoTerm>;
  static constexpr bool kDiffusion = !std::is_same_v<Diffusion, NoTerm>;
  static constexpr bool kRenormalised = std::is_same_v<Diffusion, RenormalisedDensityDiffusionTerm<D>>;
  static constexpr bool kMirror = !std::is_same_v<Mirror, NoTerm>;

  /// What the pair terms need of a neighbour j: a particle or its mirror image.
  struct Neighbour {
    Vec<D> rij;  ///< r_i - r_j (minimum image)
    Vec<D> v;
    double rho, m, p_over_rho2, inv_rho, volume;
    Vec<D> grad_rho;  ///< kRenormalised only
  };
  /// What the pair terms need of the owner i of the sums.
  struct Owner {
    Vec<D> v;
    double rho, p_over_rho2, inv_rho;
    Vec<D> grad_rho;  ///< kRenormalised only
    double m = 0.0, volume = 0.0;  ///< the symmetric loop only: i's share given to j
  };
  /// The kernel's constants for the pair loops: grad_i W_ij = grad_scale (2 - q)^3 r_ij.
  struct KernelConstants {
    double inv_h, support2, grad_scale, alpha;
    explicit KernelConstants(const WendlandKernel<D>& k)
        : inv_h(1.0 / k.h()),
          support2(k.supportSquared()),
          grad_scale(-10.0 * k.alpha() * inv_h * inv_h),
          alpha(k.alpha()) {}
  };
  /// What the vector row loops read: plain pointers into the Vec<D> arrays (stride D;
  /// a gather serves a strided array as well as a column) and the periodic shift as
  /// scalars (the vectoriser leaves a loop with local arrays or Eigen packets in it).
  struct Lanes {
    static_assert(sizeof(Vec<D>) == D * sizeof(double), "Vec<D> arrays must be plain doubles");
    static constexpr int Z = D - 1;  ///< the third axis in 3D; in 2D its terms are skipped
    const double *r, *v, *g;
    double L0, L1, L2, iL0, iL1, iL2;
    Lanes(const FluidParticles<D>& f, const Domain<D>& domain, const std::vector<Vec<D>>& grad_rho)
        : r(f.r.data()->data()), v(f.v.data()->data()), g(grad_rho.empty() ? nullptr : grad_rho.data()->data()) {
      const MinimumImage<D> image(domain);
      L0 = image.period[0], L1 = image.period[1], L2 = image.period[Z];
      iL0 = image.inv_period[0], iL1 = image.inv_period[1], iL2 = image.inv_period[Z];
    }
    /// Component of the minimum image r_i - r_j, given the two coordinates.
    static double separation(double xi, double xj, double L, double inv_L) {
      const double d = xi - xj;
      return d - L * std::nearbyint(d * inv_L);
    }
    /// r_i - r_j (minimum image) of an owner at (xi0, xi1, xi2) and neighbour j; rz = 0 in 2D.
    void separation(double xi0, double xi1, double xi2, std::size_t j, double& rx, double& ry, double& rz) const {
      rx = separation(xi0, r[D * j], L0, iL0);
      ry = separation(xi1, r[D * j + 1], L1, iL1);
      rz = D == 3 ? separation(xi2, r[D * j + Z], L2, iL2) : 0.0;
    }
  };

  /// The sums of particle i's rates.
  struct Sums {
    Vec<D> acc = Vec<D>::Zero();
    Vec<D> xsph = Vec<D>::Zero();
    double xsph_weight = 0.0;
    double drho = 0.0;
  };

 public:
  PairForcesImpl(Viscosity viscosity, Xsph xsph, Diffusion diffusion, Mirror mirror)
      : viscosity_(viscosity), xsph_(xsph), diffusion_(diffusion), mirror_(mirror) {}

  std::uint64_t lastInteractions() const override { return interactions_; }

  void continuityRate(FluidContext<D>& ctx, std::vector<double>& out) const override {
    const FluidParticles<D>& f = ctx.fluid;
    const NeighbourList& list = ctx.neighbours.fluidFluid();
    const KernelConstants k(ctx.kernel);
    const Lanes lanes(f, ctx.setup.domain, {});
    constexpr int Z = Lanes::Z, S = D;  // S: the stride of the Vec<D> arrays
    const double *v = lanes.v, *m = f.m.data();
    const std::uint32_t* index = list.index.data();
    const std::size_t n = f.size();
    out.resize(n);
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) {
      const double xi0 = f.r[i][0], xi1 = f.r[i][1], xi2 = f.r[i][Z];
      const double vi0 = f.v[i][0], vi1 = f.v[i][1], vi2 = f.v[i][Z];
      double sum = 0.0;
      const std::uint64_t first = list.begin[i], last = list.begin[i + 1];
#pragma omp simd reduction(+ : sum)
      for (std::uint64_t s = first; s < last; ++s) {
        const std::size_t j = index[s];
        double rx, ry, rz;
        lanes.separation(xi0, xi1, xi2, j, rx, ry, rz);
        const double r2 = rx * rx + ry * ry + rz * rz;
        const double vz = D == 3 ? v[S * j + Z] : 0.0;
        const double vr = (vi0 - v[S * j]) * rx + (vi1 - v[S * j + 1]) * ry + (vi2 - vz) * rz;
        const double t = 2.0 - std::sqrt(r2) * k.inv_h;
        sum += r2 < k.support2 ? m[j] * vr * k.grad_scale * t * t * t : 0.0;
      }
      const Vec<D> vi = f.v[i];
      forEachImage(ctx, list, i, [&](const Neighbour& nb) {
        const double r2 = nb.rij.squaredNorm();
        if (r2 >= k.support2) return;
        const double t = 2.0 - std::sqrt(r2) * k.inv_h;
        sum += nb.m * (vi - nb.v).dot(nb.rij) * k.grad_scale * t * t * t;
      });
      out[i] = sum;
    }
  }

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
    if constexpr (kMirror) imageStates(ctx);
    if constexpr (kRenormalised) densityGradients(ctx);
    // Every row is summed in vector lanes (sumRows), with mirror planes (whose images
    // are seen from their owner only, so every particle sums its own row), in 3D and in
    // a periodic domain. A bounded 2D row without mirrors is too short for the lanes
    // to pay, and there each pair is evaluated once for both particles
    // (docs/performance.md, session 42).
    if constexpr (kMirror || D == 3 || Periodic)
      interactions_ = sumRows(ctx);
    else
      interactions_ = sumPairsOnce(ctx);
  }

 private:
  /// Density, pressure quotient and volume of each particle's image across the
  /// horizontal mirror plane near it (MirrorTerm): the pressure continued hydrostatically.
  /// Images across vertical planes only keep the particle's own.
  void imageStates(FluidContext<D>& ctx) {
    const FluidParticles<D>& f = ctx.fluid;
    const TaitEos eos = ctx.eos;
    const std::size_t n = f.size();
    image_rho_.resize(n);
    image_p_over_rho2_.resize(n);
    image_inv_rho_.resize(n);
    image_volume_.resize(n);
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) {
      double plane, distance;
      int inside;
      if (!mirror_.near(1, f.r[i][1], plane, inside, distance)) continue;  // out of everyone's reach
      const double p = f.p[i] + mirror_.rho0_gy * 2.0 * (plane - f.r[i][1]);  // rho0 g . (r' - r)
      image_rho_[i] = eos.density(p);
      image_inv_rho_[i] = 1.0 / image_rho_[i];
      image_p_over_rho2_[i] = p * image_inv_rho_[i] * image_inv_rho_[i];
      image_volume_[i] = f.m[i] * image_inv_rho_[i];
    }
  }

  /// Particle j seen from i; rij is r_i - r_j (minimum image).
  Neighbour particle(const FluidParticles<D>& f, std::uint32_t j, const Vec<D>& rij) const {
    Neighbour nb{rij, f.v[j], f.rho[j], f.m[j], p_over_rho2_[j], inv_rho_[j], volume_[j], Vec<D>::Zero()};
    if constexpr (kRenormalised) nb.grad_rho = grad_rho_[j];
    return nb;
  }

  /// The mirror planes near an owner particle i: a bit per axis with a plane within
  /// reach, that plane's position and side, and i's distance from it.
  struct NearPlanes {
    unsigned mask = 0;
    Vec<D> position, distance;
    int inside[D];
  };
  NearPlanes nearPlanes(const Vec<D>& r) const {
    NearPlanes near;
    for (int a = 0; a < D; ++a)
      if (mirror_.near(a, r[a], near.position[a], near.inside[a], near.distance[a])) near.mask |= 1u << a;
    return near;
  }

  /// The image of particle j across the planes of `axes` (bits of near.mask) seen from
  /// i; rij is r_i - r_j. Along a mirrored axis r_i - r_j' = (x_i - p) + (x_j - p).
  Neighbour image(const FluidParticles<D>& f, std::uint32_t j, const Vec<D>& rij, const NearPlanes& near,
                  unsigned axes) const {
    Neighbour nb = particle(f, j, rij);
    for (int a = 0; a < D; ++a) {
      if (!(axes & (1u << a))) continue;
      nb.rij[a] = rij[a] + 2.0 * (f.r[j][a] - near.position[a]);
      nb.v[a] = -nb.v[a];
      if constexpr (kRenormalised) nb.grad_rho[a] = -nb.grad_rho[a];
    }
    if (axes & 2u) {  // moved vertically: the hydrostatic image state
      nb.rho = image_rho_[j];
      nb.p_over_rho2 = image_p_over_rho2_[j];
      nb.inv_rho = image_inv_rho_[j];
      nb.volume = image_volume_[j];
      if constexpr (kRenormalised) nb.grad_rho[1] += mirror_.ghost_gradient;
    }
    return nb;
  }

  /// Visits j's images that can be within reach of i: across every non-empty set of
  /// the planes near i for which i and j together lie within 2h of each plane.
  template <class Visit>
  void visitImages(const FluidParticles<D>& f, std::uint32_t j, const Vec<D>& rij, const NearPlanes& near,
                   Visit& visit) const {
    unsigned reachable = 0;
    for (int a = 0; a < D; ++a)
      if ((near.mask & (1u << a)) && near.distance[a] + near.inside[a] * (f.r[j][a] - near.position[a]) < mirror_.reach)
        reachable |= 1u << a;
    for (unsigned axes = reachable; axes != 0; axes = (axes - 1) & reachable) visit(image(f, j, rij, near, axes));
  }

  /// G_i of RenormalisedDensityDiffusionTerm: the renormalised density gradient, each
  /// row in vector lanes as in sumRow, then the mirror images.
  void densityGradients(FluidContext<D>& ctx) {
    const FluidParticles<D>& f = ctx.fluid;
    const NeighbourList& list = ctx.neighbours.fluidFluid();
    const KernelConstants k(ctx.kernel);
    const Lanes lanes(f, ctx.setup.domain, {});
    constexpr int Z = Lanes::Z;
    const double *rho = f.rho.data(), *volume = volume_.data();
    const std::uint32_t* index = list.index.data();
    // det of sum_j V_j r_ji (x) grad_i W_ij on a full neighbourhood: ~1 (it is the
    // identity for an exact quadrature), so min_det is a fraction of one.
    const double min_det = diffusion_.min_det;
    const std::size_t n = f.size();
    grad_rho_.resize(n);
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) {
      const double xi0 = f.r[i][0], xi1 = f.r[i][1], xi2 = f.r[i][Z], rho_i = f.rho[i];
      // The moment sum_j V_j r_ji (x) grad_i W_ij = -sum_j F r_ij r_ij^T is symmetric.
      double m00 = 0, m01 = 0, m11 = 0, m02 = 0, m12 = 0, m22 = 0, s0 = 0, s1 = 0, s2 = 0;
      const std::uint64_t first = list.begin[i], last = list.begin[i + 1];
#pragma omp simd reduction(+ : m00, m01, m11, m02, m12, m22, s0, s1, s2)
      for (std::uint64_t s = first; s < last; ++s) {
        const std::size_t j = index[s];
        double rx, ry, rz;
        lanes.separation(xi0, xi1, xi2, j, rx, ry, rz);
        const double r2 = rx * rx + ry * ry + rz * rz;
        const double t = 2.0 - std::sqrt(r2) * k.inv_h;
        const double F = r2 < k.support2 ? k.grad_scale * t * t * t * volume[j] : 0.0;  // V_j grad_i W_ij = F r_ij
        m00 -= F * rx * rx;
        m01 -= F * rx * ry;
        m11 -= F * ry * ry;
        const double jump = (rho[j] - rho_i) * F;
        s0 += jump * rx;
        s1 += jump * ry;
        if constexpr (D == 3) {
          m02 -= F * rx * rz;
          m12 -= F * ry * rz;
          m22 -= F * rz * rz;
          s2 += jump * rz;
        }
      }
      Eigen::Matrix<double, D, D> moment;
      Vec<D> sum;
      if constexpr (D == 3) {
        moment << m00, m01, m02, m01, m11, m12, m02, m12, m22;
        sum << s0, s1, s2;
      } else {
        moment << m00, m01, m01, m11;
        sum << s0, s1;
      }
      forEachImage(ctx, list, i, [&](const Neighbour& nb) {
        const double r2 = nb.rij.squaredNorm();
        if (r2 >= k.support2) return;
        const double t = 2.0 - std::sqrt(r2) * k.inv_h;
        const double F = k.grad_scale * t * t * t * nb.volume;
        moment -= F * nb.rij * nb.rij.transpose();
        sum += (nb.rho - rho_i) * F * nb.rij;
      });
      grad_rho_[i] = moment.determinant() > min_det ? Vec<D>(moment.inverse() * sum) : diffusion_.hydrostatic;
    }
  }

  /// Adds the pair (i, nb) to i's sums and, with kBoth, to j's (*sj): each term is
  /// symmetric or antisymmetric in i and j (grad_j W_ji = -grad_i W_ij, the jumps change
  /// sign), so j's share is i's with the masses and volumes swapped. False if nb is out
  /// of reach.
  template <bool kBoth>
  bool addPair(Sums& si, Sums* sj, const Owner& i, const Neighbour& nb, const KernelConstants& k) const {
    const Vec<D>& rij = nb.rij;
    const double r2 = rij.squaredNorm();
    if (r2 >= k.support2) return false;
    const double q = std::sqrt(r2) * k.inv_h;
    const double t = 2.0 - q;
    const double t3 = t * t * t;
    const double F = k.grad_scale * t3;  // grad_i W_ij = F r_ij = -grad_j W_ji
    const Vec<D> vij = i.v - nb.v;
    const double vr = vij.dot(rij);  // the same seen from j
    si.drho += nb.m * vr * F;
    double coef = i.p_over_rho2 + nb.p_over_rho2;
    if constexpr (kViscosity) coef -= viscosity_.xi_mu_eff * vr * i.inv_rho * nb.inv_rho / (r2 + viscosity_.beta2);
    const Vec<D> push = (coef * F) * rij;
    si.acc -= nb.m * push;
    if constexpr (kBoth) {
      sj->drho += i.m * vr * F;
      sj->acc += i.m * push;
    }
    if constexpr (kXsph) {
      const double w = k.alpha * t3 * t * (1.0 + 2.0 * q);  // W_ij
      si.xsph += (w * nb.volume) * nb.v;
      si.xsph_weight += w * nb.volume;
      if constexpr (kBoth) {
        sj->xsph += (w * i.volume) * i.v;
        sj->xsph_weight += w * i.volume;
      }
    }
    if constexpr (kDiffusion) {
      double jump = i.rho - nb.rho;  // j sees -jump
      if constexpr (kRenormalised) jump -= 0.5 * (i.grad_rho + nb.grad_rho).dot(rij);
      else jump -= diffusion_.hydrostatic.dot(rij);
      const double flux = diffusion_.coefficient * jump * F * r2 / (r2 + diffusion_.eta2);
      si.drho += flux * nb.volume;
      if constexpr (kBoth) sj->drho -= flux * i.volume;
    }
    return true;
  }

  /// Each listed pair once (j > i), added to both particles. Every thread accumulates in
  /// its own array of sums (a pair's j may be another thread's owner); the arrays are
  /// added up per particle afterwards. Half the kernel and term evaluations of sumRows.
  std::uint64_t sumPairsOnce(FluidContext<D>& ctx) {
    FluidParticles<D>& f = ctx.fluid;
    const NeighbourList& list = ctx.neighbours.fluidFluid();
    const Domain<D> domain = ctx.setup.domain;
    const WendlandKernel<D> kernel = ctx.kernel;
    const KernelConstants k(kernel);
    const std::size_t n = f.size();
    const int threads = omp_get_max_threads();
    if (static_cast<int>(thread_sums_.size()) < threads) thread_sums_.resize(threads);
    std::uint64_t interactions = 0;
#pragma omp parallel
    {
      std::vector<Sums>& sums = thread_sums_[omp_get_thread_num()];
      sums.assign(n, Sums{});
#pragma omp for schedule(static) reduction(+ : interactions)
      for (std::size_t i = 0; i < n; ++i) {
        Owner owner{f.v[i], f.rho[i], p_over_rho2_[i], inv_rho_[i],
                    kRenormalised ? grad_rho_[i] : Vec<D>(Vec<D>::Zero()), f.m[i], volume_[i]};
        Sums own;  // i's sums in registers: sums[i] might alias sums[j] as far as the compiler knows
        for (std::uint64_t s = list.begin[i]; s < list.begin[i + 1]; ++s) {
          const std::uint32_t j = list.index[s];
          if (j <= i) continue;  // (j, i) is summed from j's list
          Vec<D> rij = f.r[i] - f.r[j];
          if constexpr (Periodic) rij = domain.minimumImage(rij);
          if (addPair<true>(own, &sums[j], owner, particle(f, j, rij), k)) interactions += 2;
        }
        add(sums[i], own);
      }
#pragma omp for schedule(static)
      for (std::size_t i = 0; i < n; ++i) {
        Sums total = thread_sums_[0][i];
        for (int t = 1; t < omp_get_num_threads(); ++t) add(total, thread_sums_[t][i]);
        storeRates(f, kernel, i, total);
      }
    }
    return interactions;
  }

  /// Each owner's row of its list summed on its own, every pair seen from both sides,
  /// the row's candidates taken several at a time (#pragma omp simd: gathers from the
  /// Vec<D> arrays through Lanes, the lanes out of reach masked by zeroing F and W). Twice the pair
  /// evaluations of sumPairsOnce, but no scatter into j's sums, no per-thread arrays,
  /// no j > i test and no division for the periodic image: in 3D the vector lanes more
  /// than pay for it (docs/performance.md, session 42).
  std::uint64_t sumRows(FluidContext<D>& ctx) {
    FluidParticles<D>& f = ctx.fluid;
    const NeighbourList& list = ctx.neighbours.fluidFluid();
    const WendlandKernel<D> kernel = ctx.kernel;
    const KernelConstants kernel_constants(kernel);
    const Lanes lanes(f, ctx.setup.domain, grad_rho_);
    const std::size_t n = f.size();
    std::uint64_t interactions = 0;
#pragma omp parallel for schedule(static) reduction(+ : interactions)
    for (std::size_t i = 0; i < n; ++i) {
      Sums sums;
      interactions += sumRow(ctx, lanes, kernel_constants, list, i, sums);
      if constexpr (kMirror) {
        const Owner owner{f.v[i], f.rho[i], p_over_rho2_[i], inv_rho_[i],
                          kRenormalised ? grad_rho_[i] : Vec<D>(Vec<D>::Zero())};
        forEachImage(ctx, list, i, [&](const Neighbour& nb) { addPair<false>(sums, nullptr, owner, nb, kernel_constants); });
      }
      storeRates(f, kernel, i, sums);
    }
    return interactions;
  }

  /// With mirror planes, calls visit(nb) for the images near i: those of its listed
  /// neighbours within reach and its own (a scalar pass, for the few particles within
  /// 2h of a plane). Nothing without mirror planes.
  template <class Visit>
  void forEachImage(const FluidContext<D>& ctx, const NeighbourList& list, std::size_t i, Visit&& visit) const {
    if constexpr (kMirror) {
      const FluidParticles<D>& f = ctx.fluid;
      const NearPlanes near = nearPlanes(f.r[i]);
      if (!near.mask) return;
      const double support2 = ctx.kernel.supportSquared();
      const MinimumImage<D> minimum_image(ctx.setup.domain);
      auto each = [&](const Neighbour& nb) { visit(nb); };
      for (std::uint64_t s = list.begin[i]; s < list.begin[i + 1]; ++s) {
        const std::uint32_t j = list.index[s];
        const Vec<D> rij = minimum_image(f.r[i] - f.r[j]);
        // An image is no nearer than its particle while i is on the water's side.
        if (rij.squaredNorm() < support2) visitImages(f, j, rij, near, each);
      }
      visitImages(f, static_cast<std::uint32_t>(i), Vec<D>::Zero(), near, each);
    }
  }

  /// The sums of owner i over its whole list (the terms of addPair, i's side only).
  /// Returns the number of listed particles within reach.
  std::uint32_t sumRow(const FluidContext<D>& ctx, const Lanes& lanes, const KernelConstants& k,
                       const NeighbourList& list, std::size_t i, Sums& out) const {
    const FluidParticles<D>& f = ctx.fluid;
    constexpr int Z = Lanes::Z, S = D;  // S: the stride of the Vec<D> arrays
    const double *v = lanes.v, *g = lanes.g;
    const double* m = f.m.data();
    const double* rho = f.rho.data();
    const double* p_over_rho2 = p_over_rho2_.data();
    const double* inv_rho = inv_rho_.data();
    const double* volume = volume_.data();
    const std::uint32_t* index = list.index.data();
    const double xi0 = f.r[i][0], xi1 = f.r[i][1], xi2 = f.r[i][Z];
    const double vi0 = f.v[i][0], vi1 = f.v[i][1], vi2 = f.v[i][Z];
    double gi0 = 0, gi1 = 0, gi2 = 0, hy0 = 0, hy1 = 0, hy2 = 0;
    if constexpr (kRenormalised) {
      gi0 = grad_rho_[i][0];
      gi1 = grad_rho_[i][1];
      gi2 = grad_rho_[i][Z];
    } else if constexpr (kDiffusion) {
      hy0 = diffusion_.hydrostatic[0];
      hy1 = diffusion_.hydrostatic[1];
      hy2 = diffusion_.hydrostatic[Z];
    }
    const double rho_i = f.rho[i], p_i = p_over_rho2_[i], inv_rho_i = inv_rho_[i];
    double ax = 0, ay = 0, az = 0, sx = 0, sy = 0, sz = 0, sw = 0, drho = 0;
    std::uint32_t count = 0;
    const std::uint64_t first = list.begin[i], last = list.begin[i + 1];
#pragma omp simd reduction(+ : ax, ay, az, sx, sy, sz, sw, drho, count)
    for (std::uint64_t s = first; s < last; ++s) {
      const std::size_t j = index[s];
      double rx, ry, rz;
      lanes.separation(xi0, xi1, xi2, j, rx, ry, rz);
      const double vx = v[S * j], vy = v[S * j + 1], vz = D == 3 ? v[S * j + Z] : 0.0;
      const double vr = (vi0 - vx) * rx + (vi1 - vy) * ry + (vi2 - vz) * rz;
      const double r2 = rx * rx + ry * ry + rz * rz;
      const bool reached = r2 < k.support2;
      const double q = std::sqrt(r2) * k.inv_h;
      const double t = 2.0 - q;
      const double t3 = t * t * t;
      const double F = reached ? k.grad_scale * t3 : 0.0;  // grad_i W_ij = F r_ij
      drho += m[j] * vr * F;
      // 1/(r2 + beta^2) and r2/(r2 + eta^2) from one division when both terms are on.
      double inv_viscous = 0.0, diffusive = 0.0;
      if constexpr (kViscosity && kDiffusion) {
        const double a = r2 + viscosity_.beta2, b = r2 + diffusion_.eta2;
        const double inv_ab = 1.0 / (a * b);
        inv_viscous = b * inv_ab;
        diffusive = r2 * a * inv_ab;
      } else if constexpr (kViscosity) {
        inv_viscous = 1.0 / (r2 + viscosity_.beta2);
      } else if constexpr (kDiffusion) {
        diffusive = r2 / (r2 + diffusion_.eta2);
      }
      double coef = p_i + p_over_rho2[j];
      if constexpr (kViscosity) coef -= viscosity_.xi_mu_eff * vr * inv_rho_i * inv_rho[j] * inv_viscous;
      const double push = m[j] * coef * F;
      ax -= push * rx;
      ay -= push * ry;
      az -= push * rz;
      if constexpr (kXsph) {
        const double w = reached ? k.alpha * t3 * t * (1.0 + 2.0 * q) * volume[j] : 0.0;  // W_ij V_j
        sx += w * vx;
        sy += w * vy;
        sz += w * vz;
        sw += w;
      }
      if constexpr (kDiffusion) {
        double jump = rho_i - rho[j];
        if constexpr (kRenormalised) {
          jump -= 0.5 * ((gi0 + g[S * j]) * rx + (gi1 + g[S * j + 1]) * ry);
          if constexpr (D == 3) jump -= 0.5 * (gi2 + g[S * j + Z]) * rz;
        } else {
          jump -= hy0 * rx + hy1 * ry + hy2 * rz;
        }
        drho += diffusion_.coefficient * jump * F * diffusive * volume[j];
      }
      count += reached ? 1u : 0u;
    }
    const double acc[3] = {ax, ay, az}, xsph[3] = {sx, sy, sz};
    for (int a = 0; a < D; ++a) {
      out.acc[a] = acc[a];
      out.xsph[a] = xsph[a];
    }
    out.xsph_weight = sw;
    out.drho = drho;
    return count;
  }

  static void add(Sums& to, const Sums& from) {
    to.acc += from.acc;
    to.xsph += from.xsph;
    to.xsph_weight += from.xsph_weight;
    to.drho += from.drho;
  }

  /// Writes particle i's rates from its completed sums.
  void storeRates(FluidParticles<D>& f, const WendlandKernel<D>& kernel, std::size_t i, const Sums& sums) const {
    const Vec<D> vi = f.v[i];
    f.dvdt[i] = sums.acc;
    f.drhodt[i] = sums.drho;
    if constexpr (kXsph) {
      if (xsph_.form == XsphForm::Reference) {
        const double self = kernel.valueAtZero() * volume_[i];  // the sum includes j = i
        f.drdt[i] = (1.0 - xsph_.eps) * vi + xsph_.eps * (sums.xsph + self * vi);
      } else {
        f.drdt[i] = vi + xsph_.eps * (sums.xsph - sums.xsph_weight * vi);
      }
    } else {
      f.drdt[i] = vi;
    }
  }

  Viscosity viscosity_;
  Xsph xsph_;
  Diffusion diffusion_;
  Mirror mirror_;
  std::uint64_t interactions_ = 0;
  std::vector<double> p_over_rho2_, inv_rho_, volume_;
  std::vector<std::vector<Sums>> thread_sums_;  ///< sumPairsOnce: one array per thread
  std::vector<Vec<D>> grad_rho_;  ///< renormalised density gradients (kRenormalised only)
  std::vector<double> image_rho_, image_p_over_rho2_, image_inv_rho_, image_volume_;  ///< kMirror only
};

// Compile-time composition: pick each term's type from the scene's list, one branch
// per term, resolved once here.
template <int D, bool Periodic, class V, class X, class Dd>
std::unique_ptr<PairForces<D>> withMirrors(const FluidSetup<D>& s, V v, X x, Dd d) {
  if (s.has("mirror_walls") && s.mirror_walls.empty())
    throw std::invalid_argument("mirror_walls: no planes (a tank builder sets them from its side faces)");
  if (!s.mirrorPlanes().empty())
    return std::make_unique<PairForcesImpl<D, Periodic, V, X, Dd, MirrorTerm<D>>>(v, x, d, MirrorTerm<D>(s));
  return std::make_unique<PairForcesImpl<D, Periodic, V, X, Dd, NoTerm>>(v, x, d, NoTerm{});
}

template <int D, bool Periodic, class V, class X>
std::unique_ptr<PairForces<D>> withDiffusion(const FluidSetup<D>& s, V v, X x) {
  if (s.has("density_diffusion") && s.method.density_diffusion_form == DensityDiffusionForm::Renormalised)
    return withMirrors<D, Periodic>(s, v, x, RenormalisedDensityDiffusionTerm<D>(s));
  if (s.has("density_diffusion")) return withMirrors<D, Periodic>(s, v, x, DensityDiffusionTerm<D>(s));
  return withMirrors<D, Periodic>(s, v, x, NoTerm{});
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
