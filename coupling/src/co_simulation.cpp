#include <moorsph/coupling/co_simulation.hpp>

#include <numeric>

namespace moorsph::coupling {

template <int D>
CoSimulation<D>::CoSimulation(std::unique_ptr<fluid::FluidSimulation<D>> fluid,
                              std::unique_ptr<bodies::MultibodySystem> bodies, std::vector<CoupledBody> links,
                              CouplingOptions options)
    : fluid_(std::move(fluid)), bodies_(std::move(bodies)) {
  auto effect = std::make_unique<BodyCoupling<D>>(*bodies_, fluid_->updWalls(), std::move(links), options);
  coupling_ = effect.get();
  coupling_->useFluidSetup(fluid_->setup());
  fluid_->addEffect(std::move(effect));
}

template <int D>
EnergyLedger CoSimulation<D>::calcEnergy() const {
  const fluid::FluidEnergy f = fluid_->calcEnergy();
  const bodies::EnergyReport b = bodies_->energy();
  EnergyLedger e;
  e.fluid_kinetic = f.kinetic;
  e.fluid_potential = f.potential;
  e.fluid_elastic = f.elastic;
  if (const auto* outflow = fluid_->outflow()) e.fluid_outflow = outflow->tally().energy;
  e.body_kinetic = b.kinetic;
  e.body_potential = b.gravitational;
  e.line_elastic = b.lineElastic;
  e.line_dissipated = b.dissipated;
  e.work_by_fluid_on_bodies = b.externalWork;
  return e;
}

template <int D>
double CoSimulation<D>::fluidSeconds() const {
  const auto& s = fluid_->phaseTimers().seconds();
  return std::accumulate(s.begin(), s.end(), 0.0);  // the exchange runs outside these phases
}

template class CoSimulation<2>;
template class CoSimulation<3>;

}  // namespace moorsph::coupling
