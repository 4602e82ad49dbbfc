#pragma once
// A Simbody Measure whose value is any function of the State, evaluated lazily and
// cached per State. Used with Measure::Integrate to accumulate the work of the
// external wrenches and the energy dissipated by line dampers as extra continuous
// state variables, so that the energy balance is integrated to the same accuracy as
// the motion itself (not sampled between coupling steps).
#include "simbody_include.hpp"

#include <functional>
#include <utility>

namespace moorsph::bodies::detail {

class StateFunctionMeasureImpl final : public SimTK::Measure_<SimTK::Real>::Implementation {
 public:
  using Function = std::function<double(const SimTK::State&)>;
  StateFunctionMeasureImpl(Function f, SimTK::Stage dependsOn)
      : SimTK::Measure_<SimTK::Real>::Implementation(0.0, 1), f_(std::move(f)), dependsOn_(dependsOn) {}

  StateFunctionMeasureImpl* cloneVirtual() const override { return new StateFunctionMeasureImpl(*this); }
  int getNumTimeDerivativesVirtual() const override { return 0; }
  SimTK::Stage getDependsOnStageVirtual(int) const override { return dependsOn_; }
  void calcCachedValueVirtual(const SimTK::State& s, int, SimTK::Real& value) const override { value = f_(s); }

 private:
  Function f_;
  SimTK::Stage dependsOn_;
};

// Handle class: only a derived handle may use the (protected) SetHandle constructor.
class StateFunctionMeasure final : public SimTK::Measure {
 public:
  StateFunctionMeasure(SimTK::Subsystem& sub, StateFunctionMeasureImpl* impl)
      : SimTK::Measure(sub, impl, SimTK::AbstractMeasure::SetHandle()) {}
};

inline SimTK::Measure makeStateFunctionMeasure(SimTK::Subsystem& sub, SimTK::Stage dependsOn,
                                               StateFunctionMeasureImpl::Function f) {
  return StateFunctionMeasure(sub, new StateFunctionMeasureImpl(std::move(f), dependsOn));
}

}  // namespace moorsph::bodies::detail
