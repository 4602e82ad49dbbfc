#pragma once
// The optional terms of the fluid pair loop, each a small value type constructed
// only when the scene names it (see pair_forces.hpp).
#include <cmath>
#include <moorsph/fluid/counted.hpp>
#include <moorsph/fluid/fluid_setup.hpp>

namespace moorsph::fluid {

/// Placeholder for a term the scene did not name.
struct NoTerm {};

/// Cleary viscosity (METHOD.md section 1), added to the pressure coefficient:
///   Pi_ij = -(xi/(rho_i rho_j)) (4 mu_i mu_j/(mu_i + mu_j)) (v_ij . r_ij) / (|r_ij|^2 + beta^2)
/// With one fluid, 4 mu^2/(2 mu) = 2 mu. Approaching particles (v_ij . r_ij < 0) get
/// Pi > 0, an extra repulsion: the term dissipates.
struct ViscosityTerm : Counted<ViscosityTerm> {
  double xi_mu_eff;  ///< xi * 4 mu_i mu_j / (mu_i + mu_j)  [Pa s]
  double beta2;      ///< beta^2 [m^2]
  template <int D>
  explicit ViscosityTerm(const FluidSetup<D>& s)
      : xi_mu_eff(s.method.viscosity_xi * 2.0 * s.mu),
        beta2(s.method.viscosity_beta_factor * s.dx * s.method.viscosity_beta_factor * s.dx) {}
};

/// XSPH velocity smoothing (METHOD.md section 1, or Monaghan's form; see XsphForm).
struct XsphTerm : Counted<XsphTerm> {
  double eps;
  XsphForm form;
  template <int D>
  explicit XsphTerm(const FluidSetup<D>& s) : eps(s.method.xsph_eps), form(s.method.xsph_form) {}
};

/// Density diffusion (delta-SPH), the usual cure for WCSPH pressure noise:
///   drho_i/dt += delta h c_s sum_j 2 (rho_i - rho_j - rho_ij^H) (r_ij . grad_i W_ij)/(|r_ij|^2 + eta^2) V_j
/// Molteni & Colagrossi (2009) have rho_ij^H = 0. Fourtakas et al. (2019) subtract the
/// hydrostatic density difference rho_ij^H = rho0 (g . r_ij)/c_s^2 so that a still
/// fluid under gravity has no spurious diffusive flux. eta^2 = 0.01 h^2.
template <int D>
struct DensityDiffusionTerm : Counted<DensityDiffusionTerm<D>> {
  double coefficient;  ///< 2 delta h c_s [m^2/s]
  double eta2;         ///< [m^2]
  Vec<D> hydrostatic;  ///< rho0 g / c_s^2 (Fourtakas) or zero  [kg/m^4]
  explicit DensityDiffusionTerm(const FluidSetup<D>& s)
      : coefficient(2.0 * s.method.density_diffusion_delta * s.h() * s.sound_speed),
        eta2(0.01 * s.h() * s.h()),
        hydrostatic(s.method.density_diffusion_form == DensityDiffusionForm::Fourtakas
                        ? Vec<D>(s.rho0 * s.gravity / (s.sound_speed * s.sound_speed))
                        : Vec<D>(Vec<D>::Zero())) {}
};

/// Density diffusion of delta-SPH (Antuono, Colagrossi, Marrone, Molteni 2010, Comput.
/// Phys. Commun. 181, eq. 10): the jump is
///   psi_ij = (rho_i - rho_j) - (G_i + G_j) . r_ij / 2,
///   G_i = L_i sum_j (rho_j - rho_i) grad_i W_ij V_j,  L_i = (sum_j r_ji (x) grad_i W_ij V_j)^-1,
/// which vanishes for any linear density field. Near a free surface the plain jump of
/// Molteni & Colagrossi (or Fourtakas) meets a one-sided neighbourhood and diffuses the
/// wave's dynamic pressure out of the surface layer, a loss of order delta h c_s that
/// damped free waves (docs/validation/wave-propagation.md). Where L_i is singular (a
/// particle with too few neighbours: det below `min_det` of the full-support value) G_i
/// falls back to the hydrostatic gradient rho0 g / c_s^2.
template <int D>
struct RenormalisedDensityDiffusionTerm : Counted<RenormalisedDensityDiffusionTerm<D>> {
  double coefficient;  ///< 2 delta h c_s [m^2/s]
  double eta2;         ///< [m^2]
  Vec<D> hydrostatic;  ///< rho0 g / c_s^2, the fallback gradient [kg/m^4]
  double min_det = 0.1;
  explicit RenormalisedDensityDiffusionTerm(const FluidSetup<D>& s)
      : coefficient(2.0 * s.method.density_diffusion_delta * s.h() * s.sound_speed),
        eta2(0.01 * s.h() * s.h()),
        hydrostatic(s.rho0 * s.gravity / (s.sound_speed * s.sound_speed)) {}
};

/// A free-slip floor y = height made of mirror images ("ghost particles", Libersky et
/// al. 1993; the ghost-fluid wall of Colagrossi & Landrini 2003, J. Comput. Phys. 191).
/// Every fluid particle j within 2h of the floor has an image j' at y' = 2 height - y_j
/// with the horizontal velocity kept and the vertical one reversed, and the pressure
/// continued hydrostatically, P_j' = P_j + 2 rho0 |g| (y_j - height), so that the
/// still water's pressure gradient carries on through the floor. The images complete
/// the kernel: particles near the floor see a full neighbourhood in the pressure,
/// continuity, diffusion and XSPH sums, where the "walls" force only pushes. One flat
/// horizontal floor per scene (a tank's `floor: mirror`, the periodic wave tank's
/// `floor=mirror`); side walls, pistons and bodies remain boundary particles.
template <int D>
struct MirrorFloorTerm : Counted<MirrorFloorTerm<D>> {
  double height;           ///< the floor plane's y [m]
  double rho0_g;           ///< rho0 |g| [Pa/m]
  double ghost_gradient;   ///< 2 rho0 g_y / c_s^2: the image's density gradient shift [kg/m^4]
  double reach;            ///< 2h: particles farther than this from the floor have no image in range
  explicit MirrorFloorTerm(const FluidSetup<D>& s)
      : height(s.mirror_floor_height),
        rho0_g(s.rho0 * std::abs(s.gravity[1])),
        ghost_gradient(2.0 * s.rho0 * s.gravity[1] / (s.sound_speed * s.sound_speed)),
        reach(2.0 * s.h()) {}
  /// The image of a vector: its vertical component reversed.
  static Vec<D> mirror(Vec<D> a) {
    a[1] = -a[1];
    return a;
  }
};

}  // namespace moorsph::fluid
