#pragma once
// Settling for the still-water case: dv/dt += -k v on every fluid particle until
// t_end, then nothing. A lattice start is not in equilibrium with the wall force law
// (the layer next to a side wall sits at half a spacing, inside the force's range,
// where no hydrostatic pressure balances it near the surface), so the first steps
// push it off the walls and fill the tank with acoustic noise that the method damps
// only slowly (rms 0.06 m/s at 0.25 s, e-folding about 6 s). Damping it out first
// isolates what the stability case asks: whether the method itself, left alone from
// a settled state, drives currents or drift. k dt << 1 keeps the step stable.
#include <moorsph/fluid/fluid_effect.hpp>

namespace moorsph::stability {

template <int D>
class Settling final : public fluid::FluidEffect<D> {
 public:
  Settling(double rate, double t_end) : rate_(rate), t_end_(t_end) {}
  const char* name() const override { return "settling"; }
  void addRates(fluid::FluidContext<D>& ctx) override {
    if (ctx.time >= t_end_) return;
    auto& f = ctx.fluid;
    for (std::size_t i = 0; i < f.size(); ++i) f.dvdt[i] -= rate_ * f.v[i];
  }
  void advanceTo(double, fluid::StepStage) override {}

 private:
  double rate_, t_end_;
};

}  // namespace moorsph::stability
