#pragma once
// A fluid effect: one physical ingredient that a scene names (gravity, walls, a
// forcing region, a damping zone...). The step calls each built effect once per
// rate evaluation (a virtual call per evaluation, never per particle pair), after
// the pair forces. Effects a scene does not name are never constructed.
#include <cstdint>
#include <moorsph/fluid/fluid_particles.hpp>
#include <moorsph/fluid/fluid_setup.hpp>
#include <moorsph/fluid/neighbour_search.hpp>
#include <moorsph/fluid/tait_eos.hpp>
#include <moorsph/fluid/wendland_kernel.hpp>

namespace moorsph::fluid {

/// What an effect sees during one evaluation of the rates.
template <int D>
struct FluidContext {
  FluidParticles<D>& fluid;
  const NeighbourSearch<D>& neighbours;
  const WendlandKernel<D>& kernel;
  const TaitEos& eos;
  const FluidSetup<D>& setup;
  double time;  ///< time of the state being evaluated [s]
};

/// Where in the predictor-corrector step a call to FluidEffect::advanceTo falls.
enum class StepStage {
  Start,      ///< before the first evaluation of a run (or after a restart)
  Predicted,  ///< before the rates at the predicted state are evaluated
  Corrected,  ///< after the corrector, before the rates that start the next step
};

template <int D>
class FluidEffect {
 public:
  virtual ~FluidEffect() = default;
  /// The scene's name for this effect.
  virtual const char* name() const = 0;
  /// Add this effect's contribution to dv/dt, dr/dt or drho/dt.
  virtual void addRates(FluidContext<D>& ctx) = 0;
  /// Move prescribed parts (boundaries, makers, coupled bodies) to time t before the
  /// state at t is evaluated. `stage` tells a coupled effect which state that is: the
  /// reactions of the last evaluation belong to the predicted state when stage is
  /// Corrected (see coupling/).
  virtual void advanceTo(double /*t*/, StepStage /*stage*/) {}
  /// Enforce a constraint on the state just integrated: `stage` is Predicted after the
  /// predictor, Corrected after the corrector (e.g. keep particles on the fluid side of
  /// a mirror plane).
  virtual void constrain(FluidParticles<D>& /*fluid*/, StepStage /*stage*/) {}
};

}  // namespace moorsph::fluid
