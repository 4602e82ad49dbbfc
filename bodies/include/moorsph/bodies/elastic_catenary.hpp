#pragma once
// Quasi-static elastic catenary mooring line with seabed contact and friction
// (catenary_solver.hpp for the equations: Irvine 1981; Jonkman 2007 section 4.1.1).
// Each evaluation solves the catenary by Newton from the current fairlead-anchor
// spans: the line has no memory and no inertia, its weight and stretch are exact in
// static equilibrium. The seabed is the horizontal plane through the anchor (when
// anchorOnSeabed). Vertical is `up` (default +y, METHOD.md axes).
//
//   F_fairlead = -HF e_h - VF up,   F_anchor = HA e_h + VA up
// with e_h the horizontal unit vector from anchor to fairlead. If the fairlead is
// below the anchor the roles of the ends are swapped and no seabed contact is assumed.
//
// calcPotentialEnergy returns int_0^L [T^2/(2EA) + w h(s)] ds with h the height above
// the anchor: for a frictionless line the fairlead force is minus its gradient (tested).
// Seabed friction is path dependent; the quasi-static model ignores that hysteresis.

#include <moorsph/bodies/catenary_solver.hpp>
#include <moorsph/bodies/mooring_line.hpp>

namespace moorsph::bodies {

struct ElasticCatenaryParams {
  double length = 0.0;            ///< unstretched length L, m
  double axialStiffness = 0.0;    ///< EA, N
  double weightPerLength = 0.0;   ///< submerged weight w, N/m (mass minus buoyancy, times g)
  double seabedFriction = 0.0;    ///< cb, -
  bool anchorOnSeabed = true;
  Eigen::Vector3d up{0.0, 1.0, 0.0};  ///< unit vector opposite to gravity
  int shapePoints = 41;           ///< points returned by calcShape
};

class ElasticCatenary final : public MooringLine {
 public:
  explicit ElasticCatenary(const ElasticCatenaryParams& params);

  std::string modelName() const override { return "elastic_catenary"; }
  LineForces calcForces(const LineEnds& ends) const override;
  double calcPotentialEnergy(const LineEnds& ends) const override;
  std::vector<Eigen::Vector3d> calcShape(const LineEnds& ends) const override;

  const ElasticCatenaryParams& params() const { return params_; }

 private:
  struct Plane;  // the line's vertical plane and the solved catenary in it
  Plane solve(const LineEnds& ends) const;
  ElasticCatenaryParams params_;
};

}  // namespace moorsph::bodies
