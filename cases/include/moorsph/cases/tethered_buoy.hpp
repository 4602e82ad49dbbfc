#pragma once
// The tethered laboratory buoy of METHOD.md section 6.2: a sphere (R = 0.1015 m,
// 1.745 kg, centre of mass 27 mm below the centroid) tethered from its bottom point by
// a tension-only spring (k = 30.88 N/m) to an anchor 0.71 m below the still level
// (9 cm above the floor of the 0.8 m deep laboratory tank). The rest length is set so
// the buoy floats half submerged at rest:
//   T0 = B_half - m g = rho g (2/3) pi R^3 - m g = 21.4839 - 17.1185 = 4.3654 N,
//   L0 = (0.71 m - R) - T0 / k = 0.46713 m.
// The line is a spring, not a body in the water, so the fluid may be shallower than
// the laboratory's 0.8 m: the anchor then lies below the fluid's floor at the
// laboratory's depth below the still level, and the cable's geometry is unchanged.
// The vertical release pulls the centroid 0.12 m below its rest height, the
// horizontal one 0.508 m along the surface; the body is held while the fluid
// settles around it (release_time) and then let go.
// Header only: it needs bodies/, which a build without MOORSPH_WITH_BODIES lacks.
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <moorsph/bodies/mooring_factory.hpp>
#include <moorsph/bodies/multibody_system.hpp>
#include <moorsph/coupling/co_simulation.hpp>
#include <moorsph/fluid/settling_damping.hpp>
#include <moorsph/fluid/shape_sampling.hpp>
#include <moorsph/fluid/tank_scene.hpp>

namespace moorsph::cases {

/// The buoy and its rig, METHOD.md section 6.2 (SI units).
struct LabBuoy {
  double radius = 0.1015;
  double mass = 1.745;
  double com_below_centroid = 0.027;
  Eigen::Vector3d inertia_about_com{1.735209e-3, 1.776363e-3, 1.735209e-3};  ///< y = symmetry axis
  double stiffness = 30.88;
  double anchor_below_still_level = 0.71;  ///< 0.8 m depth - 0.09 m
  double rho = 1000.0, g = 9.81;

  double halfBuoyancy() const { return rho * g * 2.0 / 3.0 * std::acos(-1.0) * std::pow(radius, 3); }
  double pretension() const { return halfBuoyancy() - mass * g; }
  double restLength() const { return anchor_below_still_level - radius - pretension() / stiffness; }
};

enum class BuoyRelease { Rest, Vertical, Horizontal };

struct TetheredBuoyTank {
  BuoyRelease release = BuoyRelease::Vertical;
  double dx = 0.02;          ///< fluid spacing [m]
  double length = 1.0;       ///< x [m]
  double width = 1.0;        ///< z [m]
  double depth = 0.5;        ///< still-water depth of the fluid [m] (laboratory: 0.8)
  double release_time = 0.3; ///< bodies held while the fluid settles [s]
  /// Velocity damping rate of the fluid while the buoy is held [1/s] (0: none;
  /// fluid/settling_damping.hpp).
  double settling_damping = 0.0;
  double mu = 1.0e-3;        ///< dynamic viscosity [Pa s] (water)
  double b_off = 0.5;
  double h_factor = 1.2;     ///< h / dx (METHOD.md reference 1.2)
  double boundary_h_factor = 0.0;  ///< the wall law's h_w / dx; 0: h
  /// The wall law: METHOD.md's (Reference) or its conservative form, which keeps the
  /// free buoy from the wall law's flutter (fluid/boundary_force_law.hpp).
  fluid::BoundaryForceForm boundary_force = fluid::BoundaryForceForm::Reference;
  double cfl = 0.5;          ///< CFL number of the fluid step (METHOD.md reference 0.5)
  double sound_speed_factor = 10.0;  ///< c_s = factor sqrt(2 g depth) (METHOD.md: 10)
  double boundary_strength = 0.01;   ///< wall force scale (METHOD.md: 0.01)
  bool density_diffusion = true;
  fluid::DensityDiffusionForm density_diffusion_form = fluid::DensityDiffusionForm::Fourtakas;
  /// The floor as mirror images (the mirror_floor effect) instead of a row of wall particles.
  bool mirror_floor = false;
  /// The tank's four side walls as mirror images too (the mirror_walls effect).
  bool mirror_walls = false;
  /// Spray thrown over the open tank's walls is removed (the outflow effect) instead of
  /// stopping the run: a buoy breaching at D/8 throws droplets 1 m up.
  bool outflow = false;
  double vertical_pull = 0.12;     ///< 6.2a [m]
  double horizontal_pull = 0.508;  ///< 6.2b [m]
  std::string mooring_model = "tension_only_spring";
  /// Sphere on mirror-symmetric latitude rings (fluid::sampleSphereRings) instead of a
  /// Fibonacci lattice: at D/6 the buoy left at rest drifted 8.5 mm sideways in 3 s on
  /// the lattice and 1.4 mm on the rings (tests/coupling/test_lab_buoy_rest.cpp).
  bool ring_sampling = true;
  LabBuoy buoy;
};

struct TetheredBuoyScene {
  std::unique_ptr<coupling::CoSimulation<3>> co;
  Eigen::Vector3d rest;      ///< centroid at rest: half submerged at the still level [m]
  Eigen::Vector3d start;     ///< centroid when released [m]
  double still_level = 0.0;  ///< with the buoy at rest [m]
  std::size_t particles = 0;
  std::size_t buoy_surface = 0;  ///< the buoy's boundary surface (Walls::calcSurfaceWrench)
};

inline TetheredBuoyScene buildTetheredBuoy(const TetheredBuoyTank& t) {
  const LabBuoy& b = t.buoy;
  const double pi = std::acos(-1.0);
  if (2.0 * b.radius < 5.0 * t.dx) throw std::invalid_argument("tethered buoy: dx coarser than D/5");
  fluid::TankSpec<3> spec;
  spec.size = fluid::Vec<3>(t.length, t.depth + 0.25, t.width);
  spec.water_upper = fluid::Vec<3>(t.length, t.depth, t.width);
  spec.dx = t.dx;
  spec.fluid.sound_speed = t.sound_speed_factor * std::sqrt(2.0 * b.g * t.depth);  // > 10x the buoy's ~1.3 m/s
  spec.fluid.mu = t.mu;
  spec.fluid.method.boundary_offset = t.b_off;
  spec.fluid.method.h_factor = t.h_factor;
  spec.fluid.method.boundary_h_factor = t.boundary_h_factor;
  spec.fluid.method.boundary_force_form = t.boundary_force;
  spec.fluid.method.cfl = t.cfl;
  spec.fluid.method.density_diffusion_form = t.density_diffusion_form;
  spec.fluid.method.boundary_strength = t.boundary_strength;
  spec.fluid.effects = {"pressure", "viscosity", "xsph", "gravity", "walls"};
  if (t.density_diffusion) spec.fluid.effects.push_back("density_diffusion");
  if (t.mirror_floor) spec.fluid.effects.push_back("mirror_floor");
  if (t.mirror_walls) spec.fluid.effects.push_back("mirror_walls");
  if (t.outflow) spec.fluid.effects.push_back("outflow");
  auto scene = fluid::buildTankScene<3>(spec);

  TetheredBuoyScene out;
  out.rest = Eigen::Vector3d(t.length / 2, t.depth, t.width / 2);
  if (t.release == BuoyRelease::Horizontal) out.rest[0] = t.length / 2 - t.horizontal_pull / 2;  // swings about the middle
  out.start = out.rest;
  if (t.release == BuoyRelease::Vertical) out.start[1] -= t.vertical_pull;
  if (t.release == BuoyRelease::Horizontal) out.start[0] += t.horizontal_pull;

  // Fluid particles start at least dx/2 outside the sphere (as they start dx/2 inside walls).
  auto waterAround = [&](const Eigen::Vector3d& centre) {
    fluid::FluidParticles<3> w;
    for (std::size_t i = 0; i < scene.fluid.size(); ++i)
      if ((scene.fluid.r[i] - centre).norm() >= b.radius + 0.5 * t.dx)
        w.add(scene.fluid.r[i], scene.fluid.v[i], scene.fluid.rho[i], scene.fluid.m[i]);
    return w;
  };
  // Still level with the buoy at rest: the water's volume plus the half sphere it
  // displaces, over the tank's area; the buoy's heights follow that level.
  const double area = t.length * t.width;
  auto stillLevel = [&](std::size_t n) {
    return (n * std::pow(t.dx, 3) + 2.0 / 3.0 * pi * std::pow(b.radius, 3)) / area;
  };
  const double shift = stillLevel(waterAround(out.start).size()) - t.depth;
  out.rest[1] += shift;
  out.start[1] += shift;
  fluid::FluidParticles<3> water = waterAround(out.start);
  out.still_level = stillLevel(water.size());
  out.particles = water.size();

  out.buoy_surface = scene.boundary.addSurface(t.ring_sampling ? fluid::sampleSphereRings(out.start, b.radius, t.dx)
                                            : fluid::sampleSphere<3>(out.start, b.radius, t.dx),
                            fluid::SurfaceInfo{"buoy", true, true, out.start, true});
  auto fluid_sim = std::make_unique<fluid::FluidSimulation<3>>(scene.setup, water, scene.boundary);
  if (t.settling_damping > 0.0)
    fluid_sim->addEffect(std::make_unique<fluid::SettlingDamping<3>>(t.settling_damping, t.release_time));

  auto system = std::make_unique<bodies::MultibodySystem>();
  bodies::RigidBodySpec body;
  body.name = "buoy";
  body.mass = b.mass;
  body.centreOfMass = Eigen::Vector3d(0.0, -b.com_below_centroid, 0.0);
  body.inertiaAboutCom = b.inertia_about_com.asDiagonal();
  body.mobilizer = bodies::Mobilizer::Free;
  body.initial.position = out.start;
  const int id = system->addBody(body);

  bodies::MooringLineParams line;
  line.model = t.mooring_model;
  line.stiffness = b.stiffness;
  line.restLength = b.restLength();
  bodies::LineAttachment at;
  at.fairleadBody = id;
  at.fairleadPoint = Eigen::Vector3d(0.0, -b.radius, 0.0);  // the buoy's bottom point
  at.anchorPoint = Eigen::Vector3d(out.rest[0], out.still_level - b.anchor_below_still_level, out.rest[2]);
  system->addLine("tether", at, bodies::makeMooringLine(line));
  system->initialize();
  out.co = std::make_unique<coupling::CoSimulation<3>>(std::move(fluid_sim), std::move(system),
                                                       std::vector<coupling::CoupledBody>{{id, out.buoy_surface}},
                                                       coupling::CouplingOptions{t.release_time, 0.0});
  return out;
}

}  // namespace moorsph::cases
