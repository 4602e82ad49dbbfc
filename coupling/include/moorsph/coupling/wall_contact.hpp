#pragma once
// Contact between a coupled body and the fixed walls (issue 8, stability case 6).
//
// Bodies and walls are both layers of boundary particles, and the reference method
// only lets boundary particles push fluid particles (METHOD.md section 2). A body
// heavier than water that reaches the floor squeezes the last fluid out from under
// it and then sinks through (observed: a cylinder of density ratio 2 resting in a
// corner leaves the tank 0.12 s after release). Contact closes that gap with the same
// law: each fixed wall particle k pushes each body surface particle p as it would push
// a fluid particle of mass m_c = rho0 dx^D standing at p,
//   F_pk = m_c a_wall(r_p - r_k)      (BoundaryForceLaw, METHOD.md section 2),
// and the body feels the sum (force and torque about its origin). So a body resting on
// the floor is held where the fluid layer next to the floor would be held (about half
// a spacing above it), and the force is as stiff as the wall is for the fluid.
// Contact acts only with non-movable surfaces (tank walls, fixed obstacles), not
// between bodies or with pistons. Cost: one pass over the fixed wall particles per
// body and step to collect those within reach of the body, then the pairs.
#include <vector>
#include <moorsph/bodies/body_types.hpp>
#include <moorsph/fluid/walls.hpp>

namespace moorsph::coupling {

template <int D>
class WallContact {
 public:
  /// particle_mass: m_c = rho0 dx^D [kg, per metre of span in 2D]; h the smoothing
  /// length (the wall law is zero beyond q = 1 along a normal and dx sideways, all
  /// within 2h of the wall particle).
  WallContact(const fluid::Walls<D>& walls, double particle_mass, double h);

  /// Contact wrench on the body whose surface is `surface`: force, and torque about
  /// `origin` (the body origin), ground frame. Zero when no fixed wall is in reach.
  bodies::BodyWrench wrench(std::size_t surface, const fluid::Vec<D>& origin) const;

 private:
  const fluid::Walls<D>& walls_;
  double mass_;
  std::vector<std::size_t> fixed_;  ///< indices of the particles of non-movable surfaces
  double reach_;                    ///< 2h
};

}  // namespace moorsph::coupling
