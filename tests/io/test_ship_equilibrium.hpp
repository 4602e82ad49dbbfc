#pragma once
// The floating equilibrium of a moored hull in still water, from the mesh's exact hydrostatics
// (io/mesh_properties.hpp) and the cables' spring law, for the METHOD.md section 6.5 ship and
// its tiny CI version (tests/io/test_ship_scene.cpp). Nothing here comes from the SPH code:
// it is the number the simulation is checked against.
//
// The hull keeps its roll and yaw at zero (the three cables meet at one fairlead on the
// mid-plane above the centre of their anchor triangle, so they add no roll or yaw moment);
// the unknowns are the reference point's surge x and height y and the trim angle theta about
// the across axis z (the body -> ground rotation is Rz(theta), positive theta puts the bow,
// at -x, down). The three equations are: the horizontal force, the vertical force and the
// moment about z vanish, with
//   buoyancy  rho g V(x, y, theta) up through the centre of buoyancy (the mesh, moved to the
//             pose, clipped at the still level: io::hydrostatics),
//   weight    m g down through the centre of mass,
//   cables    T = k (l - L0) (l > L0, else 0) along the fairlead -> anchor direction.
// Solved by Newton's method with a finite-difference Jacobian (the residuals are smooth: the
// waterplane moves continuously with the pose).
#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

#include <Eigen/Dense>
#include <moorsph/io/mesh_properties.hpp>
#include <moorsph/io/triangle_mesh.hpp>

namespace moorsph::test {

struct MooredHull {
  io::TriangleMesh mesh;                    ///< body frame (reference point at the origin)
  double mass = 0.0;                        ///< kg
  Eigen::Vector3d centre_of_mass{0, 0, 0};  ///< body frame [m]
  double water_density = 1025.0;            ///< kg/m^3
  double gravity = 9.81;                    ///< m/s^2
  double still_level = 0.0;                 ///< y of the still surface [m]
  double z = 0.0;                           ///< the mid-plane's ground z [m]
  Eigen::Vector3d fairlead{0, 0, 0};        ///< body frame [m]
  std::vector<Eigen::Vector3d> anchors;     ///< ground [m]
  double stiffness = 0.0;                   ///< N/m
  double rest_length = 0.0;                 ///< m
};

struct HullPose {
  double x = 0.0, y = 0.0, theta = 0.0;     ///< reference point [m], trim [rad]
  Eigen::Matrix3d rotation() const { return Eigen::AngleAxisd(theta, Eigen::Vector3d::UnitZ()).toRotationMatrix(); }
  Eigen::Vector3d toGround(const Eigen::Vector3d& body, double z) const {
    return Eigen::Vector3d(x, y, z) + rotation() * body;
  }
};

struct HullBalance {
  Eigen::Vector3d residual{0, 0, 0};  ///< Fx [N], Fy [N], Mz [N m] about the reference point
  double displaced_volume = 0.0;      ///< m^3
  std::vector<double> tensions;       ///< N, one per anchor
};

inline HullBalance hullBalance(const MooredHull& h, const HullPose& p) {
  io::TriangleMesh moved = h.mesh;
  for (auto& v : moved.vertices) v = p.toGround(v, h.z);
  const io::Hydrostatics hs = io::hydrostatics(moved, h.still_level);
  const Eigen::Vector3d origin(p.x, p.y, h.z);
  HullBalance b;
  b.displaced_volume = hs.volume;
  auto add = [&](const Eigen::Vector3d& at, const Eigen::Vector3d& f) {
    const Eigen::Vector3d arm = at - origin;
    b.residual += Eigen::Vector3d(f.x(), f.y(), arm.x() * f.y() - arm.y() * f.x());
  };
  add(hs.centre_of_buoyancy, Eigen::Vector3d(0, h.water_density * h.gravity * hs.volume, 0));
  add(p.toGround(h.centre_of_mass, h.z), Eigen::Vector3d(0, -h.mass * h.gravity, 0));
  const Eigen::Vector3d f = p.toGround(h.fairlead, h.z);
  for (const auto& a : h.anchors) {
    const Eigen::Vector3d d = a - f;
    const double tension = h.stiffness * std::max(d.norm() - h.rest_length, 0.0);
    b.tensions.push_back(tension);
    add(f, tension * d.normalized());
  }
  return b;
}

/// The still-water equilibrium pose, starting from `guess`.
inline HullPose solveHullEquilibrium(const MooredHull& h, HullPose guess) {
  const Eigen::Vector3d scale(1e6, 1e6, 1e8);  // N, N, N m: residuals of a few of these are "small"
  const Eigen::Vector3d step(1e-3, 1e-3, 1e-6);
  auto asVector = [](const HullPose& p) { return Eigen::Vector3d(p.x, p.y, p.theta); };
  auto asPose = [](const Eigen::Vector3d& q) { return HullPose{q.x(), q.y(), q.z()}; };
  Eigen::Vector3d q = asVector(guess);
  for (int iteration = 0; iteration < 50; ++iteration) {
    const Eigen::Vector3d r = hullBalance(h, asPose(q)).residual;
    if ((r.cwiseQuotient(scale)).cwiseAbs().maxCoeff() < 1e-6) return asPose(q);
    Eigen::Matrix3d jacobian;
    for (int k = 0; k < 3; ++k) {
      Eigen::Vector3d dq = q;
      dq[k] += step[k];
      jacobian.col(k) = (hullBalance(h, asPose(dq)).residual - r) / step[k];
    }
    q -= jacobian.fullPivLu().solve(r);
  }
  throw std::runtime_error("solveHullEquilibrium: no convergence");
}

/// Anchors on an equilateral triangle of side s centred below ground (cx, cz) at height y:
/// one toward -x (the piston), two behind it at +-s/2 across.
inline std::vector<Eigen::Vector3d> anchorTriangle(double cx, double y, double cz, double side) {
  const double r = side / std::sqrt(3.0);  // circumradius
  return {Eigen::Vector3d(cx - r, y, cz), Eigen::Vector3d(cx + 0.5 * r, y, cz - 0.5 * side),
          Eigen::Vector3d(cx + 0.5 * r, y, cz + 0.5 * side)};
}

}  // namespace moorsph::test
