#pragma once
// A weakly-compressible SPH fluid assembled from the effects a scene names
// (DESIGN.md section 5), advanced by the predictor-corrector of METHOD.md section 1:
//
//   rates at the start of the step (r^n, v^n, rho^n)       -> a^n, (dr/dt)^n, D^n
//   predict with Euler:        x* = x^n + f dt (dx/dt)^n
//   rates at the predicted state                            -> a*, (dr/dt)*, D*
//   correct from the start:    x^{n+1} = x^n + dt (dx/dt)*
//
// Two rate evaluations per step. The reference (f = 1, METHOD.md's "predict with
// Euler") has amplification 1 + z + z^2 for z = i omega dt, |.|^2 = 1 - x^2 + x^4:
// it damps acoustic noise, at the price of first-order accuracy. f = 1/2 is the
// midpoint rule (1 + z + z^2/2, |.|^2 = 1 + x^4/4): second order but it amplifies
// undamped acoustic modes, so it needs density diffusion (method option).
//
// The symplectic option (method.integrator, Stormer-Verlet with the velocity as the
// momentum): the same predictor at f = 1/2 (r*, rho* half a step on, v* too, for the
// velocity-dependent terms), the rates there, then
//   kick:   v^{n+1}   = v^n + dt a*
//   drift:  r^{n+1}   = r* + dt/2 (v^{n+1} + (dr/dt)* - v*)      (XSPH/shifting part kept)
//           rho^{n+1} = rho* + dt/2 (D* + C(v^{n+1} - v*))
// with C the continuity sum alone at r* (linear in the velocity), so the second half
// of the density's drift sees the new velocity and the density diffusion of the
// mid-state. For rho' = -alpha v, v' = beta rho (an acoustic mode, (w dt)^2 = z) the
// step's matrix has determinant exactly 1 and trace 2 - z: neutral for w dt < 2, where
// the midpoint rule grows by z^2/8 per step (docs/stability.md 3h). One extra pair pass
// (continuity only) per step.
//
// Time step (METHOD.md section 1): dt = min(CFL h/(c_s + 2 xi mu/(h rho0)),
// force_dt_factor sqrt(h / max|a|)); the second bound matters in impacts.
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>
#include <moorsph/fluid/fluid_effect.hpp>
#include <moorsph/fluid/outflow.hpp>
#include <moorsph/fluid/pair_forces.hpp>
#include <moorsph/fluid/phase_timers.hpp>
#include <moorsph/fluid/walls.hpp>

namespace moorsph::fluid {

/// Raised when a run goes wrong (NaN/Inf, a particle leaving the domain, rho <= 0, a
/// time step below method.min_dt_fraction x the CFL step; coupling/ adds a body
/// leaving the domain). The message names the particle or body, its state, the time
/// and the likely cause (run_guard.hpp).
class SimulationError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Mechanical energy of the fluid [J]. potential is sum(-m g.r); elastic is the Tait
/// compression energy sum(m e(rho)).
struct FluidEnergy {
  double kinetic = 0.0;
  double potential = 0.0;
  double elastic = 0.0;
  double total() const { return kinetic + potential + elastic; }
};

template <int D>
class FluidSimulation {
 public:
  /// Builds exactly the effects `setup.effects` names. Throws std::invalid_argument
  /// for an unknown effect, a missing one that another needs, or inconsistent input.
  FluidSimulation(FluidSetup<D> setup, FluidParticles<D> fluid, BoundaryGeometry<D> boundary = {});

  /// One predictor-corrector step.
  void step();
  /// Step until time() >= t (the last step is not shortened).
  void advanceTo(double t);

  /// Rebuild (and re-sort) the neighbour lists at the end of the next step, before the
  /// rates that start the following step are evaluated.
  void requestNeighbourRebuild() { rebuild_requested_ = true; }
  /// A restart's lists: those the checkpointed run had, rebuilt from the positions its
  /// last rebuild saw (NeighbourSearch::restore), so the restart continues bit-identically
  /// without the run having rebuilt before its checkpoint. Call after construction with
  /// the saved particles, before the first step; `boundary_at_build` is empty without walls.
  void restoreNeighbourLists(const std::vector<Vec<D>>& fluid_at_build, const std::vector<Vec<D>>& boundary_at_build);
  /// Set the clock of a run restored from a checkpoint (the particles were passed to
  /// the constructor in their saved order).
  void restoreClock(double time, std::size_t steps, double last_dt) {
    time_ = time;
    steps_ = steps;
    dt_ = last_dt;
    rates_current_ = false;
  }

  /// Add an effect built outside (e.g. by coupling/ or io/); it runs after the built-in ones.
  void addEffect(std::unique_ptr<FluidEffect<D>> effect);

  double time() const { return time_; }
  double lastDt() const { return dt_; }
  std::size_t stepCount() const { return steps_; }
  /// The CFL-limited time step (the largest the scheme will take).
  double cflDt() const { return cfl_dt_; }

  const FluidSetup<D>& setup() const { return setup_; }
  const FluidParticles<D>& fluid() const { return fluid_; }
  FluidParticles<D>& updFluid() { return fluid_; }
  const WendlandKernel<D>& kernel() const { return kernel_; }
  const TaitEos& eos() const { return eos_; }
  const NeighbourSearch<D>& neighbours() const { return neighbours_; }
  /// The walls effect, or null if the scene has no walls.
  const Walls<D>* walls() const { return walls_; }
  Walls<D>* updWalls() { return walls_; }

  /// The first effect of type E (built-in or added), or null.
  template <class E>
  const E* findEffect() const {
    for (const auto& e : effects_)
      if (const auto* found = dynamic_cast<const E*>(e.get())) return found;
    return nullptr;
  }
  template <class E>
  E* updEffect() {
    for (const auto& e : effects_)
      if (auto* found = dynamic_cast<E*>(e.get())) return found;
    return nullptr;
  }

  /// The "outflow" effect (spray leaving an open tank is removed), or null if the scene
  /// does not name it.
  const Outflow<D>* outflow() const { return outflow_.get(); }
  Outflow<D>* updOutflow() { return outflow_.get(); }

  /// Names of the effects that were built, in evaluation order (the pair terms first).
  std::vector<std::string> effectNames() const;
  /// Fluid-fluid pairs within 2h evaluated by the last rate evaluation.
  std::uint64_t lastInteractions() const { return pairs_->lastInteractions(); }
  /// Fluid-fluid pairs within 2h evaluated since construction (two evaluations a step).
  std::uint64_t totalInteractions() const { return total_interactions_; }
  FluidEnergy calcEnergy() const;
  /// Wall time per phase: neighbours, pairs, one per effect, integrate, checks.
  const PhaseTimers& phaseTimers() const { return timers_; }

 private:
  void buildEffects(BoundaryGeometry<D> boundary);
  void evaluateRates(double t, bool may_rebuild);
  double computeDt() const;
  void predict(double dt);
  void correct(double dt);
  /// The symplectic integrator's kick and second drift (Integrator::Symplectic).
  void correctSymplectic(double dt);
  void removeOutflow();
  void checkHealth() const;

  FluidSetup<D> setup_;
  FluidParticles<D> fluid_;
  WendlandKernel<D> kernel_;
  TaitEos eos_;
  NeighbourSearch<D> neighbours_;
  std::unique_ptr<PairForces<D>> pairs_;
  std::vector<Vec<D>> transport_;        ///< correctSymplectic's scratch: (dr/dt)* - v*
  std::vector<double> continuity_change_;  ///< correctSymplectic's scratch: C(v^{n+1} - v*)
  std::vector<std::unique_ptr<FluidEffect<D>>> effects_;
  Walls<D>* walls_ = nullptr;  // owned by effects_
  std::unique_ptr<Outflow<D>> outflow_;
  std::vector<char> no_tracking_;
  double time_ = 0.0;
  double dt_ = 0.0;
  double cfl_dt_ = 0.0;
  std::size_t steps_ = 0;
  bool rates_current_ = false;
  bool rebuild_requested_ = false;
  std::uint64_t total_interactions_ = 0;
  PhaseTimers timers_;
  int phase_neighbours_ = 0, phase_pairs_ = 0, phase_integrate_ = 0, phase_checks_ = 0, phase_outflow_ = -1;
  std::vector<int> phase_effects_;
};

}  // namespace moorsph::fluid
