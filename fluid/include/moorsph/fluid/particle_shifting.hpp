#pragma once
// The "particle_shifting" effect: keeps the particles near a uniform arrangement by
// adding a small diffusive shifting velocity to their transport velocity dr/dt.
//
// Why: in weakly compressible SPH the particles drift into disordered clusters along
// the streamlines; the disorder adds noise to the pressure, and wave energy leaks into
// that particle-scale motion where the dissipative terms remove it. A regular wave
// then loses 0.09-0.2 of its height per wavelength (docs/validation/wave-propagation.md).
//
// The shift follows Fick's law (Lind et al. 2012, J. Comput. Phys. 231:1499): particles
// move down the gradient of the particle concentration C_i = sum_j V_j W_ij,
//
//   du_shift_i = -A h |v_i| sum_j V_j [1 + R (W_ij / W(dx))^n] grad_i W_ij       (1)
//
// with the diffusion coefficient scaled by the particle's own speed, A h |v_i|, so the
// shift is a fixed fraction of the distance the particle travels and vanishes in water
// at rest (Skillen et al. 2013, Comput. Methods Appl. Mech. Eng. 265:163, A = 2). The
// bracket is the anti-clustering term of Lind et al. (they use R = 0.2, n = 4) meant to
// keep pairs closer than dx apart from the tensile instability. It is off by default
// (R = 0): with R = 0.2, 3D water at rest in a tank sank 10 mm of its 100 mm mean height in
// 1 s and its kinetic energy rose sevenfold (test_particle_shifting, StillWater3DKeeps-
// ItsVolume; docs/stability.md 3c). |du_shift| <= cap |v_i|.
//
// Where the kernel is truncated the concentration gradient is not disorder but the
// missing neighbours, and a shift along it would move water across its boundary:
//  - free surface: particles whose position divergence div r = -sum_j V_j r_ij.grad_i W_ij
//    is below surface_divergence (the bulk value is about D; a flat surface's top layer
//    has 1.26 in 2D and 2.08 in 3D with h = 1.2 dx) shift only tangentially: the
//    component along their surface normal n = -grad C/|grad C| is removed; particles
//    that have such a surface particle within 2h do the same with the mean normal of those
//    surface neighbours; isolated particles (div r below splash_divergence) do not shift;
//  - walls and bodies: the component into the wall, along the normals of every boundary
//    particle within 2h, is removed (a shift away from a wall is allowed).
// The shift moves particles without changing their velocity or density (the Taylor
// correction of the carried fields is neglected, as in most WCSPH implementations); the
// density diffusion term is recommended beside it.
#include <vector>
#include <moorsph/fluid/boundary_particles.hpp>
#include <moorsph/fluid/counted.hpp>
#include <moorsph/fluid/fluid_effect.hpp>
#include <moorsph/fluid/method_parameters.hpp>

namespace moorsph::fluid {


template <int D>
class ParticleShifting final : public FluidEffect<D>, public Counted<ParticleShifting<D>> {
 public:
  /// `boundary` may be null (no walls); it must outlive the effect.
  ParticleShifting(const ShiftingParameters& parameters, double dx, double h, const BoundaryParticles<D>* boundary);
  const char* name() const override { return "particle_shifting"; }
  void addRates(FluidContext<D>& ctx) override;

  /// Per-particle classification of the last evaluation (for tests and output).
  enum class Region : char { Bulk, NearSurface, Surface, Splash };
  const std::vector<Region>& regions() const { return region_; }
  /// The last evaluation's concentration gradient (with the anti-clustering term) [1/m].
  const std::vector<Vec<D>>& concentrationGradients() const { return grad_c_; }
  const std::vector<double>& positionDivergence() const { return div_r_; }

 private:
  void measureConcentration(const FluidContext<D>& ctx);
  void classify(const FluidContext<D>& ctx);
  void applyShift(FluidContext<D>& ctx) const;
  Vec<D> withoutWallComponents(const FluidContext<D>& ctx, std::size_t i, Vec<D> shift) const;

  ShiftingParameters p_;
  double h_;
  double inv_w_dx_;  // 1 / W(dx)
  const BoundaryParticles<D>* boundary_;
  std::vector<Vec<D>> grad_c_, normal_, band_normal_;
  std::vector<double> div_r_;
  std::vector<Region> region_;
  std::vector<char> near_surface_;
};

}  // namespace moorsph::fluid
