#pragma once
// Fluid-fluid pair interactions (METHOD.md section 1), fused in one loop over each
// particle's neighbours:
//   continuity   drho_i/dt = sum_j m_j (v_i - v_j) . grad_i W_ij
//   momentum     dv_i/dt   = - sum_j m_j (P_i/rho_i^2 + P_j/rho_j^2 + Pi_ij) grad_i W_ij
// plus the terms a scene names: Cleary viscosity Pi_ij ("viscosity"), XSPH
// ("xsph"), density diffusion ("density_diffusion"). The loop is a template over the
// chosen terms, so a term not named costs nothing and is never constructed; the
// choice is dispatched once when the simulation is built (DESIGN.md section 5).
//
// The loop needs no atomics: in 3D, periodic domains and with mirror planes each
// particle sums its own list row in vector lanes (a gather); a bounded 2D scene takes
// each pair once into per-thread sums (docs/performance.md, sessions 30 and 42). It
// counts the pairs within 2h it evaluated ("neighbour interactions").
#include <cstdint>
#include <memory>
#include <vector>
#include <moorsph/fluid/fluid_effect.hpp>

namespace moorsph::fluid {

template <int D>
class PairForces {
 public:
  virtual ~PairForces() = default;
  /// Pressures from the equation of state, then dv/dt, drho/dt and dr/dt of every particle
  /// (overwritten, not accumulated).
  virtual void evaluate(FluidContext<D>& ctx) = 0;
  /// Pairs within 2h evaluated by the last call.
  virtual std::uint64_t lastInteractions() const = 0;
  /// The continuity term of drho/dt alone, sum_j m_j (v_i - v_j) . grad_i W_ij (mirror
  /// images included), at the current positions and velocities, into `out`; no density
  /// diffusion. Uses the neighbour list and image states of the last evaluate(), so
  /// the positions must be those of that evaluation (the symplectic integrator's drift).
  virtual void continuityRate(FluidContext<D>& ctx, std::vector<double>& out) const = 0;
};

/// Build the pair loop for the effects `setup` names. Throws std::invalid_argument
/// if "pressure" is missing (a weakly-compressible fluid cannot move without it).
template <int D>
std::unique_ptr<PairForces<D>> makePairForces(const FluidSetup<D>& setup);

}  // namespace moorsph::fluid
