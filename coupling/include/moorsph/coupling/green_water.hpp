#pragma once
// Green water on a deck: the volume of fluid standing above a body's deck inside the
// deck's outline, the quantity a naval architect reads to see whether a wave boards
// the ship (METHOD.md 6.5). A fluid particle i counts when its body-frame position
// q = R^T (r_i - p) lies above the deck height (q_y > deck_height) and, in 3D, (q_x, q_z)
// inside the outline polygon (even-odd rule), in 2D q_x within [x_min, x_max]; it
// contributes its volume m_i / rho_i (2D: per metre of span). The deck is treated as a
// flat plane at deck_height in the body frame (sheer and camber neglected).
#include <Eigen/Core>
#include <utility>
#include <vector>
#include <moorsph/bodies/body_types.hpp>
#include <moorsph/fluid/fluid_particles.hpp>

namespace moorsph::coupling {

struct DeckOutline {
  double deck_height = 0.0;  ///< body-frame y of the deck [m]
  /// 3D: closed polygon of body-frame (x, z) vertices [m]; 2D: two entries, x_min and x_max
  /// in the first component.
  std::vector<Eigen::Vector2d> outline;
};

/// True if the body-frame point (x, z) lies inside the outline polygon (3D).
bool insideOutline(const std::vector<Eigen::Vector2d>& polygon, double x, double z);

/// Volume of fluid on the deck [m^3; 2D: m^2 per metre of span].
template <int D>
double greenWaterVolume(const fluid::FluidParticles<D>& fluid, const bodies::BodyKinematics& body,
                        const DeckOutline& deck);

}  // namespace moorsph::coupling
