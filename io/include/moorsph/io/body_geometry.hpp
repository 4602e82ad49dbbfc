#pragma once
// The surfaces of a scene's rigid bodies as boundary particles, and where water must
// not start around them. Particles are sampled in the body frame (origin = the body's
// reference point) and translated to the reference point's start position without
// rotating them: the walls keep them as body-frame reference coordinates and the
// coupling places them at the body's pose (orientation included) before the first
// fluid evaluation (coupling/body_coupling.hpp).
#include <Eigen/Core>
#include <moorsph/fluid/boundary_particles.hpp>
#include <moorsph/io/scene_config.hpp>

namespace moorsph::io {

/// Body -> ground rotation of the scene's orientation (y up): Ry(yaw) Rz(pitch) Rx(roll).
Eigen::Matrix3d bodyRotation(const BodyConfig& body);

/// The body's surface particles (normals out of the body), at body-frame offsets
/// from its start position.
template <int D>
fluid::BoundaryParticles<D> sampleBodySurface(const BodyConfig& body, double spacing);

/// True if the ground point r lies inside the body at its start pose, or within `gap`
/// of its surface (a fluid particle there would be thrown off by the wall force).
template <int D>
bool insideBody(const BodyConfig& body, const fluid::Vec<D>& r, double gap);

}  // namespace moorsph::io
