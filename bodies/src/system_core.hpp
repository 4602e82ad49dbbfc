#pragma once
// Internal (not installed): the Simbody-side state of a MultibodySystem, shared by
// system_core.cpp (building and stepping) and multibody_system.cpp (the public API).
// The Simbody facts it relies on are DESIGN.md section 3.
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

namespace detail {

// Generalized-speed index of a ground-frame DOF for each mobilizer, or -1 when the
// mobilizer does not have it. Free: u = [w_x w_y w_z v_x v_y v_z] (angular velocity and
// origin velocity in the parent = ground frame). Planar: u = [w_z v_x v_y].
inline int speedIndex(Mobilizer mobilizer, Dof dof) {
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

}  // namespace detail

struct LineEntry {
  std::string name;
  LineAttachment where;
  std::unique_ptr<MooringLine> model;
  SimTK::ForceIndex forceIndex;  // invalid for dynamic lines
  CablePathLine* cable = nullptr;  // set for cable_path lines (Simbody CableSpring)
  SimTK::CableSpring spring;
  bool broken = false;
  double breakTime = std::numeric_limits<double>::quiet_NaN();
  double breakTension = std::numeric_limits<double>::quiet_NaN();
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
  SimTK::Measure::Integrate dissipatedEnergy;
  SimTK::Measure::Integrate externalWork;
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

  // Work bound of one stepTo() (system_core.cpp, SystemCore::throwIfOverBudget).
  static constexpr int kStepsPerReturn = 1000;
  static constexpr double kStepBudgetFactor = 100.0;
  static constexpr double kStepBudgetAllowance = 10000.0;

  void build();
  void buildCable(LineEntry& line);
  void throwIfOverBudget(double t0, double t, long attempts0) const;
  void stepTo(double t);
  void checkBreaks();
  void exchangeDynamicLineForces();
  void advanceTo(double t);
};

}  // namespace moorsph::bodies
