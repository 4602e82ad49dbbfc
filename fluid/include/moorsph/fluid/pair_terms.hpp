#pragma once
// The optional terms of the fluid pair loop, each a small value type constructed
// only when the scene names it (see pair_forces.hpp).
#include <array>
#include <cmath>
#include <stdexcept>
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

/// Free-slip walls made of mirror images ("ghost particles", Libersky et al. 1993; the
/// ghost-fluid wall of Colagrossi & Landrini 2003, J. Comput. Phys. 191): the floor
/// (mirror_floor) and a tank's side walls (mirror_walls), each an axis-aligned plane.
/// Every fluid particle j within 2h of a plane has an image j' reflected across it,
/// with the velocity component normal to the plane reversed; near an edge or corner
/// also the images across two or three planes (the image of the image). Across a
/// horizontal plane the pressure is continued hydrostatically,
/// P_j' = P_j + rho0 g . (r_j' - r_j), so that still water's pressure gradient carries
/// on through the floor; across a vertical plane the image keeps P_j. The images
/// complete the kernel: particles near a mirror wall see a full neighbourhood in the
/// pressure, continuity, diffusion and XSPH sums, where the "walls" force only pushes
/// and leaves the first layers short of support (docs/stability.md 3c: 79% at a 3D
/// wall, 64% in an edge column). Pistons and bodies remain boundary particles.
template <int D>
struct MirrorTerm : Counted<MirrorTerm<D>> {
  /// The planes normal to one axis: none, one, or two (a tank's opposite faces).
  struct Axis {
    int count = 0;
    double position[2] = {0.0, 0.0};
    int inside[2] = {1, 1};
  };
  std::array<Axis, D> axes;
  double rho0_gy;         ///< rho0 g_y: the image's pressure change per metre it is moved up [Pa/m]
  double ghost_gradient;  ///< 2 rho0 g_y / c_s^2: the y-image's density gradient shift [kg/m^4]
  double reach;           ///< 2h: particles farther than this from a plane have no image in range

  explicit MirrorTerm(const FluidSetup<D>& s)
      : rho0_gy(s.rho0 * s.gravity[1]),
        ghost_gradient(2.0 * s.rho0 * s.gravity[1] / (s.sound_speed * s.sound_speed)),
        reach(2.0 * s.h()) {
    for (const MirrorPlane& p : s.mirrorPlanes()) {
      if (p.axis < 0 || p.axis >= D) throw std::invalid_argument("mirror plane: axis out of range");
      if (s.domain.periodic[p.axis]) throw std::invalid_argument("mirror planes: the domain must not be periodic along them");
      if (p.axis != 1 && s.gravity[p.axis] != 0.0)
        throw std::invalid_argument("mirror_walls: gravity must be normal to the floor (the images keep P across a side wall)");
      Axis& a = axes[p.axis];
      if (a.count == 2) throw std::invalid_argument("mirror planes: more than two normal to one axis");
      if (a.count == 1 && std::abs(a.position[0] - p.position) <= 2.0 * reach)
        throw std::invalid_argument("mirror planes: two parallel planes closer than 4h (a particle would see both)");
      a.position[a.count] = p.position;
      a.inside[a.count] = p.inside;
      ++a.count;
    }
  }

  /// The plane normal to `axis` within reach of coordinate x, if any: its position,
  /// side, and x's signed distance from it into the water (negative once crossed).
  bool near(int axis, double x, double& position, int& inside, double& distance) const {
    const Axis& a = axes[axis];
    for (int k = 0; k < a.count; ++k) {
      const double d = a.inside[k] * (x - a.position[k]);
      if (d < reach) {
        position = a.position[k], inside = a.inside[k], distance = d;
        return true;
      }
    }
    return false;
  }
};

}  // namespace moorsph::fluid
