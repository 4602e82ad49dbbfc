#pragma once
// Settling damping: dv/dt += -k v on every fluid particle until t_end, then nothing.
// A lattice start is not in equilibrium: the layer next to a wall sits inside the wall
// force's range, and in 3D the simple cubic lattice itself packs ~1% denser under the
// Wendland kernel (docs/stability.md 3c). The first steps fill the tank with acoustic
// noise and slow rearrangement that the method damps only slowly (e-folding ~3-6 s).
// Damping the fluid while the bodies are held (the coupling's settling period) lets it
// find its discrete equilibrium before anything is measured or released. k dt << 1
// keeps the step stable; the damping does no work on a fluid at rest.
#include <moorsph/fluid/fluid_effect.hpp>

namespace moorsph::fluid {

template <int D>
class SettlingDamping final : public FluidEffect<D> {
 public:
  /// rate k [1/s], active while the evaluated time is below t_end [s]
  SettlingDamping(double rate, double t_end) : rate_(rate), t_end_(t_end) {}
  const char* name() const override { return "settling_damping"; }
  void addRates(FluidContext<D>& ctx) override {
    if (ctx.time >= t_end_) return;
    auto& f = ctx.fluid;
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < f.size(); ++i) f.dvdt[i] -= rate_ * f.v[i];
  }
  void advanceTo(double, StepStage) override {}

 private:
  double rate_, t_end_;
};

}  // namespace moorsph::fluid
