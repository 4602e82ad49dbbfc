#pragma once
// The 2D scene of the body stability cases: a rectangular tank of still water (built
// by fluid::buildTankScene, hydrostatic start) with one rigid circular cylinder,
// coupled through coupling::CoSimulation as in cases/floating_box/submerged_release
// (a circle of boundary particles from fluid::sampleSphere, the water removed from
// its disc and dx/2 around it, a Planar body whose mass is density_ratio x the
// displaced mass per metre of span). Optionally a tension-only spring from the
// cylinder's bottom to an anchor on the floor below.
#include <cmath>
#include <memory>
#include <moorsph/bodies/tension_only_spring.hpp>
#include <moorsph/coupling/co_simulation.hpp>
#include <moorsph/fluid/shape_sampling.hpp>
#include <moorsph/fluid/tank_scene.hpp>

#include "stability_monitor.hpp"

namespace moorsph::stability {

struct CylinderCase {
  fluid::Vec<2> tank{0.6, 0.6};  ///< inner size [m]
  double depth = 0.4;            ///< still water depth [m]
  double dx = 0.01;
  double sound_speed = 0.0;      ///< 0: 10 sqrt(2 g depth)
  double mu = 0.01;              ///< [Pa s] (as submerged_release)
  double radius = 0.05;
  fluid::Vec<2> centre{0.3, 0.2};
  double density_ratio = 0.5;
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();  ///< initial velocity [m/s]
  bool fix_rotation = true;
  double release_time = 0.0;     ///< body held (fluid settles) until then [s]
  /// Tension-only spring to the floor below the centre; 0: none.
  double spring_stiffness = 0.0;  ///< [N/m]
  double spring_slack = 0.0;      ///< rest length minus the initial fairlead-anchor distance [m]
  std::vector<std::string> effects{"pressure", "viscosity", "xsph", "gravity", "walls"};

  double mass() const { return density_ratio * 1000.0 * std::acos(-1.0) * radius * radius; }  // per metre
};

inline std::unique_ptr<coupling::CoSimulation<2>> buildCylinderCase(const CylinderCase& c) {
  fluid::TankSpec<2> spec;
  spec.size = c.tank;
  spec.water_upper = fluid::Vec<2>(c.tank[0], c.depth);
  spec.dx = c.dx;
  spec.fluid.sound_speed = c.sound_speed > 0.0 ? c.sound_speed : 10.0 * std::sqrt(2.0 * 9.81 * c.depth);
  spec.fluid.mu = c.mu;
  spec.fluid.effects = c.effects;
  auto scene = fluid::buildTankScene<2>(spec);
  fluid::FluidParticles<2> water;
  for (std::size_t i = 0; i < scene.fluid.size(); ++i)
    if ((scene.fluid.r[i] - c.centre).norm() >= c.radius + 0.5 * c.dx)
      water.add(scene.fluid.r[i], scene.fluid.v[i], scene.fluid.rho[i], scene.fluid.m[i]);
  const Eigen::Vector3d origin(c.centre[0], c.centre[1], 0.0);
  scene.boundary.addSurface(fluid::sampleSphere<2>(c.centre, c.radius, c.dx),
                            fluid::SurfaceInfo{"cylinder", true, true, origin, true});

  auto system = std::make_unique<bodies::MultibodySystem>();
  bodies::RigidBodySpec body;
  body.name = "cylinder";
  body.mass = c.mass();
  body.mobilizer = bodies::Mobilizer::Planar;
  body.fixedDofs[static_cast<int>(bodies::Dof::RotationZ)] = c.fix_rotation;
  body.inertiaAboutCom = Eigen::Matrix3d::Identity() * 0.5 * body.mass * c.radius * c.radius;
  body.initial.position = origin;
  body.initial.velocity = c.velocity;
  system->addBody(body);
  if (c.spring_stiffness > 0.0) {
    bodies::LineAttachment at;
    at.fairleadBody = 0;
    at.fairleadPoint = Eigen::Vector3d(0.0, -c.radius, 0.0);
    at.anchorPoint = Eigen::Vector3d(c.centre[0], 0.0, 0.0);
    bodies::TensionOnlySpringParams p;
    p.stiffness = c.spring_stiffness;
    p.restLength = c.centre[1] - c.radius + c.spring_slack;
    system->addLine("cable", at, std::make_unique<bodies::TensionOnlySpring>(p));
  }
  system->initialize();
  return std::make_unique<coupling::CoSimulation<2>>(
      std::make_unique<fluid::FluidSimulation<2>>(scene.setup, water, scene.boundary), std::move(system),
      std::vector<coupling::CoupledBody>{{0, 1}}, coupling::CouplingOptions{c.release_time, 0.0});
}

}  // namespace moorsph::stability

namespace moorsph::stability {

/// What a body case records besides the monitor's contract.
struct BodyTrack {
  Eigen::Vector3d min_position = Eigen::Vector3d::Constant(1e9), max_position = Eigen::Vector3d::Constant(-1e9);
  double max_speed = 0.0;        ///< [m/s]
  double max_tension = 0.0;      ///< [N], the line's fairlead tension (if any)
  double initial_energy = 0.0;   ///< ledger total at the start [J]
  std::string error;             ///< the SimulationError, if the run stopped on one
};

/// Runs the case to `end`, sampling the monitor (fluid particles inside the cylinder
/// count as through the body) and the body's excursion after every step.
inline BodyTrack runCylinderCase(coupling::CoSimulation<2>& co, const CylinderCase& c, StabilityMonitor<2>& monitor,
                                 double end) {
  BodyTrack track;
  monitor.addBody("cylinder", [&co, r = c.radius](const fluid::Vec<2>& p) {
    return (p - co.bodies().kinematics(0).position.head<2>()).norm() - r;
  });
  track.initial_energy = co.calcEnergy().total();
  monitor.sample(track.initial_energy, 0.0);
  try {
    while (co.time() < end) {
      co.step();
      monitor.sample(co.calcEnergy().total(), 0.0);
      const auto k = co.bodies().kinematics(0);
      track.min_position = track.min_position.cwiseMin(k.position);
      track.max_position = track.max_position.cwiseMax(k.position);
      track.max_speed = std::max(track.max_speed, k.velocity.norm());
      if (co.bodies().lineCount() > 0)
        track.max_tension = std::max(track.max_tension, co.bodies().lineDiagnostics(0).fairleadTension);
    }
  } catch (const fluid::SimulationError& e) {
    track.error = e.what();
  }
  return track;
}

}  // namespace moorsph::stability
