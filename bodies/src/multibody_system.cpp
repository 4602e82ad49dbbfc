// Public API of MultibodySystem (multibody_system.hpp) over SystemCore.
#include "system_core.hpp"

namespace moorsph::bodies {

using detail::speedIndex;

struct MultibodySystem::Impl : SystemCore {
  using SystemCore::SystemCore;
};

MultibodySystem::MultibodySystem(const SystemOptions& options) : impl_(std::make_unique<Impl>(options)) {
  if (!(options.maxStep > 0.0) || !(options.accuracy > 0.0) || !(options.lineSyncStep > 0.0)) {
    throw std::invalid_argument("SystemOptions: maxStep, accuracy and lineSyncStep must be > 0");
  }
}
MultibodySystem::~MultibodySystem() = default;
MultibodySystem::MultibodySystem(MultibodySystem&&) noexcept = default;
MultibodySystem& MultibodySystem::operator=(MultibodySystem&&) noexcept = default;

int MultibodySystem::addBody(const RigidBodySpec& spec) {
  if (impl_->initialized) throw std::logic_error("MultibodySystem::addBody after initialize()");
  impl_->specs.push_back(spec);
  impl_->pendingWrenches.emplace_back();
  return static_cast<int>(impl_->specs.size()) - 1;
}

int MultibodySystem::addLine(const std::string& name, const LineAttachment& where,
                             std::unique_ptr<MooringLine> model) {
  if (impl_->initialized) throw std::logic_error("MultibodySystem::addLine after initialize()");
  if (!model) throw std::invalid_argument("MultibodySystem::addLine: null model");
  LineEntry entry;
  entry.name = name;
  entry.where = where;
  entry.model = std::move(model);
  impl_->lines.push_back(std::move(entry));
  return static_cast<int>(impl_->lines.size()) - 1;
}

void MultibodySystem::initialize() {
  if (impl_->initialized) throw std::logic_error("MultibodySystem::initialize called twice");
  impl_->build();
}
bool MultibodySystem::isInitialized() const { return impl_->initialized; }

double MultibodySystem::time() const { return impl_->initialized ? impl_->integ->getTime() : 0.0; }

void MultibodySystem::setExternalWrench(int body, const BodyWrench& wrench) {
  Impl& m = *impl_;
  m.pendingWrenches.at(body) = wrench;
  if (!m.initialized) return;
  m.external.setOneBodyForce(m.integ->updAdvancedState(), m.mobods.at(body),
                             SimTK::SpatialVec(toSimTK(wrench.torque), toSimTK(wrench.force)));
  // A discrete variable changed: the integrator must drop what it cached.
  m.integ->reinitialize(SimTK::Stage::Dynamics, false);
}

BodyWrench MultibodySystem::externalWrench(int body) const {
  if (!impl_->initialized) return impl_->pendingWrenches.at(body);
  const SimTK::SpatialVec& w =
      impl_->external.getAllBodyForces(impl_->state())[impl_->mobods.at(body).getMobilizedBodyIndex()];
  BodyWrench out;
  out.torque = toEigen(w[0]);
  out.force = toEigen(w[1]);
  return out;
}

void MultibodySystem::advanceTo(double t) {
  if (!impl_->initialized) throw std::logic_error("MultibodySystem::advanceTo before initialize()");
  impl_->advanceTo(t);
}

int MultibodySystem::bodyCount() const { return static_cast<int>(impl_->specs.size()); }
int MultibodySystem::lineCount() const { return static_cast<int>(impl_->lines.size()); }
const MooringLine& MultibodySystem::line(int index) const { return *impl_->lines.at(index).model; }
long MultibodySystem::internalStepCount() const {
  return impl_->initialized ? static_cast<long>(impl_->integ->getNumStepsTaken()) : 0L;
}

const std::string& MultibodySystem::capturedSimbodyOutput() const { return impl_->capturedOutput; }

BodyKinematics MultibodySystem::kinematics(int body) const {
  const Impl& m = *impl_;
  if (!m.initialized) return m.specs.at(body).initial;
  const SimTK::State& s = m.state();
  m.system.realize(s, SimTK::Stage::Acceleration);
  const SimTK::MobilizedBody& mb = m.mobods.at(body);
  BodyKinematics k;
  k.position = toEigen(mb.getBodyOriginLocation(s));
  k.orientation = toEigen(mb.getBodyRotation(s));
  k.velocity = toEigen(mb.getBodyOriginVelocity(s));
  k.angularVelocity = toEigen(mb.getBodyAngularVelocity(s));
  k.acceleration = toEigen(mb.getBodyOriginAcceleration(s));
  k.angularAcceleration = toEigen(mb.getBodyAngularAcceleration(s));
  return k;
}

MassReport MultibodySystem::massProperties(int body) const {
  const Impl& m = *impl_;
  if (!m.initialized) throw std::logic_error("MultibodySystem::massProperties before initialize()");
  const SimTK::MassProperties mp = m.mobods.at(body).getBodyMassProperties(m.state());
  MassReport r;
  r.mass = mp.getMass();
  r.centreOfMass = toEigen(mp.getMassCenter());
  const SimTK::Mat33 i = mp.getInertia().shiftToMassCenter(mp.getMassCenter(), mp.getMass()).toMat33();
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) r.inertiaAboutCom(a, b) = i(a, b);
  return r;
}

int MultibodySystem::mobilityCount(int body) const {
  if (!impl_->initialized) throw std::logic_error("MultibodySystem::mobilityCount before initialize()");
  return impl_->mobods.at(body).getNumU(impl_->state());
}

int MultibodySystem::unlockedMobilityCount(int body) const {
  int fixed = 0;
  const RigidBodySpec& spec = impl_->specs.at(body);
  for (int d = 0; d < 6; ++d) fixed += (spec.fixedDofs[d] && speedIndex(spec.mobilizer, static_cast<Dof>(d)) >= 0);
  return mobilityCount(body) - fixed;
}

EnergyReport MultibodySystem::energy() const {
  const Impl& m = *impl_;
  if (!m.initialized) throw std::logic_error("MultibodySystem::energy before initialize()");
  const SimTK::State& s = m.state();
  m.system.realize(s, SimTK::Stage::Acceleration);
  EnergyReport e;
  e.kinetic = m.system.calcKineticEnergy(s);
  e.gravitational = m.gravity->calcPotentialEnergyContribution(s);
  e.dissipated = m.dissipatedEnergy.getValue(s);
  for (const LineEntry& line : m.lines) {
    if (line.cable) {
      // Simbody integrates the CableSpring's own dissipation.
      e.dissipated += line.spring.getDissipatedEnergy(s);
      if (!line.broken) e.lineElastic += line.spring.getPotentialEnergy(s);
      continue;
    }
    if (line.broken) continue;
    e.lineElastic += line.model->calcPotentialEnergy(m.endsOf(s, line, false));
  }
  e.externalWork = m.externalWork.getValue(s);
  return e;
}

LineDiagnostics MultibodySystem::lineDiagnostics(int index, bool withShape) const {
  const Impl& m = *impl_;
  if (!m.initialized) throw std::logic_error("MultibodySystem::lineDiagnostics before initialize()");
  const LineEntry& line = m.lines.at(index);
  const SimTK::State& s = m.state();
  m.system.realize(s, SimTK::Stage::Velocity);
  const LineEnds ends = m.endsOf(s, line, true);
  LineDiagnostics d;
  d.name = line.name;
  d.model = line.model->modelName();
  d.broken = line.broken;
  d.breakTime = line.breakTime;
  d.breakTension = line.breakTension;
  if (!line.broken) {
    const LineForces f = m.lineForces(s, line);
    d.fairleadTension = f.fairleadTension;
    d.anchorTension = f.anchorTension;
    d.forceOnFairlead = f.onFairlead;
    d.forceOnAnchor = f.onAnchor;
    d.slack = f.slack;
  } else {
    d.slack = true;
  }
  if (withShape && !line.broken) d.shape = line.cable ? m.cablePoints(s, line) : line.model->calcShape(ends);
  return d;
}

}  // namespace moorsph::bodies
