// Building and stepping the Simbody system behind MultibodySystem.
#include "system_core.hpp"

#include <algorithm>

namespace moorsph::bodies {

using detail::speedIndex;


// Force element applying one quasi-static mooring model between two stations.
class LineForceElement final : public SimTK::Force::Custom::Implementation {
 public:
  LineForceElement(const SystemCore& sys, std::size_t index) : sys_(sys), index_(index) {}

  void calcForce(const SimTK::State& s, SimTK::Vector_<SimTK::SpatialVec>& bodyForces,
                 SimTK::Vector_<SimTK::Vec3>&, SimTK::Vector&) const override {
    const LineEntry& line = sys_.lines[index_];
    const LineForces f = line.model->calcForces(sys_.endsOf(s, line, true));
    sys_.mobods[line.where.fairleadBody].applyForceToBodyPoint(
        s, toSimTK(line.where.fairleadPoint), toSimTK(f.onFairlead), bodyForces);
    if (line.where.anchorBody != LineAttachment::kGround) {
      sys_.mobods[line.where.anchorBody].applyForceToBodyPoint(
          s, toSimTK(line.where.anchorPoint), toSimTK(f.onAnchor), bodyForces);
    }
  }
  SimTK::Real calcPotentialEnergy(const SimTK::State& s) const override {
    const LineEntry& line = sys_.lines[index_];
    return line.model->calcPotentialEnergy(sys_.endsOf(s, line, false));
  }

 private:
  const SystemCore& sys_;
  std::size_t index_;
};

// cable_path: Simbody CablePath from the fairlead (origin) through the via points to
// the anchor (termination), tensioned by a CableSpring. A pretension is resolved here
// from the initial poses because the slack length is a topology-stage parameter.
void SystemCore::buildCable(LineEntry& line) {
  if (!cables) cables = std::make_unique<SimTK::CableTrackerSubsystem>(system);
  auto mobodOf = [&](int body) -> const SimTK::MobilizedBody& {
    return body == LineAttachment::kGround ? static_cast<const SimTK::MobilizedBody&>(matter.Ground()) : mobods.at(body);
  };
  auto initialGround = [&](int body, const Eigen::Vector3d& point) -> Eigen::Vector3d {
    if (body == LineAttachment::kGround) return point;
    return specs.at(body).initial.pointToGround(point);
  };
  SimTK::CablePath path(*cables, mobodOf(line.where.fairleadBody), toSimTK(line.where.fairleadPoint),
                        mobodOf(line.where.anchorBody), toSimTK(line.where.anchorPoint));
  std::vector<Eigen::Vector3d> pts{initialGround(line.where.fairleadBody, line.where.fairleadPoint)};
  for (const CableViaPoint& via : line.cable->params().viaPoints) {
    if (via.body < LineAttachment::kGround || via.body >= static_cast<int>(specs.size())) {
      throw std::invalid_argument("line '" + line.name + "': via point body index out of range");
    }
    SimTK::CableObstacle::ViaPoint(path, mobodOf(via.body), toSimTK(via.point));
    pts.push_back(initialGround(via.body, via.point));
  }
  pts.push_back(initialGround(line.where.anchorBody, line.where.anchorPoint));
  double length = 0.0;
  for (std::size_t i = 1; i < pts.size(); ++i) length += (pts[i] - pts[i - 1]).norm();
  line.cable->resolveRestLength(length);
  const CablePathParams& p = line.cable->params();
  line.spring = SimTK::CableSpring(forces, path, p.stiffness, p.restLength, p.dissipation);
  line.forceIndex = line.spring.getForceIndex();
}

void SystemCore::build() {
  if (specs.empty()) throw std::logic_error("MultibodySystem: no bodies added");
  gravity = std::make_unique<SimTK::Force::Gravity>(forces, matter, toSimTK(options.gravity).norm() > 0
                                                                       ? SimTK::UnitVec3(toSimTK(options.gravity))
                                                                       : SimTK::UnitVec3(0, -1, 0),
                                                    options.gravity.norm());
  for (const RigidBodySpec& spec : specs) {
    if (!(spec.mass > 0.0)) throw std::invalid_argument("body '" + spec.name + "': mass must be > 0 kg");
    // Inertia is in kg m^2 about the centre of mass; Simbody wants it about the body
    // origin. Using UnitInertia here would multiply by the mass a second time.
    const SimTK::Mat33 iCom(spec.inertiaAboutCom(0, 0), spec.inertiaAboutCom(0, 1), spec.inertiaAboutCom(0, 2),
                            spec.inertiaAboutCom(1, 0), spec.inertiaAboutCom(1, 1), spec.inertiaAboutCom(1, 2),
                            spec.inertiaAboutCom(2, 0), spec.inertiaAboutCom(2, 1), spec.inertiaAboutCom(2, 2));
    const SimTK::Vec3 com = toSimTK(spec.centreOfMass);
    const SimTK::Inertia inertiaOrigin = SimTK::Inertia(iCom).shiftFromMassCenter(com, spec.mass);
    SimTK::Body::Rigid body(SimTK::MassProperties(spec.mass, com, inertiaOrigin));
    if (spec.mobilizer == Mobilizer::Free) {
      mobods.push_back(SimTK::MobilizedBody::Free(matter.Ground(), SimTK::Transform(), body, SimTK::Transform()));
    } else {
      mobods.push_back(SimTK::MobilizedBody::Planar(matter.Ground(), SimTK::Transform(), body, SimTK::Transform()));
    }
    for (int d = 0; d < 6; ++d) {
      if (!spec.fixedDofs[d]) continue;
      const int u = speedIndex(spec.mobilizer, static_cast<Dof>(d));
      if (u >= 0) SimTK::Constraint::ConstantSpeed(mobods.back(), SimTK::MobilizerUIndex(u), 0.0);
    }
  }
  for (std::size_t i = 0; i < lines.size(); ++i) {
    LineEntry& line = lines[i];
    if (line.where.fairleadBody < 0 || line.where.fairleadBody >= static_cast<int>(specs.size()) ||
        line.where.anchorBody >= static_cast<int>(specs.size()) || line.where.anchorBody < LineAttachment::kGround) {
      throw std::invalid_argument("line '" + line.name + "': attachment body index out of range");
    }
    line.cable = dynamic_cast<CablePathLine*>(line.model.get());
    if (line.cable) {
      buildCable(line);
    } else if (line.model->isDynamic()) {
      anyDynamic = true;
    } else {
      SimTK::Force::Custom element(forces, new LineForceElement(*this, i));
      line.forceIndex = element.getForceIndex();
    }
    anyBreakable = anyBreakable || std::isfinite(line.model->breakingLoad());
  }
  const SimTK::Measure dissipation = detail::makeStateFunctionMeasure(
      forces, SimTK::Stage::Dynamics, [this](const SimTK::State& s) { return dissipationPower(s); });
  const SimTK::Measure power = detail::makeStateFunctionMeasure(
      forces, SimTK::Stage::Dynamics, [this](const SimTK::State& s) { return externalPower(s); });
  dissipatedEnergy = SimTK::Measure::Integrate(forces, dissipation, SimTK::Measure::Zero(forces));
  externalWork = SimTK::Measure::Integrate(forces, power, SimTK::Measure::Zero(forces));

  detail::StdoutCapture capture;  // CablePath's diagnostics (DESIGN.md 3)
  SimTK::State s = system.realizeTopology();
  for (std::size_t b = 0; b < specs.size(); ++b) {
    const BodyKinematics& k = specs[b].initial;
    mobods[b].setQToFitTransform(s, SimTK::Transform(toSimTK(k.orientation), toSimTK(k.position)));
  }
  system.realize(s, SimTK::Stage::Position);
  for (std::size_t b = 0; b < specs.size(); ++b) {
    const BodyKinematics& k = specs[b].initial;
    mobods[b].setUToFitVelocity(s, SimTK::SpatialVec(toSimTK(k.angularVelocity), toSimTK(k.velocity)));
    for (int d = 0; d < 6; ++d) {
      const int u = speedIndex(specs[b].mobilizer, static_cast<Dof>(d));
      if (specs[b].fixedDofs[d] && u >= 0) mobods[b].setOneU(s, SimTK::MobilizerUIndex(u), 0.0);
    }
    const BodyWrench& w = pendingWrenches[b];
    external.setOneBodyForce(s, mobods[b], SimTK::SpatialVec(toSimTK(w.torque), toSimTK(w.force)));
  }
  system.realize(s, SimTK::Stage::Velocity);
  // Lines resolve pretension and initial shape from the initial pose, before the
  // first force evaluation.
  for (LineEntry& line : lines) {
    if (!line.cable) line.model->initialize(endsOf(s, line, true));
  }

  integ = std::make_unique<SimTK::RungeKuttaMersonIntegrator>(system);
  // Settings must precede initialize() (DESIGN.md 3).
  integ->setAccuracy(options.accuracy);
  integ->setMaximumStepSize(options.maxStep);
  integ->setAllowInterpolation(false);  // the advanced state is always at the reported time
  integ->setReturnEveryInternalStep(anyBreakable);
  // stepTo() returns (ReachedStepLimit) after this many steps, so stepTo() below can
  // bound the work of one advance (see there).
  integ->setInternalStepLimit(kStepsPerReturn);
  integ->initialize(s);
  capturedOutput = capture.finish();
  initialized = true;
  if (anyDynamic) exchangeDynamicLineForces();
}

// Writes the current fairlead forces of the dynamic lines into their DiscreteForces
// element (held in the State, so Simbody never sees a stale value).
void SystemCore::exchangeDynamicLineForces() {
  SimTK::State& s = integ->updAdvancedState();
  system.realize(s, SimTK::Stage::Velocity);
  SimTK::Vector_<SimTK::SpatialVec> all(matter.getNumBodies(), SimTK::SpatialVec(SimTK::Vec3(0), SimTK::Vec3(0)));
  for (const LineEntry& line : lines) {
    if (!line.model->isDynamic() || line.broken) continue;
    const LineForces f = line.model->calcForces(endsOf(s, line, true));
    auto applyAt = [&](int body, const Eigen::Vector3d& point, const Eigen::Vector3d& force) {
      if (body == LineAttachment::kGround) return;
      const SimTK::MobilizedBody& mb = mobods[body];
      const SimTK::Vec3 arm = mb.getBodyRotation(s) * toSimTK(point);
      SimTK::SpatialVec& w = all[mb.getMobilizedBodyIndex()];
      w[0] += arm % toSimTK(force);
      w[1] += toSimTK(force);
    };
    applyAt(line.where.fairleadBody, line.where.fairleadPoint, f.onFairlead);
    applyAt(line.where.anchorBody, line.where.anchorPoint, f.onAnchor);
  }
  dynamicLineForces.setAllBodyForces(s, all);
  integ->reinitialize(SimTK::Stage::Dynamics, false);
}

void SystemCore::checkBreaks() {
  for (LineEntry& line : lines) {
    if (line.broken || !std::isfinite(line.model->breakingLoad())) continue;
    const SimTK::State& s = integ->getState();
    const LineForces f = lineForces(s, line);
    const double tension = std::max(f.fairleadTension, f.anchorTension);
    if (tension > line.model->breakingLoad()) {
      // The first internal step ending above the load: the crossing lies within it.
      line.broken = true;
      line.breakTime = s.getTime();
      line.breakTension = tension;
      if (line.forceIndex.isValid()) {
        // Disabling the force element is an Instance-stage change held in the State.
        forces.getForce(line.forceIndex).disable(integ->updAdvancedState());
        integ->reinitialize(SimTK::Stage::Instance, false);
      }
    }
  }
}

// Bounded work. With forces of a physical size the error-controlled integrator takes
// about (t - t0)/maxStep steps: the ship of METHOD.md 6.5 under its fluid wrench, held
// constant per fluid step, takes 18 steps per 0.017 s step at maxStep = 1 ms
// (tests/bodies/heavy_body_wrench_test.cpp). A wrench out of all scale (a fluid
// particle in the wall law's singular range gave 5e23 N on the 5e7 kg ship,
// docs/validation/ship.md finding 2) makes the body spin at ~1e15 rad/s^2, and the
// error control then shrinks the step without end: the run hung inside Simbody.
// Allowing kStepBudgetFactor times the nominal count (plus a fixed allowance for the
// start after each wrench change) turns that into an error naming the forces.
void SystemCore::throwIfOverBudget(double t0, double t, long steps0) const {
  const double span = t - t0;
  const double nominal = std::ceil(span / options.maxStep);
  const double budget = kStepBudgetFactor * nominal + kStepBudgetAllowance;
  const long used = static_cast<long>(integ->getNumStepsAttempted()) - steps0;
  if (static_cast<double>(used) <= budget) return;
  std::ostringstream msg;
  msg << "MultibodySystem: the body integrator attempted " << used << " steps and reached t = " << integ->getTime()
      << " s of the advance from " << t0 << " s to " << t << " s (nominal " << nominal
      << " steps of at most " << options.maxStep << " s, last step " << integ->getPreviousStepSizeTaken()
      << " s): the forces on the bodies are out of scale.";
  const SimTK::State& s = integ->getState();
  const SimTK::Vector_<SimTK::SpatialVec>& all = external.getAllBodyForces(s);
  for (std::size_t b = 0; b < specs.size(); ++b) {
    const SimTK::SpatialVec& w = all[mobods[b].getMobilizedBodyIndex()];
    msg << " Body '" << specs[b].name << "' (" << specs[b].mass << " kg, weight " << specs[b].mass * options.gravity.norm()
        << " N): external force " << w[1].norm() << " N, torque " << w[0].norm() << " N m.";
  }
  msg << " Check the fluid force (a fluid particle deep in a wall's force law?) and the mooring stiffness.";
  throw std::runtime_error(msg.str());
}

void SystemCore::stepTo(double t) {
  // After initialize()/reinitialize() the first stepTo() may return without advancing
  // (StartOfContinuousInterval), and with setReturnEveryInternalStep it returns after
  // each step: loop until the target is really reached. Passing t as the scheduled
  // event time keeps the integrator from stepping past it.
  const double tolerance = 1e-12 * std::max(1.0, std::abs(t));
  const double t0 = integ->getTime();
  const long attempts0 = static_cast<long>(integ->getNumStepsAttempted());
  int stalls = 0;
  while (integ->getTime() < t - tolerance) {
    throwIfOverBudget(t0, t, attempts0);
    const double before = integ->getTime();
    const SimTK::Integrator::SuccessfulStepStatus status = integ->stepTo(t, t);
    if (status == SimTK::Integrator::EndOfSimulation) {
      std::ostringstream msg;
      msg << "MultibodySystem: integrator ended the simulation at t = " << integ->getTime()
          << " s (" << integ->getTerminationReasonString(integ->getTerminationReason()) << ")";
      throw std::runtime_error(msg.str());
    }
    if (anyBreakable) checkBreaks();
    stalls = integ->getTime() > before ? 0 : stalls + 1;
    if (stalls > 10) throw std::runtime_error("MultibodySystem: integrator does not advance");
  }
}

// Without dynamic lines: one integrator run to t. With them: exchange intervals of
// lineSyncStep; hold the lines' forces, advance the bodies, then advance the lines with
// their ends moving linearly between the bodies' poses (explicit staggering).
void SystemCore::advanceTo(double t) {
  if (t < integ->getTime() - 1e-12) throw std::invalid_argument("MultibodySystem::advanceTo: time goes backwards");
  if (!anyDynamic) {
    stepTo(t);
    return;
  }
  while (integ->getTime() < t - 1e-12 * std::max(1.0, std::abs(t))) {
    const double t0 = integ->getTime();
    const double t1 = std::min(t, t0 + options.lineSyncStep);
    std::vector<LineEnds> start;
    for (const LineEntry& line : lines) start.push_back(endsOf(integ->getState(), line, true));
    stepTo(t1);
    system.realize(integ->getState(), SimTK::Stage::Velocity);
    for (std::size_t i = 0; i < lines.size(); ++i) {
      LineEntry& line = lines[i];
      if (!line.model->isDynamic() || line.broken) continue;
      line.model->advance(t1 - t0, start[i], endsOf(integ->getState(), line, true));
      // The line tested its load after each of its sub-steps and stopped at the first
      // one above it; the bodies stop feeling it from this exchange (t1) on.
      const MooringLine::Exceedance& e = line.model->lastExceedance();
      if (std::isfinite(e.timeIntoAdvance)) {
        line.broken = true;
        line.breakTime = t0 + e.timeIntoAdvance;
        line.breakTension = e.tension;
      }
    }
    exchangeDynamicLineForces();
  }
}

}  // namespace moorsph::bodies
