#pragma once
// The "piston" effect (METHOD.md section 4b): a movable wall surface translated along
// x by a prescribed displacement X(t) (any function, e.g. a CubicSpline of a time
// series or a generated wave-maker signal). Before each rate evaluation the surface
// is placed at its reference position + X(t) e_x, moving at X'(t) e_x. Needs `walls`.
// When the surface tracks its reactions the effect also sums the work the plate does on
// the water, W = sum over steps of dt X'(t) (-F_x), F the fluid's force on the plate at
// the state the corrector used (first order in dt; the energy input of a wave flume).
#include <functional>
#include <moorsph/fluid/counted.hpp>
#include <moorsph/fluid/walls.hpp>

namespace moorsph::fluid {

template <int D>
class Piston final : public FluidEffect<D>, public Counted<Piston<D>> {
 public:
  using Signal = std::function<double(double)>;  ///< t [s] -> X [m] (or dX/dt [m/s])

  /// Throws std::invalid_argument if `walls` is null or the surface is not movable.
  Piston(Walls<D>* walls, std::size_t surface, Signal displacement, Signal velocity);

  const char* name() const override { return "piston"; }
  void addRates(FluidContext<D>&) override {}
  void advanceTo(double t, StepStage stage) override;
  double displacement() const { return x_; }
  /// Work done on the fluid since the run started [J] (2D: J/m), carried across restarts
  /// by the checkpoint; 0 when the surface does not track reactions.
  double work() const { return work_; }
  /// Continue the sum of a run restored from a checkpoint.
  void restoreWork(double work) { work_ = work; }

 private:
  Walls<D>* walls_;
  std::size_t surface_;
  Signal displacement_, velocity_;
  Vec<D> origin_;
  double x_ = 0.0;
  double work_ = 0.0, last_t_ = 0.0;
};

}  // namespace moorsph::fluid
