#pragma once
// Numerical-method parameters. `reference()` is METHOD.md exactly; options on top
// of it (density diffusion, the Monaghan XSPH form) are off there.
#include <cstddef>
#include <string>

namespace moorsph::fluid {

/// An option's names in scenes and runner keys: one table per enum, shared by the scene
/// reader, the scene writer and the runners.
template <class Enum>
struct OptionName {
  Enum value;
  const char* name;
};

/// The name of `value` in `table` (the first entry's if it is not there).
template <class Enum, std::size_t N>
const char* optionName(const OptionName<Enum> (&table)[N], Enum value) {
  for (const auto& entry : table)
    if (entry.value == value) return entry.name;
  return table[0].name;
}

/// False if `name` is none of the table's names (then `value` is left as it was).
template <class Enum, std::size_t N>
bool optionFromName(const OptionName<Enum> (&table)[N], const std::string& name, Enum& value) {
  for (const auto& entry : table)
    if (name == entry.name) {
      value = entry.value;
      return true;
    }
  return false;
}

/// "'a', 'b' or 'c'": the table's names for an error message.
template <class Enum, std::size_t N>
std::string optionNames(const OptionName<Enum> (&table)[N]) {
  std::string list;
  for (std::size_t i = 0; i < N; ++i)
    list += (i == 0 ? "'" : i + 1 == N ? " or '" : ", '") + std::string(table[i].name) + "'";
  return list;
}

enum class XsphForm {
  /// METHOD.md: dr/dt = (1 - eps) v_i + eps sum_j (m_j/rho_j) v_j W_ij, self term included.
  Reference,
  /// Monaghan (1989): dr/dt = v_i + eps sum_j (m_j/rho_j) (v_j - v_i) W_ij; keeps a uniform
  /// flow's speed exactly, also where the kernel is truncated at the free surface.
  Monaghan,
};

inline constexpr OptionName<XsphForm> kXsphFormNames[] = {
    {XsphForm::Reference, "reference"},
    {XsphForm::Monaghan, "monaghan"},
};

enum class DensityDiffusionForm {
  MolteniColagrossi,  ///< Molteni & Colagrossi (2009)
  Fourtakas,          ///< Fourtakas et al. (2019): hydrostatic part removed, no wall spurious flux
  /// Antuono et al. (2010), the delta-SPH term: the jump is corrected by the particles'
  /// renormalised density gradients, so any linear density field (the hydrostatic one
  /// included) gives no flux, also where the kernel is cut by the free surface or a wall.
  Renormalised,
};

inline constexpr OptionName<DensityDiffusionForm> kDensityDiffusionFormNames[] = {
    {DensityDiffusionForm::Fourtakas, "fourtakas"},
    {DensityDiffusionForm::MolteniColagrossi, "molteni_colagrossi"},
    {DensityDiffusionForm::Renormalised, "renormalised"},
};

/// How a step advances the state (fluid_simulation.hpp).
enum class Integrator {
  /// METHOD.md section 1: predict by predictor_fraction dt, evaluate, correct the whole
  /// state from the step's start with the predicted rates.
  PredictorCorrector,
  /// Stormer-Verlet in (position, density) against velocity: drift half a step, kick a
  /// whole step with the mid-step rates, drift the second half with the new velocity,
  /// the density's second half by the continuity sum with that velocity. Neutral for
  /// an undamped oscillation (w dt < 2), where the midpoint predictor amplifies one.
  Symplectic,
};

inline constexpr OptionName<Integrator> kIntegratorNames[] = {
    {Integrator::PredictorCorrector, "predictor_corrector"},
    {Integrator::Symplectic, "symplectic"},
};

/// The wall law of boundary_force_law.hpp.
enum class BoundaryForceForm {
  /// METHOD.md section 2: each boundary particle pushes along its normal only.
  Reference,
  /// Minus the gradient of the law's potential B(r_par) Psi(q): adds a part along the
  /// wall, so the wall force does no net work around a closed path, and bodies take
  /// the reactions' moments at the fluid particles (angular momentum kept). The
  /// reference law's normal-only push is not a gradient; on a free body it fed a
  /// growing sway (docs/validation/tethered-buoy.md, "A flutter of the wall law").
  Conservative,
};

inline constexpr OptionName<BoundaryForceForm> kBoundaryForceFormNames[] = {
    {BoundaryForceForm::Reference, "reference"},
    {BoundaryForceForm::Conservative, "conservative"},
};

/// Particle shifting (the "particle_shifting" effect, particle_shifting.hpp).
struct ShiftingParameters {
  double coefficient = 2.0;        ///< A in (1): Skillen et al. 2013
  double anti_clustering = 0.0;    ///< R in (1): Lind et al. 2012
  int anti_clustering_power = 4;   ///< n in (1)
  double cap = 0.5;                ///< |du_shift| <= cap |v|
  double surface_divergence = -1;  ///< < 0: D - 0.4 (1.6 in 2D, 2.6 in 3D)
  double splash_divergence = -1;   ///< < 0: D / 2
};

struct MethodParameters {
  std::string name = "reference";
  double h_factor = 1.2;             ///< h = h_factor dx
  double cfl = 0.5;                  ///< dt = cfl h / (c_s + 2 xi mu/(h rho0))
  /// Fraction of dt the predictor advances. 1: METHOD.md's Euler predictor (damps
  /// acoustic modes, first order in time); 0.5: the midpoint rule (second order,
  /// needs a smaller cfl or density diffusion to stay stable).
  double predictor_fraction = 1.0;
  /// Symplectic: the predictor advances dt/2 whatever predictor_fraction says.
  Integrator integrator = Integrator::PredictorCorrector;
  double force_dt_factor = 0.25;     ///< dt <= force_dt_factor sqrt(h / max|a|)
  double gamma = 7.0;                ///< Tait exponent
  double xsph_eps = 0.5;             ///< XSPH epsilon
  XsphForm xsph_form = XsphForm::Reference;
  double viscosity_xi = 5.75;        ///< Cleary xi for the Wendland kernel
  double viscosity_beta_factor = 0.01;  ///< beta = factor * dx
  double boundary_offset = 0.5;      ///< b_off: distance pushed back into the wall, in dx
  double boundary_strength = 0.01;   ///< wall force scale: strength c_s^2 m_i / h_w
  /// The wall law's length h_w = boundary_h_factor dx (METHOD.md section 2 uses the
  /// kernel's h); 0: the kernel's h. With a larger kernel (h_factor 2) a wall law on
  /// h_w = 1.2 dx keeps the reference's reach (0.7 dx) and stiffness.
  double boundary_h_factor = 0.0;
  BoundaryForceForm boundary_force_form = BoundaryForceForm::Reference;
  double density_diffusion_delta = 0.1;
  DensityDiffusionForm density_diffusion_form = DensityDiffusionForm::Fourtakas;
  ShiftingParameters shifting;      ///< used when the scene names particle_shifting
  double skin_factor = 0.15;         ///< Verlet skin = skin_factor * 2h
  /// Runtime guard, not part of the method: a step shorter than min_dt_fraction x the
  /// CFL step (the step a fluid at rest takes) stops the run with a diagnostic. 0 disables it.
  double min_dt_fraction = 1.0e-3;
  /// Runtime guard, not part of the method: a fluid particle faster than
  /// max_speed_fraction x c_s stops the run. The method is built for flows below c_s/10
  /// (METHOD.md section 1); a particle at c_s/2 has been flung by a numerical fault, as
  /// the one that got behind the 6 m ship's bow face and was thrown out at 1.06 c_s
  /// (docs/validation/ship.md). 0 disables it.
  double max_speed_fraction = 0.5;
  /// Runtime guard, not part of the method: a fluid particle inside a closed surface (a
  /// body), more than max_leak_depth x dx behind the faces of its nearest boundary
  /// particle, stops the run. The wall force holds the water about half a spacing in
  /// front of the boundary particles; one behind them got through a gap in the surface's
  /// particles or came faster than the force can stop. 0 disables it.
  double max_leak_depth = 0.1;

  static MethodParameters reference() { return MethodParameters{}; }
};

}  // namespace moorsph::fluid
