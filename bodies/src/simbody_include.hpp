#pragma once
// The one place bodies/ includes Simbody. Every .cpp that includes this file must be
// listed in moorsph_simbody_sources() (compiled with -UNDEBUG: Debian's Simbody 3.7
// was built without NDEBUG and some classes change layout with it, DESIGN.md 3).
// Simbody 3.7 derives from std::iterator, deprecated in C++17: silence that here
// rather than in every user. Never `using namespace SimTK;` where Eigen is used.

#ifdef NDEBUG
#error "Simbody translation units must be compiled with -UNDEBUG (moorsph_simbody_sources)"
#endif

#pragma GCC system_header
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"
#include <Simbody.h>
#pragma GCC diagnostic pop

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace moorsph::bodies::detail {

inline SimTK::Vec3 toSimTK(const Eigen::Vector3d& v) { return SimTK::Vec3(v.x(), v.y(), v.z()); }
inline Eigen::Vector3d toEigen(const SimTK::Vec3& v) { return Eigen::Vector3d(v[0], v[1], v[2]); }

inline SimTK::Rotation toSimTK(const Eigen::Quaterniond& q) {
  const Eigen::Quaterniond n = q.normalized();
  return SimTK::Rotation(SimTK::Quaternion(n.w(), n.x(), n.y(), n.z()));
}
inline Eigen::Quaterniond toEigen(const SimTK::Rotation& r) {
  const SimTK::Quaternion q = r.convertRotationToQuaternion();
  return Eigen::Quaterniond(q[0], q[1], q[2], q[3]);
}

}  // namespace moorsph::bodies::detail
