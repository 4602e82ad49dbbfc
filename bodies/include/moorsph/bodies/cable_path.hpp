#pragma once
// A cable routed through via points (ideal, frictionless pulleys) fixed on ground or
// on bodies, for laboratory rigs: inside MultibodySystem it is Simbody's CablePath with
// CableObstacle::ViaPoint and CableSpring (Simbody 3.7; Sherman, Seth & Delp 2011,
// "Simbody: multibody dynamics for biomedical research", Procedia IUTAM 2). Units SI.
//
//   L = sum of the straight segments fairlead -> via_1 -> ... -> via_n -> anchor
//   x = max(0, L - L0),  f_s = k x,  T = f_s + max(-f_s, f_s c Ldot)   (uniform)
//   pulling each end and each via point along the adjacent segments.
// Note the damping law is Simbody's: c is in s/m (a fraction of the elastic tension
// per unit length rate), not the N s/m of tension_only_spring.
// L0 is given, or derived from a pretension T0 at the initial pose: L0 = L_init - T0/k.
// Simbody 3.7 prints ~80 lines of path diagnostics to stdout when such a system is
// built and initialised; MultibodySystem captures them (capturedSimbodyOutput()).
//
// Outside a MultibodySystem, calcForces() evaluates the same law with the via points
// taken as fixed in ground (viaPoint.body must be kGround then).

#include <moorsph/bodies/mooring_line.hpp>

#include <limits>
#include <vector>

namespace moorsph::bodies {

struct CableViaPoint {
  int body = LineAttachment::kGround;  ///< body index or kGround
  Eigen::Vector3d point = Eigen::Vector3d::Zero();  ///< body (or ground) frame, m
};

struct CablePathParams {
  double stiffness = 0.0;  ///< k, N/m
  double restLength = std::numeric_limits<double>::quiet_NaN();  ///< L0, m (or pretension)
  double pretension = std::numeric_limits<double>::quiet_NaN();  ///< T0 at the initial pose, N
  double dissipation = 0.0;  ///< c, s/m (Simbody CableSpring law)
  std::vector<CableViaPoint> viaPoints;  ///< in order from fairlead to anchor
};

class CablePathLine final : public MooringLine {
 public:
  explicit CablePathLine(const CablePathParams& params);

  std::string modelName() const override { return "cable_path"; }
  /// Resolves the pretension from the initial path (via points in ground frame here).
  void initialize(const LineEnds& ends) override;
  LineForces calcForces(const LineEnds& ends) const override;
  double calcPotentialEnergy(const LineEnds& ends) const override;
  std::vector<Eigen::Vector3d> calcShape(const LineEnds& ends) const override;
  bool dissipates() const override { return params_.dissipation > 0.0; }

  const CablePathParams& params() const { return params_; }
  double restLength() const { return params_.restLength; }
  /// Sets L0 from the path length at the initial pose (used by MultibodySystem, which
  /// knows where body-mounted via points are).
  void resolveRestLength(double initialPathLength);

 private:
  std::vector<Eigen::Vector3d> groundPath(const LineEnds& ends) const;
  CablePathParams params_;
};

}  // namespace moorsph::bodies
