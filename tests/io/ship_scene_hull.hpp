#pragma once
// The moored hull of a METHOD.md 6.5 ship scene (cases/ship/*.yaml) as the input of the
// hydrostatic equilibrium solver (test_ship_equilibrium.hpp): its body, its identical
// spring lines' k and L0, the still level (the highest water top), and the pose its
// `position` puts it at. Shared by the ship scene tests and the heavy-ship stability case.
#include <algorithm>
#include <moorsph/io/scene_config.hpp>
#include "test_ship_equilibrium.hpp"

namespace moorsph::test {

inline test::MooredHull mooredHull(const io::SceneConfig& c) {
  const auto vec = [](const io::Triple& t) { return Eigen::Vector3d(t[0], t[1], t[2]); };
  test::MooredHull h;
  const io::BodyConfig& b = c.bodies.at(0);
  h.mesh = b.shape.mesh;
  h.mass = b.mass;
  h.centre_of_mass = vec(b.centre_of_mass);
  h.water_density = c.rho0;
  h.gravity = -c.gravity[1];
  for (const auto& w : c.water) h.still_level = std::max(h.still_level, w.box.upper[1]);
  h.z = b.position[2];
  for (const auto& m : c.moorings) {
    h.fairlead = vec(m.fairlead.point);
    h.anchors.push_back(vec(m.anchor.point));
    h.stiffness = m.stiffness;
    h.rest_length = m.rest_length;
  }
  return h;
}

/// The scene's start pose: reference point (x, y) and trim = the pitch about z.
inline test::HullPose scenePose(const io::SceneConfig& c) {
  const io::BodyConfig& b = c.bodies.at(0);
  return {b.position[0], b.position[1], b.orientation[1]};
}

}  // namespace moorsph::test
