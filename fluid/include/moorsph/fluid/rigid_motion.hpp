#pragma once
// Rigid-body kinematics of a boundary surface, in the ground frame (SI): the position
// of its reference point, the rotation from body to ground axes, the velocity of the
// reference point and the angular velocity (in 2D only its z component is used: a
// Planar body rotates about the axis normal to the x-y plane).
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <moorsph/fluid/vec.hpp>

namespace moorsph::fluid {

template <int D>
struct RigidMotion {
  Vec<D> position = Vec<D>::Zero();                                   ///< [m]
  Eigen::Matrix<double, D, D> rotation = Eigen::Matrix<double, D, D>::Identity();
  Vec<D> velocity = Vec<D>::Zero();                                   ///< [m/s]
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();         ///< [rad/s]

  /// Velocity of the body-fixed point now at r: v + omega x (r - position).
  Vec<D> velocityAt(const Vec<D>& r) const {
    Eigen::Vector3d arm = Eigen::Vector3d::Zero();
    arm.template head<D>() = r - position;
    const Eigen::Vector3d w = angular_velocity.cross(arm);
    return velocity + w.template head<D>();
  }

  /// A pure translation by `offset` moving at `speed`.
  static RigidMotion translation(const Vec<D>& offset, const Vec<D>& speed) {
    RigidMotion m;
    m.position = offset;
    m.velocity = speed;
    return m;
  }
};

}  // namespace moorsph::fluid
