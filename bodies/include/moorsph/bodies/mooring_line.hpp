#pragma once
// One interface for every mooring model (DESIGN.md section 4). A line joins a fairlead
// (a point fixed on a body) to an anchor (a point fixed on ground or on another body).
// The model only sees plain data: the two end positions and velocities in the ground
// frame; the multibody system turns its answer into forces on the bodies. A scene
// swaps the model by changing the `model` word of MooringLineParams (mooring_factory.hpp).

#include <Eigen/Core>

#include <limits>
#include <string>
#include <vector>

namespace moorsph::bodies {

/// Ground-frame positions (m) and velocities (m/s) of a line's two ends.
struct LineEnds {
  Eigen::Vector3d fairlead = Eigen::Vector3d::Zero();
  Eigen::Vector3d fairleadVelocity = Eigen::Vector3d::Zero();
  Eigen::Vector3d anchor = Eigen::Vector3d::Zero();
  Eigen::Vector3d anchorVelocity = Eigen::Vector3d::Zero();
};

/// What a line does to its ends at one instant.
struct LineForces {
  Eigen::Vector3d onFairlead = Eigen::Vector3d::Zero();  ///< force of the line on the fairlead, N
  Eigen::Vector3d onAnchor = Eigen::Vector3d::Zero();    ///< force of the line on the anchor, N
  double fairleadTension = 0.0;                          ///< N
  double anchorTension = 0.0;                            ///< N
  double dissipationPower = 0.0;  ///< power removed by line damping, W (>= 0)
  bool slack = false;
};

/// Where a line is attached. Body indices are those returned by
/// MultibodySystem::addBody; kGround (-1) means the point is fixed in ground.
struct LineAttachment {
  static constexpr int kGround = -1;
  int fairleadBody = 0;
  Eigen::Vector3d fairleadPoint = Eigen::Vector3d::Zero();  ///< body frame, m
  int anchorBody = kGround;
  Eigen::Vector3d anchorPoint = Eigen::Vector3d::Zero();  ///< ground or anchor-body frame, m
};

/// Output record of one line (for series.h5 and for tests).
struct LineDiagnostics {
  std::string name;
  std::string model;
  double fairleadTension = 0.0;  ///< N
  double anchorTension = 0.0;    ///< N
  Eigen::Vector3d forceOnFairlead = Eigen::Vector3d::Zero();  ///< N, ground
  Eigen::Vector3d forceOnAnchor = Eigen::Vector3d::Zero();    ///< N, ground
  bool slack = false;
  bool broken = false;
  /// When the line broke: the end of the first integrator step (Simbody step for the
  /// quasi-static models, line sub-step for lumped_mass) whose end tension exceeded
  /// the breaking load, so within one step after the crossing. NaN if intact.
  double breakTime = std::numeric_limits<double>::quiet_NaN();  ///< s
  double breakTension = std::numeric_limits<double>::quiet_NaN();  ///< N, larger end tension then
  std::vector<Eigen::Vector3d> shape;  ///< points from fairlead to anchor, ground, m
};

/// Base class of the mooring models.
class MooringLine {
 public:
  virtual ~MooringLine() = default;

  /// The scene word of the model ("tension_only_spring", "elastic_catenary", ...).
  virtual std::string modelName() const = 0;

  /// Called once when the system is built, with the initial end positions: resolves
  /// anything specified "at the initial pose" (pretension -> rest length, initial
  /// shape of a dynamic line).
  virtual void initialize(const LineEnds& ends) { (void)ends; }

  /// Forces on the ends for the given end state. For dynamic lines this reads their
  /// internal state (the ends are used only for the attachment points).
  virtual LineForces calcForces(const LineEnds& ends) const = 0;

  /// Potential energy stored in the line (elastic), J.
  virtual double calcPotentialEnergy(const LineEnds& ends) const = 0;

  /// Line shape from fairlead to anchor for output (ground frame, m).
  virtual std::vector<Eigen::Vector3d> calcShape(const LineEnds& ends) const = 0;

  /// True when the model has velocity-dependent dissipation (enables tracking).
  virtual bool dissipates() const { return false; }

  /// Dynamic lines carry their own state and are advanced alongside the body
  /// integrator with their own stable sub-step (see lumped_mass_line.hpp).
  virtual bool isDynamic() const { return false; }
  virtual void advance(double dt, const LineEnds& start, const LineEnds& end) {
    (void)dt; (void)start; (void)end;
  }

  /// Internal state of dynamic lines as plain numbers, for snapshots and checkpoints
  /// (empty for stateless models).
  virtual std::vector<double> saveState() const { return {}; }
  virtual void restoreState(const std::vector<double>& state) { (void)state; }
  /// A restart whose snapshot holds no state for this line (it was saved while the line
  /// had a stateless model): a dynamic line starts from its static shape between the
  /// restored ends, with its clock at `time`, instead of from the shape it was given at
  /// the initial pose (the fairlead has moved since). Stateless models ignore it.
  virtual void startWithoutSavedState(const LineEnds& ends, double time) { (void)ends; (void)time; }

  /// Tension above which the line breaks (N); infinity means unbreakable.
  double breakingLoad() const { return breakingLoad_; }
  void setBreakingLoad(double load) { breakingLoad_ = load; }

  /// Dynamic lines test their breaking load after every internal sub-step of
  /// advance() and stop there; this is the first such exceedance of the last
  /// advance(): time since that advance() began (s) and the larger end tension (N).
  /// NaN time: none. The multibody system turns it into the line's break.
  struct Exceedance {
    double timeIntoAdvance = std::numeric_limits<double>::quiet_NaN();
    double tension = 0.0;
  };
  const Exceedance& lastExceedance() const { return exceedance_; }

 protected:
  void clearExceedance() { exceedance_ = Exceedance{}; }
  void recordExceedance(double timeIntoAdvance, double tension) { exceedance_ = {timeIntoAdvance, tension}; }

 private:
  double breakingLoad_ = std::numeric_limits<double>::infinity();
  Exceedance exceedance_;
};

}  // namespace moorsph::bodies
