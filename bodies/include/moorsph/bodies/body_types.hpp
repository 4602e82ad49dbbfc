#pragma once
// Plain-data types of the coupling contract (DESIGN.md section 2): everything that
// crosses the bodies/ boundary is Eigen or standard C++, never a Simbody type, so
// coupling/ and io/ never see Simbody headers. Ground frame, SI units throughout.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <string>

namespace moorsph::bodies {

/// Rigid motion of a body's reference point (the body-frame origin), ground frame.
struct BodyKinematics {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();          ///< m
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  ///< body -> ground
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();          ///< m/s
  Eigen::Vector3d angularVelocity = Eigen::Vector3d::Zero();   ///< rad/s
  Eigen::Vector3d acceleration = Eigen::Vector3d::Zero();      ///< m/s^2
  Eigen::Vector3d angularAcceleration = Eigen::Vector3d::Zero();  ///< rad/s^2

  /// Ground position of a point given in body-frame coordinates.
  Eigen::Vector3d pointToGround(const Eigen::Vector3d& bodyPoint) const {
    return position + orientation * bodyPoint;
  }
  /// Ground velocity of a body-fixed point given in body-frame coordinates.
  Eigen::Vector3d pointVelocity(const Eigen::Vector3d& bodyPoint) const {
    return velocity + angularVelocity.cross(orientation * bodyPoint);
  }
};

/// Force and torque about the body reference point (body-frame origin), both in the
/// ground frame. N and N m.
struct BodyWrench {
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  Eigen::Vector3d torque = Eigen::Vector3d::Zero();
};

/// How a body may move relative to ground.
/// - Free: 6 DOF (3D scenes). Orientation is a quaternion (no gimbal lock).
/// - Planar: 3 DOF, translation in the ground x-y plane and rotation about z (2D
///   scenes: x along the tank, y up). Gravity must lie in the x-y plane.
enum class Mobilizer { Free, Planar };

/// Ground-frame degrees of freedom, used to hold some of them fixed.
/// Rotations are about ground axes through the body reference point.
enum class Dof { TranslationX = 0, TranslationY, TranslationZ, RotationX, RotationY, RotationZ };

/// Definition of one rigid body.
struct RigidBodySpec {
  std::string name;
  double mass = 1.0;                                            ///< kg
  Eigen::Vector3d centreOfMass = Eigen::Vector3d::Zero();       ///< body frame, m
  /// Inertia tensor about the centre of mass in body-frame axes, kg m^2 (NOT per unit
  /// mass; converted to SimTK::Inertia about the body origin internally).
  Eigen::Matrix3d inertiaAboutCom = Eigen::Matrix3d::Identity();
  Mobilizer mobilizer = Mobilizer::Free;
  /// fixedDofs[Dof] = true holds that generalized speed at zero for all time.
  std::array<bool, 6> fixedDofs{{false, false, false, false, false, false}};
  BodyKinematics initial;  ///< initial pose and velocity (accelerations ignored)
};

/// Mass properties as reported back by the built multibody system (used to check
/// that what the scene asked for is what Simbody simulates).
struct MassReport {
  double mass = 0.0;                                        ///< kg
  Eigen::Vector3d centreOfMass = Eigen::Vector3d::Zero();   ///< body frame, m
  Eigen::Matrix3d inertiaAboutCom = Eigen::Matrix3d::Zero();  ///< kg m^2, body axes
};

/// Energy bookkeeping, J. total() + dissipated - externalWork is conserved.
struct EnergyReport {
  double kinetic = 0.0;
  double gravitational = 0.0;   ///< bodies' gravitational potential (zero at y=0 plane of g)
  double lineElastic = 0.0;     ///< potential energy stored in mooring lines
  double dissipated = 0.0;      ///< energy removed by line damping since t=0
  double externalWork = 0.0;    ///< work done by the external wrenches since t=0
  double mechanical() const { return kinetic + gravitational + lineElastic; }
};

}  // namespace moorsph::bodies
