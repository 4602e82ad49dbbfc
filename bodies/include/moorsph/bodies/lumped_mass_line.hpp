#pragma once
// Dynamic lumped-mass mooring line (the discretisation of Hall & Goupee 2015, "Validation
// of a lumped-mass mooring line model with DeepCwind semisubmersible model test data",
// Ocean Engineering 104, the model behind MoorDyn). Units SI.
//
// N segments of unstretched length l = L/N join N+1 nodes; node 0 is the anchor, node
// N the fairlead, both moved kinematically; the N-1 internal nodes carry the state.
//  - segment tension (tension only): T = EA e + BA de/dt for e = |dr|/l - 1 > 0, T >= 0
//  - optional bending at internal nodes from the energy EI/(2 l) |q_b - q_a|^2 (q_a, q_b
//    the unit vectors of the adjacent segments; |q_b - q_a| ~ the turning angle, so
//    this is EI kappa^2 l / 2 with kappa = angle / l); pinned ends carry no moment
//  - net weight per node: (m - f rho_w A) l g, A = pi d^2/4 (d volumetric diameter), f the
//    wet fraction of the node's two half segments (drag and added mass x f too)
//  - Morison drag per node, node tangent q, relative velocity w = u_water - v:
//    F = 1/2 rho_w d l Cdn |w_n| w_n + 1/2 rho_w pi d l Cdt |w_t| w_t, and with moving
//    water the inertia force rho_w A l [(1 + Ca) a_n + (1 + CaAx) a_t]
//  - node mass matrix: m l I + rho_w A l [Ca (I - q q^T) + CaAx q q^T]
//  - seabed (plane through seabedPoint, normal up): penetration p > 0 gives
//    F = (kb p - cb dp/dt)_+ d l up, friction -min(mu F, c_f |v_h|) v_h/|v_h| (Coulomb,
//    regularised by the largest viscous slope c_f = m_node/(2 dt) the step allows).
// Time integration: semi-implicit (symplectic) Euler, v += dt a(r, v), r += dt v,
// stable for omega dt < 2; the step is at most 0.5 l/c, c = sqrt(EA/m), and tighter if
// BA demands it (stableTimeStep()). Asking for a larger step is an error.
// Initial shape: the elastic catenary between the ends (node i at s = i l), optionally
// relaxed dynamically (mass-proportional damping) to the discrete static equilibrium.
// The force on the fairlead body is the top segment's tension plus the end node's half
// segment of net weight: the end node has no inertia of its own.
// Breaking load: tested after every sub-step of advance(), which stops at the first
// sub-step whose larger end tension exceeds it (MooringLine::lastExceedance()).

#include <moorsph/bodies/mooring_line.hpp>

#include <functional>
#include <limits>
#include <vector>

namespace moorsph::bodies {

/// Water velocity and acceleration (m/s, m/s^2, ground frame) at a point and time (s);
/// e.g. linear wave kinematics or a current. The line's clock starts at 0 at initialize().
using WaterKinematics = std::function<void(const Eigen::Vector3d& position, double time,
                                           Eigen::Vector3d& velocity, Eigen::Vector3d& acceleration)>;

struct LumpedMassParams {
  double length = 0.0;           ///< unstretched L, m
  int segments = 20;             ///< N
  double massPerLength = 0.0;    ///< m, kg/m (in air)
  double diameter = 0.0;         ///< volumetric diameter d, m
  double axialStiffness = 0.0;   ///< EA, N
  double bendingStiffness = 0.0; ///< EI, N m^2 (0: a perfectly flexible line)
  double internalDamping = 0.0;  ///< BA, N s
  /// If > 0, sets BA = 2 zeta l sqrt(EA m): zeta is the damping ratio of one segment's
  /// axial spring on its node mass (1 = critical). Axial ringing from the lumped
  /// discretisation is otherwise undamped and pollutes the tension.
  double internalDampingRatio = 0.0;
  double cdNormal = 0.0, cdAxial = 0.0;  ///< drag coefficients, -
  double caNormal = 0.0, caAxial = 0.0;  ///< added-mass coefficients, -
  double waterDensity = 1025.0;  ///< kg/m^3
  /// Height of the still water surface along "up" (m): buoyancy, drag and added mass
  /// act on the submerged part of the line only (per node, the wet fraction of its two
  /// half segments). Infinity: always submerged.
  double waterSurfaceHeight = std::numeric_limits<double>::infinity();
  Eigen::Vector3d gravity{0.0, -9.81, 0.0};  ///< m/s^2 (its direction defines "up")
  bool seabed = true;            ///< contact with the plane through seabedPoint
  /// A point of the seabed plane; NaN: the anchor's initial position.
  Eigen::Vector3d seabedPoint = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
  /// Moving water (empty: still water). Drag then acts on the relative velocity and the
  /// water's acceleration adds the Morison inertia force rho V (1 + Ca) a (per direction).
  WaterKinematics waterKinematics;
  double seabedStiffness = 3.0e6;  ///< kb, Pa/m
  double seabedDamping = 3.0e5;    ///< cb, Pa s/m
  double seabedFriction = 0.0;     ///< mu, -
  double timeStep = 0.0;           ///< s; 0 = 0.9 x stableTimeStep()
  double relaxationTime = 0.0;     ///< s of dynamic relaxation at initialize(); 0 = none
  double relaxationDamping = 1.0;  ///< 1/s, mass-proportional damping while relaxing
};

class LumpedMassLine final : public MooringLine {
 public:
  explicit LumpedMassLine(const LumpedMassParams& params);

  std::string modelName() const override { return "lumped_mass"; }
  void initialize(const LineEnds& ends) override;
  LineForces calcForces(const LineEnds& ends) const override;
  double calcPotentialEnergy(const LineEnds& ends) const override;
  std::vector<Eigen::Vector3d> calcShape(const LineEnds& ends) const override;
  bool isDynamic() const override { return true; }
  /// Advances by dt with the ends moving linearly from `start` to `end`.
  void advance(double dt, const LineEnds& start, const LineEnds& end) override;

  /// Dynamic relaxation with the ends held: runs until the fastest node is slower than
  /// `speedTolerance` (m/s) or `maxTime` (s) has passed; returns the time used.
  double relax(double maxTime, double speedTolerance = 1e-6);

  /// Node positions and velocities, dissipated energy and end work, flattened.
  std::vector<double> saveState() const override;
  void restoreState(const std::vector<double>& state) override;
  void startWithoutSavedState(const LineEnds& ends, double time) override;

  double stableTimeStep() const { return stableStep_; }
  double timeStep() const { return dt_; }
  const std::vector<Eigen::Vector3d>& nodePositions() const { return r_; }
  const std::vector<Eigen::Vector3d>& nodeVelocities() const { return v_; }
  /// Tension in each segment (anchor first), N.
  std::vector<double> segmentTensions() const;
  /// Energy of the internal nodes and segments: kinetic, and potential (elastic +
  /// net weight above the anchor + seabed spring), J.
  double kineticEnergy() const;
  /// Energy taken by drag, internal damping and the seabed since initialize(), J (with
  /// moving water: minus the net work of the hydrodynamic forces on the line).
  double dissipatedEnergy() const { return dissipated_; }
  /// Work done on the line by its two moving ends since initialize(), J.
  double endWork() const { return endWork_; }
  /// The line's own clock (s since initialize(), advanced by advance()).
  double time() const { return time_; }

 private:
  void computeAccelerations(std::vector<Eigen::Vector3d>& acc, double time, bool movingWater, double extraDamping,
                            double* dissipation, double* endPower) const;
  double segmentTension(int j, double* dampingPower) const;
  void addBendingForces(std::vector<Eigen::Vector3d>& force) const;
  double bendingEnergy() const;
  double wetFraction(int node) const;
  double buoyancyPotential(const Eigen::Vector3d& r) const;

  LumpedMassParams p_;
  Eigen::Vector3d up_;
  double segLength_ = 0.0, nodeMass_ = 0.0, netWeight_ = 0.0, area_ = 0.0;
  double stableStep_ = 0.0, dt_ = 0.0, frictionSlope_ = 0.0;
  std::vector<Eigen::Vector3d> r_, v_;
  mutable std::vector<Eigen::Vector3d> scratchForce_;
  double dissipated_ = 0.0, endWork_ = 0.0, time_ = 0.0;
  bool initialized_ = false;
};

}  // namespace moorsph::bodies
