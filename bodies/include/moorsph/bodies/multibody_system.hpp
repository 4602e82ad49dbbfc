#pragma once
// The rigid-body side of the co-simulation (DESIGN.md sections 2-3): a Simbody 3.7
// multibody system of rigid bodies (Free or Planar mobilizers), gravity, one external
// wrench per body held in the Simbody State (Force::DiscreteForces), and mooring
// lines. The interface speaks plain Eigen data; Simbody stays inside bodies/src.
//
// Usage: addBody()/addLine() ..., initialize(), then repeatedly
// setExternalWrench() and advanceTo(t); read kinematics(), energy(), lineDiagnostics().
//
// Timing and lag: the external wrench is held constant over each advanceTo() call
// (zero-order hold), which is where the coupling lag sits. Inside advanceTo() Simbody
// takes as many adaptive steps as it needs, never longer than maxStep. Dynamic lines
// (lumped_mass) exchange forces with the bodies every lineSyncStep seconds: the
// line's fairlead force is held over each exchange interval and the line is then
// advanced with the fairlead moving linearly between the two body poses.

#include <moorsph/bodies/body_types.hpp>
#include <moorsph/bodies/mooring_line.hpp>

#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace moorsph::bodies {

struct SystemOptions {
  Eigen::Vector3d gravity{0.0, -9.81, 0.0};  ///< m/s^2 (y up, METHOD.md)
  double maxStep = 1.0e-3;     ///< largest internal integrator step, s
  double accuracy = 1.0e-8;    ///< relative accuracy of the error-controlled integrator
  double lineSyncStep = 1.0e-3;  ///< force exchange interval with dynamic lines, s
};

/// Everything needed to continue a run in another MultibodySystem built from the same
/// scene (checkpoints, restarts, and variants that change a body's mass: Simbody cannot
/// change a mass after the system is built, so such a variant builds a new system and
/// restores the snapshot into it). Plain data, ground frame, SI.
struct LineSnapshot {
  bool broken = false;
  double breakTime = std::numeric_limits<double>::quiet_NaN();
  double breakTension = std::numeric_limits<double>::quiet_NaN();  ///< N
  double cableDissipated = 0.0;       ///< J, cable_path lines
  std::vector<double> internalState;  ///< MooringLine::saveState()
};
struct SystemSnapshot {
  double time = 0.0;
  std::vector<BodyKinematics> bodies;
  std::vector<BodyWrench> wrenches;
  std::vector<LineSnapshot> lines;
  double dissipated = 0.0;    ///< line damper energy so far (excluding cable_path's own), J
  double externalWork = 0.0;  ///< J
};

class MultibodySystem {
 public:
  explicit MultibodySystem(const SystemOptions& options = SystemOptions{});
  ~MultibodySystem();
  MultibodySystem(MultibodySystem&&) noexcept;
  MultibodySystem& operator=(MultibodySystem&&) noexcept;
  MultibodySystem(const MultibodySystem&) = delete;
  MultibodySystem& operator=(const MultibodySystem&) = delete;

  // ---- building (before initialize) ----
  /// Adds a rigid body; returns its index.
  int addBody(const RigidBodySpec& spec);
  /// Adds a mooring line; returns its index. The system owns the model.
  int addLine(const std::string& name, const LineAttachment& where,
              std::unique_ptr<MooringLine> model);
  /// Builds the Simbody system, sets the initial state and resolves line pretensions.
  void initialize();
  bool isInitialized() const;

  // ---- stepping ----
  double time() const;
  /// External wrench on a body (ground frame, torque about the body origin), held in
  /// the State until changed. May be called before or after initialize().
  void setExternalWrench(int body, const BodyWrench& wrench);
  BodyWrench externalWrench(int body) const;
  /// Advances until time() == t exactly (loops over the integrator's steps).
  void advanceTo(double t);
  /// The current state as plain data.
  SystemSnapshot snapshot() const;
  /// Continues from a snapshot (after initialize(); same bodies and lines, masses may
  /// differ). Time, poses, velocities, wrenches, line states and energy integrals are
  /// restored; the integrator restarts from there.
  void restore(const SystemSnapshot& snapshot);

  // ---- reading ----
  int bodyCount() const;
  int lineCount() const;
  BodyKinematics kinematics(int body) const;
  MassReport massProperties(int body) const;  ///< as Simbody holds them
  int mobilityCount(int body) const;          ///< generalized speeds of the mobilizer
  int unlockedMobilityCount(int body) const;  ///< minus the fixed ones
  EnergyReport energy() const;
  LineDiagnostics lineDiagnostics(int line, bool withShape = false) const;
  const MooringLine& line(int line) const;
  long internalStepCount() const;  ///< integrator steps taken so far
  /// What Simbody printed to stdout while the system was built (CablePath diagnostics
  /// in Simbody 3.7); kept off the user's terminal, available for logs.
  const std::string& capturedSimbodyOutput() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace moorsph::bodies
