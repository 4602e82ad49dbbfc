#include <moorsph/io/body_geometry.hpp>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <moorsph/fluid/box_geometry.hpp>
#include <moorsph/fluid/shape_sampling.hpp>
#include <moorsph/io/mesh_sampling.hpp>

namespace moorsph::io {
namespace {

Eigen::Vector3d toEigen(const Triple& t) { return Eigen::Vector3d(t[0], t[1], t[2]); }

/// Distance from p to the surface of the box centred at c with edges `size`
/// (negative inside), first `dim` axes.
double signedBoxDistance(const Eigen::Vector3d& p, const Eigen::Vector3d& c, const Triple& size, int dim) {
  double outside2 = 0.0, inside = -1e300;
  for (int k = 0; k < dim; ++k) {
    const double d = std::abs(p[k] - c[k]) - 0.5 * size[k];
    outside2 += std::max(d, 0.0) * std::max(d, 0.0);
    inside = std::max(inside, d);
  }
  return inside > 0.0 ? std::sqrt(outside2) : inside;
}

}  // namespace

Eigen::Matrix3d bodyRotation(const BodyConfig& b) {
  // y is up: yaw turns about y, pitch about z (across), roll about x (along).
  return (Eigen::AngleAxisd(b.orientation[2], Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(b.orientation[1], Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(b.orientation[0], Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

template <int D>
fluid::BoundaryParticles<D> sampleBodySurface(const BodyConfig& body, double spacing) {
  const BodyShapeConfig& s = body.shape;
  const fluid::Vec<D> centre = toEigen(s.centre).template head<D>();
  fluid::BoundaryParticles<D> p;
  if (s.kind == "sphere" && s.sampling == "rings") {
    if constexpr (D == 3) p = fluid::sampleSphereRings(centre, s.radius, spacing);  // the reader allows it in 3D only
  } else if (s.kind == "sphere" || (s.kind == "cylinder" && D == 2)) {
    p = fluid::sampleSphere<D>(centre, s.radius, spacing);
  } else if (s.kind == "box") {
    const fluid::Vec<D> half = 0.5 * toEigen(s.size).template head<D>();
    p = fluid::sampleBoxSurface<D>(centre - half, centre + half, spacing, fluid::allFaces<D>(), fluid::NormalSide::Outward);
  } else if constexpr (D == 3) {
    p = sampleMeshSurface(s.mesh, spacing, fluid::NormalSide::Outward);  // cylinder or mesh
  } else {
    throw std::invalid_argument("body '" + body.name + "': a " + s.kind + " body is 3D only");
  }
  const fluid::Vec<D> start = toEigen(body.start()).template head<D>();
  for (auto& r : p.r) r += start;
  return p;
}

template <int D>
bool insideBody(const BodyConfig& body, const fluid::Vec<D>& r, double gap) {
  const BodyShapeConfig& s = body.shape;
  Eigen::Vector3d ground = Eigen::Vector3d::Zero();
  ground.template head<D>() = r;
  const Eigen::Vector3d local = bodyRotation(body).transpose() * (ground - toEigen(body.start()));
  const Eigen::Vector3d c = toEigen(s.centre);
  if (s.kind == "sphere" || (s.kind == "cylinder" && D == 2)) return (local - c).template head<D>().norm() < s.radius + gap;
  if (s.kind == "box") return signedBoxDistance(local, c, s.size, D) < gap;
  const Eigen::Vector3d lo = s.mesh.lower().array() - gap, hi = s.mesh.upper().array() + gap;
  if ((local.array() < lo.array()).any() || (local.array() > hi.array()).any()) return false;
  return meshContains(s.mesh, local) || distanceToMesh(s.mesh, local) < gap;
}

template fluid::BoundaryParticles<2> sampleBodySurface<2>(const BodyConfig&, double);
template fluid::BoundaryParticles<3> sampleBodySurface<3>(const BodyConfig&, double);
template bool insideBody<2>(const BodyConfig&, const fluid::Vec<2>&, double);
template bool insideBody<3>(const BodyConfig&, const fluid::Vec<3>&, double);

}  // namespace moorsph::io
