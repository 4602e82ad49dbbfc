// MultibodySystem::snapshot()/restore(): the State as plain data and back.
#include "system_core.hpp"

namespace moorsph::bodies {

using detail::speedIndex;

struct MultibodySystem::Impl : SystemCore {
  using SystemCore::SystemCore;
};

SystemSnapshot MultibodySystem::snapshot() const {
  const Impl& m = *impl_;
  if (!m.initialized) throw std::logic_error("MultibodySystem::snapshot before initialize()");
  const SimTK::State& s = m.state();
  m.system.realize(s, SimTK::Stage::Acceleration);
  SystemSnapshot out;
  out.time = s.getTime();
  for (int b = 0; b < bodyCount(); ++b) {
    out.bodies.push_back(kinematics(b));
    out.wrenches.push_back(externalWrench(b));
  }
  for (const LineEntry& line : m.lines) {
    LineSnapshot l;
    l.broken = line.broken;
    l.breakTime = line.breakTime;
    l.breakTension = line.breakTension;
    if (line.cable) l.cableDissipated = line.spring.getDissipatedEnergy(s);
    l.internalState = line.model->saveState();
    out.lines.push_back(std::move(l));
  }
  out.dissipated = m.dissipatedEnergy.getValue(s);
  out.externalWork = m.externalWork.getValue(s);
  return out;
}

void MultibodySystem::restore(const SystemSnapshot& snap) {
  Impl& m = *impl_;
  if (!m.initialized) throw std::logic_error("MultibodySystem::restore before initialize()");
  if (snap.bodies.size() != m.specs.size() || snap.wrenches.size() != m.specs.size() ||
      snap.lines.size() != m.lines.size()) {
    throw std::invalid_argument("MultibodySystem::restore: snapshot has a different number of bodies or lines");
  }
  SimTK::State s = m.integ->getState();
  s.setTime(snap.time);
  for (std::size_t b = 0; b < m.specs.size(); ++b) {
    const BodyKinematics& k = snap.bodies[b];
    m.mobods[b].setQToFitTransform(s, SimTK::Transform(toSimTK(k.orientation), toSimTK(k.position)));
  }
  m.system.realize(s, SimTK::Stage::Position);
  for (std::size_t b = 0; b < m.specs.size(); ++b) {
    const BodyKinematics& k = snap.bodies[b];
    m.mobods[b].setUToFitVelocity(s, SimTK::SpatialVec(toSimTK(k.angularVelocity), toSimTK(k.velocity)));
    for (int d = 0; d < 6; ++d) {
      const int u = speedIndex(m.specs[b].mobilizer, static_cast<Dof>(d));
      if (m.specs[b].fixedDofs[d] && u >= 0) m.mobods[b].setOneU(s, SimTK::MobilizerUIndex(u), 0.0);
    }
    const BodyWrench& w = snap.wrenches[b];
    m.pendingWrenches[b] = w;
    m.external.setOneBodyForce(s, m.mobods[b], SimTK::SpatialVec(toSimTK(w.torque), toSimTK(w.force)));
  }
  for (std::size_t i = 0; i < m.lines.size(); ++i) {
    LineEntry& line = m.lines[i];
    const LineSnapshot& l = snap.lines[i];
    line.broken = l.broken;
    line.breakTime = l.breakTime;
    line.breakTension = l.breakTension;
    if (line.forceIndex.isValid()) {
      const SimTK::Force& force = m.forces.getForce(line.forceIndex);
      if (l.broken) {
        force.disable(s);
      } else {
        force.enable(s);
      }
    }
    if (!l.internalState.empty()) {
      line.model->restoreState(l.internalState);
    } else if (!line.cable) {
      m.system.realize(s, SimTK::Stage::Velocity);  // the ends' restored positions and speeds
      line.model->startWithoutSavedState(m.endsOf(s, line, true), snap.time);
    }
  }
  detail::StdoutCapture capture;  // a CablePath prints again on initialisation
  m.integ->initialize(s);
  m.capturedOutput += capture.finish();
  // Integrals are reset to their initial conditions by initialize(): set them after.
  SimTK::State& adv = m.integ->updAdvancedState();
  m.dissipatedEnergy.setValue(adv, snap.dissipated);
  m.externalWork.setValue(adv, snap.externalWork);
  for (std::size_t i = 0; i < m.lines.size(); ++i) {
    if (m.lines[i].cable) m.lines[i].spring.setDissipatedEnergy(adv, snap.lines[i].cableDissipated);
  }
  m.integ->reinitialize(SimTK::Stage::Position, false);
  if (m.anyDynamic) m.exchangeDynamicLineForces();
}

}  // namespace moorsph::bodies
