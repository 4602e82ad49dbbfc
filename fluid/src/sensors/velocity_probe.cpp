#include <moorsph/fluid/velocity_probe.hpp>

#include <limits>
#include <stdexcept>
#include <moorsph/fluid/fluid_near_point.hpp>

namespace moorsph::fluid {

template <int D>
VelocityProbe<D>::VelocityProbe(VelocityProbeSpec<D> spec) : spec_(spec) {
  if (!(spec_.min_fill > 0.0 && spec_.min_fill < 1.0))
    throw std::invalid_argument("velocity probe: min_fill must lie in (0, 1)");
}

template <int D>
Vec<D> VelocityProbe<D>::read(const FluidSimulation<D>& sim) const {
  const FluidParticles<D>& f = sim.fluid();
  Vec<D> weighted = Vec<D>::Zero();
  double fill = 0.0;
  forEachFluidNear(sim, spec_.point, [&](std::size_t j, double w) {
    weighted += w * f.v[j];
    fill += w;
  });
  if (fill < spec_.min_fill) return Vec<D>::Constant(std::numeric_limits<double>::quiet_NaN());
  return weighted / fill;
}

template class VelocityProbe<2>;
template class VelocityProbe<3>;

}  // namespace moorsph::fluid
