#pragma once
// A fully submerged circular cylinder (2D) or sphere (3D) of a given density ratio,
// held at rest in still water while the fluid settles, then released. Shared by the
// light/heavy-body sweep (cases/floating_box/submerged_release.cpp) and the neutral
// and light-body tests. Rotation is held fixed so that the body heaves against
// potential flow: added mass C_a = 1 (cylinder) and 1/2 (sphere) times the displaced
// mass, so its initial acceleration is a0 = (1 - r)/(r + C_a) g for density ratio r.
// Header only: it needs bodies/, which a build without MOORSPH_WITH_BODIES lacks.
#include <cmath>
#include <functional>
#include <memory>
#include <moorsph/coupling/co_simulation.hpp>
#include <moorsph/fluid/box_geometry.hpp>
#include <moorsph/fluid/shape_sampling.hpp>
#include <moorsph/fluid/tank_scene.hpp>

namespace moorsph::cases {

/// Potential-flow added-mass coefficient of a circle (2D) or a sphere (3D).
template <int D>
constexpr double addedMassCoefficient() {
  return D == 2 ? 1.0 : 0.5;
}

/// Area (2D, per metre of span) or volume (3D) of the body [m^2 or m^3].
template <int D>
double displacedVolume(double radius) {
  const double pi = std::acos(-1.0);
  return D == 2 ? pi * radius * radius : 4.0 / 3.0 * pi * radius * radius * radius;
}

/// Potential-flow added-mass coefficient in the tank of buildSubmergedBody with R = 0.05 m
/// at 0.2 m above the floor: 2D 1.0547 (cases/floating_box/confined_added_mass.py, boundary
/// elements); 3D the unbounded sphere's 1/2 (the 3D tank's correction is not computed).
template <int D>
constexpr double tankAddedMassCoefficient() {
  return D == 2 ? 1.0547 : addedMassCoefficient<D>();
}

/// Potential-flow initial acceleration of a body of density ratio r at rest [m/s^2].
inline double releaseAcceleration(double ratio, double added_mass_coefficient, double g = 9.81) {
  return (1.0 - ratio) / (ratio + added_mass_coefficient) * g;
}

/// The fluid side of buildSubmergedBody: tank, water (kept at least dx/2 outside the
/// body) and the body's surface, movable and tracking its reactions. `adjust` may change
/// the tank's fluid set-up (method options) before it is built.
template <int D>
struct SubmergedBodyFluid {
  fluid::Scene<D> scene;
  fluid::FluidParticles<D> water;
  std::size_t body_surface = 0;
};

/// Tank 0.6 m (2D) or 0.3 m (3D) wide, 0.5 m of water; the body at `centre`: a circle
/// (sphere) of `radius`, or, when `box_half` is not zero, a box of those half-sizes.
template <int D>
SubmergedBodyFluid<D> buildSubmergedBodyFluid(double dx, double radius, const fluid::Vec<D>& centre,
                                              const std::function<void(fluid::TankSpec<D>&)>& adjust = {},
                                              const fluid::Vec<D>& box_half = fluid::Vec<D>::Zero()) {
  fluid::TankSpec<D> spec;
  const double width = D == 2 ? 0.6 : 0.3;  // 3D: a smaller tank keeps the particle count for this machine
  spec.size = fluid::Vec<D>::Constant(width);
  spec.size[1] = 0.6;
  spec.water_upper = spec.size;
  spec.water_upper[1] = 0.5;
  spec.dx = dx;
  spec.fluid.sound_speed = 10.0 * std::sqrt(2.0 * 9.81 * 0.5);
  spec.fluid.mu = 0.01;
  spec.fluid.effects = {"pressure", "viscosity", "xsph", "density_diffusion", "gravity", "walls"};
  if (adjust) adjust(spec);
  SubmergedBodyFluid<D> out{fluid::buildTankScene<D>(spec), {}, 0};
  const auto& all = out.scene.fluid;
  const bool box = box_half.norm() > 0.0;
  auto outside = [&](const fluid::Vec<D>& r) {  // at least dx/2 outside the body
    if (!box) return (r - centre).norm() >= radius + 0.5 * dx;
    return ((r - centre).cwiseAbs() - box_half).maxCoeff() >= 0.5 * dx;
  };
  for (std::size_t i = 0; i < all.size(); ++i)
    if (outside(all.r[i])) out.water.add(all.r[i], all.v[i], all.rho[i], all.m[i]);
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  origin.head<D>() = centre;
  out.body_surface = out.scene.boundary.addSurface(
      box ? fluid::sampleBoxSurface<D>(centre - box_half, centre + box_half, dx, fluid::allFaces<D>(),
                                       fluid::NormalSide::Outward)
          : fluid::sampleSphere<D>(centre, radius, dx),
      fluid::SurfaceInfo{"body", true, true, origin, true});
  return out;
}

/// The body of buildSubmergedBodyFluid, of density ratio `ratio`, held until `release`.
template <int D>
coupling::CoSimulation<D> buildSubmergedBody(double dx, double ratio, double radius, const fluid::Vec<D>& centre,
                                              double release) {
  auto f = buildSubmergedBodyFluid<D>(dx, radius, centre);
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  origin.head<D>() = centre;
  auto system = std::make_unique<bodies::MultibodySystem>();
  bodies::RigidBodySpec body;
  body.name = "body";
  body.mass = ratio * 1000.0 * displacedVolume<D>(radius);  // 2D: per metre of span
  body.mobilizer = D == 2 ? bodies::Mobilizer::Planar : bodies::Mobilizer::Free;
  for (int k = 3; k < 6; ++k) body.fixedDofs[k] = true;  // no rotation: heave against potential flow
  body.inertiaAboutCom = Eigen::Matrix3d::Identity() * 0.4 * body.mass * radius * radius;
  body.initial.position = origin;
  system->addBody(body);
  system->initialize();
  return coupling::CoSimulation<D>(std::make_unique<fluid::FluidSimulation<D>>(f.scene.setup, f.water, f.scene.boundary),
                                   std::move(system), {{0, 1}}, {release, 0.0});
}

}  // namespace moorsph::cases
