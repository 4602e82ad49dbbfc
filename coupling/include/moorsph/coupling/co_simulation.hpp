#pragma once
// The fluid-body co-simulation (DESIGN.md section 2): owns the fluid, the multibody
// system and the "bodies" effect that exchanges wrenches and kinematics between them
// at every fluid step (see body_coupling.hpp for the order and where the lag sits).
// Reports wall time per side and an energy ledger.
#include <memory>
#include <moorsph/coupling/body_coupling.hpp>
#include <moorsph/fluid/fluid_simulation.hpp>

namespace moorsph::coupling {

/// Energy of the coupled system [J]. Fluid potential is sum(-m g.r); body terms come
/// from bodies::EnergyReport. `work_by_fluid_on_bodies` is the work done by the
/// coupling wrenches on the bodies since release. What the fluid loses to viscosity,
/// numerical damping and the wall-force potential is not itemised: it is the ledger's
/// balance, reported as the drift of total() from its initial value.
/// `fluid_outflow` is the energy carried out of the domain by spray the "outflow"
/// effect removed (fluid/outflow.hpp), so the total stays comparable after a removal.
struct EnergyLedger {
  double fluid_kinetic = 0.0, fluid_potential = 0.0, fluid_elastic = 0.0, fluid_outflow = 0.0;
  double body_kinetic = 0.0, body_potential = 0.0, line_elastic = 0.0, line_dissipated = 0.0;
  double work_by_fluid_on_bodies = 0.0;
  double total() const {
    return fluid_kinetic + fluid_potential + fluid_elastic + fluid_outflow + body_kinetic + body_potential +
           line_elastic + line_dissipated;
  }
};

template <int D>
class CoSimulation {
 public:
  /// The system must be initialized; the links name movable, reaction-tracking surfaces.
  CoSimulation(std::unique_ptr<fluid::FluidSimulation<D>> fluid, std::unique_ptr<bodies::MultibodySystem> bodies,
               std::vector<CoupledBody> links, CouplingOptions options);

  void step() { fluid_->step(); }
  void advanceTo(double t) { fluid_->advanceTo(t); }
  double time() const { return fluid_->time(); }

  const fluid::FluidSimulation<D>& fluid() const { return *fluid_; }
  fluid::FluidSimulation<D>& updFluid() { return *fluid_; }
  const bodies::MultibodySystem& bodies() const { return *bodies_; }
  const BodyCoupling<D>& coupling() const { return *coupling_; }

  EnergyLedger calcEnergy() const;
  /// Wall time [s]: fluid (its phase timers), bodies (Simbody steps), exchange
  /// (placing surfaces, summing wrenches).
  double fluidSeconds() const;
  double bodySeconds() const { return coupling_->bodySeconds(); }
  double exchangeSeconds() const { return coupling_->exchangeSeconds() - coupling_->bodySeconds(); }

 private:
  std::unique_ptr<fluid::FluidSimulation<D>> fluid_;
  std::unique_ptr<bodies::MultibodySystem> bodies_;
  BodyCoupling<D>* coupling_ = nullptr;  // owned by the fluid's effect list
};

}  // namespace moorsph::coupling
