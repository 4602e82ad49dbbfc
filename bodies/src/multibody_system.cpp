// Simbody implementation of MultibodySystem. See multibody_system.hpp for the
// contract; the Simbody facts it relies on are DESIGN.md section 3.
#include "simbody_include.hpp"

#include "system_measures.hpp"

#include <moorsph/bodies/cable_path.hpp>
#include <moorsph/bodies/multibody_system.hpp>

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <iostream>
#include <sstream>
#include <stdexcept>

namespace moorsph::bodies {

using detail::toEigen;
using detail::toSimTK;

namespace {

// Generalized-speed index of a ground-frame DOF for each mobilizer, or -1 when the
// mobilizer does not have it. Free: u = [w_x w_y w_z v_x v_y v_z] (angular velocity and
// origin velocity in the parent = ground frame). Planar: u = [w_z v_x v_y].
int speedIndex(Mobilizer mobilizer, Dof dof) {
  const int d = static_cast<int>(dof);
  if (mobilizer == Mobilizer::Free) {
    return d >= 3 ? d - 3 : d + 3;
  }
  switch (dof) {
    case Dof::RotationZ: return 0;
    case Dof::TranslationX: return 1;
    case Dof::TranslationY: return 2;
    default: return -1;
  }
}

// Redirects the process's stdout (fd 1) into a temporary file while alive: Simbody 3.7's
// CablePath prints its internal diagnostics there during realizeTopology() and
// integrator initialisation. Not thread safe: nothing else should print meanwhile.
class StdoutCapture {
 public:
  StdoutCapture() {
    std::cout.flush();
    std::fflush(stdout);
    file_ = std::tmpfile();
    saved_ = file_ ? ::dup(1) : -1;
    if (saved_ >= 0) ::dup2(::fileno(file_), 1);
  }
  std::string finish() {
    std::string text;
    if (saved_ < 0) return text;
    std::cout.flush();
    std::fflush(stdout);
    ::dup2(saved_, 1);
    ::close(saved_);
    saved_ = -1;
    std::rewind(file_);
    char buffer[4096];
    std::size_t n;
    while ((n = std::fread(buffer, 1, sizeof buffer, file_)) > 0) text.append(buffer, n);
    std::fclose(file_);
    file_ = nullptr;
    return text;
  }
  ~StdoutCapture() { finish(); }
  StdoutCapture(const StdoutCapture&) = delete;
  StdoutCapture& operator=(const StdoutCapture&) = delete;

 private:
  std::FILE* file_ = nullptr;
  int saved_ = -1;
};

}  // namespace

struct LineEntry {
  std::string name;
  LineAttachment where;
  std::unique_ptr<MooringLine> model;
  SimTK::ForceIndex forceIndex;  // invalid for dynamic lines
  CablePathLine* cable = nullptr;  // set for cable_path lines (Simbody CableSpring)
  SimTK::CableSpring spring;
  bool broken = false;
  double breakTime = std::numeric_limits<double>::quiet_NaN();
};

// All Simbody-side state. A namespace-scope struct (rather than the private Impl
// itself) so that the force element below may refer to it.
struct SystemCore {
  SystemOptions options;
  std::vector<RigidBodySpec> specs;
  std::vector<BodyWrench> pendingWrenches;
  std::vector<LineEntry> lines;

  SimTK::MultibodySystem system;
  SimTK::SimbodyMatterSubsystem matter{system};
  SimTK::GeneralForceSubsystem forces{system};
  std::vector<SimTK::MobilizedBody> mobods;
  SimTK::Force::DiscreteForces external{forces, matter};
  SimTK::Force::DiscreteForces dynamicLineForces{forces, matter};
  SimTK::Measure dissipatedEnergy;
  SimTK::Measure externalWork;
  std::unique_ptr<SimTK::Force::Gravity> gravity;
  std::unique_ptr<SimTK::CableTrackerSubsystem> cables;  // only when a cable_path exists
  std::string capturedOutput;
  std::unique_ptr<SimTK::Integrator> integ;
  bool initialized = false;
  bool anyBreakable = false;
  bool anyDynamic = false;

  explicit SystemCore(const SystemOptions& o) : options(o) {}

  const SimTK::State& state() const { return integ->getState(); }

  // Ground-frame end positions (and velocities when the state is realized far enough).
  LineEnds endsOf(const SimTK::State& s, const LineEntry& line, bool withVelocity) const {
    LineEnds e;
    const SimTK::MobilizedBody& fb = mobods.at(line.where.fairleadBody);
    const SimTK::Vec3 fp = toSimTK(line.where.fairleadPoint);
    e.fairlead = toEigen(fb.findStationLocationInGround(s, fp));
    if (withVelocity) e.fairleadVelocity = toEigen(fb.findStationVelocityInGround(s, fp));
    if (line.where.anchorBody == LineAttachment::kGround) {
      e.anchor = line.where.anchorPoint;
    } else {
      const SimTK::MobilizedBody& ab = mobods.at(line.where.anchorBody);
      const SimTK::Vec3 ap = toSimTK(line.where.anchorPoint);
      e.anchor = toEigen(ab.findStationLocationInGround(s, ap));
      if (withVelocity) e.anchorVelocity = toEigen(ab.findStationVelocityInGround(s, ap));
    }
    return e;
  }

  Eigen::Vector3d stationInGround(const SimTK::State& s, int body, const Eigen::Vector3d& point) const {
    if (body == LineAttachment::kGround) return point;
    return toEigen(mobods.at(body).findStationLocationInGround(s, toSimTK(point)));
  }

  // Ground path of a cable_path line: fairlead, via points, anchor.
  std::vector<Eigen::Vector3d> cablePoints(const SimTK::State& s, const LineEntry& line) const {
    std::vector<Eigen::Vector3d> pts{stationInGround(s, line.where.fairleadBody, line.where.fairleadPoint)};
    for (const CableViaPoint& via : line.cable->params().viaPoints) pts.push_back(stationInGround(s, via.body, via.point));
    pts.push_back(stationInGround(s, line.where.anchorBody, line.where.anchorPoint));
    return pts;
  }

  // What any kind of line does to its ends now (state realized to Velocity at least).
  LineForces lineForces(const SimTK::State& s, const LineEntry& line) const {
    if (!line.cable) return line.model->calcForces(endsOf(s, line, true));
    system.realize(s, SimTK::Stage::Dynamics);
    LineForces f;
    const double t = line.spring.getTension(s);
    const std::vector<Eigen::Vector3d> pts = cablePoints(s, line);
    f.fairleadTension = f.anchorTension = t;
    f.onFairlead = t * (pts[1] - pts[0]).normalized();
    f.onAnchor = t * (pts[pts.size() - 2] - pts.back()).normalized();
    f.slack = t <= 0.0;
    return f;
  }

  // Power of the line dampers, W: integrated into the dissipated energy.
  double dissipationPower(const SimTK::State& s) const {
    double p = 0.0;
    for (const LineEntry& line : lines) {
      if (!line.model->dissipates() || line.model->isDynamic() || line.cable) continue;
      if (forces.getForce(line.forceIndex).isDisabled(s)) continue;
      p += line.model->calcForces(endsOf(s, line, true)).dissipationPower;
    }
    return p;
  }

  // Power of the external wrenches, W, read from the State-held DiscreteForces.
  double externalPower(const SimTK::State& s) const {
    const SimTK::Vector_<SimTK::SpatialVec>& all = external.getAllBodyForces(s);
    double p = 0.0;
    for (const SimTK::MobilizedBody& mb : mobods) {
      const SimTK::SpatialVec& w = all[mb.getMobilizedBodyIndex()];
      p += ~w[0] * mb.getBodyAngularVelocity(s) + ~w[1] * mb.getBodyOriginVelocity(s);
    }
    return p;
  }

  void build();
  void buildCable(LineEntry& line);
  void stepTo(double t);
  void checkBreaks();
  void exchangeDynamicLineForces();
};

struct MultibodySystem::Impl : SystemCore {
  using SystemCore::SystemCore;
};

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

  StdoutCapture capture;  // CablePath's diagnostics (DESIGN.md 3)
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
    if (std::max(f.fairleadTension, f.anchorTension) > line.model->breakingLoad()) {
      line.broken = true;
      line.breakTime = s.getTime();
      if (line.forceIndex.isValid()) {
        // Disabling the force element is an Instance-stage change held in the State.
        forces.getForce(line.forceIndex).disable(integ->updAdvancedState());
        integ->reinitialize(SimTK::Stage::Instance, false);
      }
    }
  }
}

void SystemCore::stepTo(double t) {
  // After initialize()/reinitialize() the first stepTo() may return without advancing
  // (StartOfContinuousInterval), and with setReturnEveryInternalStep it returns after
  // each step: loop until the target is really reached. Passing t as the scheduled
  // event time keeps the integrator from stepping past it.
  const double tolerance = 1e-12 * std::max(1.0, std::abs(t));
  int stalls = 0;
  while (integ->getTime() < t - tolerance) {
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
  Impl& m = *impl_;
  if (!m.initialized) throw std::logic_error("MultibodySystem::advanceTo before initialize()");
  if (t < m.integ->getTime() - 1e-12) throw std::invalid_argument("MultibodySystem::advanceTo: time goes backwards");
  if (!m.anyDynamic) {
    m.stepTo(t);
    return;
  }
  while (m.integ->getTime() < t - 1e-12 * std::max(1.0, std::abs(t))) {
    const double t0 = m.integ->getTime();
    const double t1 = std::min(t, t0 + m.options.lineSyncStep);
    std::vector<LineEnds> start;
    for (const LineEntry& line : m.lines) start.push_back(m.endsOf(m.integ->getState(), line, true));
    m.stepTo(t1);
    m.system.realize(m.integ->getState(), SimTK::Stage::Velocity);
    for (std::size_t i = 0; i < m.lines.size(); ++i) {
      LineEntry& line = m.lines[i];
      if (!line.model->isDynamic() || line.broken) continue;
      line.model->advance(t1 - t0, start[i], m.endsOf(m.integ->getState(), line, true));
      if (std::isfinite(line.model->breakingLoad())) {
        const LineForces f = line.model->calcForces(m.endsOf(m.integ->getState(), line, true));
        if (std::max(f.fairleadTension, f.anchorTension) > line.model->breakingLoad()) {
          line.broken = true;
          line.breakTime = t1;
        }
      }
    }
    m.exchangeDynamicLineForces();
  }
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
  if (!line.broken) {
    const LineForces f = m.lineForces(s, line);
    d.fairleadTension = f.fairleadTension;
    d.anchorTension = f.anchorTension;
    d.forceOnFairlead = f.onFairlead;
    d.slack = f.slack;
  } else {
    d.slack = true;
  }
  if (withShape && !line.broken) d.shape = line.cable ? m.cablePoints(s, line) : line.model->calcShape(ends);
  return d;
}

}  // namespace moorsph::bodies
