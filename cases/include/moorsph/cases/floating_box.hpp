#pragma once
// A 2D tank with a floating box placed at its Archimedes draught below the still
// level (which the displaced area raises): the coupling tests and the light-body
// sweep (cases/floating_box) use it. Header only: it needs bodies/, which a build
// without MOORSPH_WITH_BODIES lacks.
#include <cmath>
#include <memory>
#include <moorsph/bodies/multibody_system.hpp>
#include <moorsph/fluid/box_geometry.hpp>
#include <moorsph/fluid/fluid_simulation.hpp>
#include <moorsph/fluid/tank_scene.hpp>

namespace moorsph::cases {

struct FloatingBox {
  double tank_length = 0.8, depth = 0.2, dx = 0.01, width = 0.2, height = 0.1, density_ratio = 0.5;
  double mu = 0.05;  ///< raised to damp the sloshing the box radiates (METHOD 1 allows it)
  bool track_tank = false;
  bool fix_rotation = false;
  double mass() const { return density_ratio * 1000.0 * width * height; }  // kg per metre of span
  double draught() const { return mass() / (1000.0 * width); }             // Archimedes, 2D
};

struct FloatingBoxScene {
  std::unique_ptr<fluid::FluidSimulation<2>> fluid;
  std::unique_ptr<bodies::MultibodySystem> system;  ///< built, not initialized (lines may be added)
  double still_level = 0.0;                          ///< with the box floating [m]
  fluid::Vec<2> centre;                              ///< initial box centre [m]
};

inline FloatingBoxScene buildFloatingBox(const FloatingBox& box) {
  fluid::TankSpec<2> spec;
  spec.size = fluid::Vec<2>(box.tank_length, 0.4);
  spec.water_upper = fluid::Vec<2>(box.tank_length, box.depth);
  spec.dx = box.dx;
  spec.fluid.sound_speed = 20.0;  // 10 sqrt(2 g depth)
  spec.fluid.mu = box.mu;
  spec.fluid.effects = {"pressure", "viscosity", "xsph", "gravity", "walls"};
  auto scene = fluid::buildTankScene<2>(spec);
  scene.boundary.surfaces[0].track_reaction = box.track_tank;

  FloatingBoxScene out;
  out.centre = fluid::Vec<2>(box.tank_length / 2, box.depth - box.draught() + box.height / 2);
  fluid::FluidParticles<2> water;
  for (std::size_t i = 0; i < scene.fluid.size(); ++i) {
    const auto& r = scene.fluid.r[i];
    if (std::abs(r[0] - out.centre[0]) < box.width / 2 && std::abs(r[1] - out.centre[1]) < box.height / 2) continue;
    water.add(r, scene.fluid.v[i], scene.fluid.rho[i], scene.fluid.m[i]);
  }
  out.still_level = (water.size() * box.dx * box.dx + box.width * box.draught()) / box.tank_length;
  const fluid::Vec<2> half(box.width / 2, box.height / 2);
  scene.boundary.addSurface(fluid::sampleBoxSurface<2>(out.centre - half, out.centre + half, box.dx,
                                                       fluid::allFaces<2>(), fluid::NormalSide::Outward),
                            fluid::SurfaceInfo{"box", true, true, Eigen::Vector3d(out.centre[0], out.centre[1], 0.0), true});
  out.fluid = std::make_unique<fluid::FluidSimulation<2>>(scene.setup, water, scene.boundary);

  out.system = std::make_unique<bodies::MultibodySystem>();
  bodies::RigidBodySpec body;
  body.name = "box";
  body.mass = box.mass();
  body.mobilizer = bodies::Mobilizer::Planar;
  body.fixedDofs[static_cast<int>(bodies::Dof::RotationZ)] = box.fix_rotation;
  body.inertiaAboutCom =
      Eigen::Matrix3d::Identity() * box.mass() * (box.width * box.width + box.height * box.height) / 12;
  body.initial.position = Eigen::Vector3d(out.centre[0], out.centre[1], 0.0);
  out.system->addBody(body);
  return out;
}

}  // namespace moorsph::cases
