// Light-body hard case (issue 5): a fully submerged circular cylinder (2D) lighter
// than water, held while the fluid settles, then released from rest. Potential flow
// gives the 2D cylinder an added mass equal to the displaced mass rho pi R^2, so its
// initial acceleration is a0 = (1 - r)/(r + 1) g for density ratio r; at r = 0.1 the
// added mass is ten times the body's, the classic failure case of explicit coupling.
// Prints per ratio whether the run stayed finite, the mean acceleration over the first
// 20 ms against a0, and the rise after 0.1 s.
// Usage: moorsph_submerged_release [dx=0.01] [ratios...]
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>
#include <moorsph/coupling/co_simulation.hpp>
#include <moorsph/fluid/shape_sampling.hpp>
#include <moorsph/fluid/tank_scene.hpp>

namespace {

using namespace moorsph;

coupling::CoSimulation<2> buildScene(double dx, double ratio, double radius, const fluid::Vec<2>& centre, double release) {
  const double pi = std::acos(-1.0);
  fluid::TankSpec<2> spec;
  spec.size = fluid::Vec<2>(0.6, 0.6);
  spec.water_upper = fluid::Vec<2>(0.6, 0.5);
  spec.dx = dx;
  spec.fluid.sound_speed = 10.0 * std::sqrt(2.0 * 9.81 * 0.5);
  spec.fluid.mu = 0.01;
  spec.fluid.effects = {"pressure", "viscosity", "xsph", "density_diffusion", "gravity", "walls"};
  auto scene = fluid::buildTankScene<2>(spec);
  fluid::FluidParticles<2> water;
  for (std::size_t i = 0; i < scene.fluid.size(); ++i)
    if ((scene.fluid.r[i] - centre).norm() >= radius + 0.5 * dx)
      water.add(scene.fluid.r[i], scene.fluid.v[i], scene.fluid.rho[i], scene.fluid.m[i]);
  scene.boundary.addSurface(fluid::sampleSphere<2>(centre, radius, dx),
                            fluid::SurfaceInfo{"cylinder", true, true, Eigen::Vector3d(centre[0], centre[1], 0.0)});
  auto system = std::make_unique<bodies::MultibodySystem>();
  bodies::RigidBodySpec body;
  body.name = "cylinder";
  body.mass = ratio * 1000.0 * pi * radius * radius;  // per metre of span
  body.mobilizer = bodies::Mobilizer::Planar;
  body.fixedDofs[static_cast<int>(bodies::Dof::RotationZ)] = true;
  body.inertiaAboutCom = Eigen::Matrix3d::Identity() * 0.5 * body.mass * radius * radius;
  body.initial.position = Eigen::Vector3d(centre[0], centre[1], 0.0);
  system->addBody(body);
  system->initialize();
  return coupling::CoSimulation<2>(std::make_unique<fluid::FluidSimulation<2>>(scene.setup, water, scene.boundary),
                                   std::move(system), {{0, 1}}, {release, 0.0});
}

}  // namespace

int main(int argc, char** argv) {
  const double dx = argc > 1 ? std::atof(argv[1]) : 0.01;
  std::vector<double> ratios{0.1, 0.2, 0.5, 0.8};
  if (argc > 2) ratios.clear();
  for (int a = 2; a < argc; ++a) ratios.push_back(std::atof(argv[a]));
  const double radius = 0.05, release = 0.3;
  const fluid::Vec<2> centre(0.3, 0.2);
  std::printf("# cylinder R = %.3f m (%.1f dx), dx = %.4f m, release at %.2f s\n", radius, radius / dx, dx, release);
  std::printf("# ratio  stable  mean_accel_0-20ms  potential_flow_a0  ratio_to_a0  rise_0.1s_m\n");
  for (double ratio : ratios) {
    auto co = buildScene(dx, ratio, radius, centre, release);
    double v20 = 0.0;
    bool stable = true;
    try {
      while (co.time() < release + 0.1) {
        co.step();
        if (v20 == 0.0 && co.time() >= release + 0.02) v20 = co.bodies().kinematics(0).velocity[1] / (co.time() - release);
      }
    } catch (const std::exception& e) {
      stable = false;
      std::fprintf(stderr, "ratio %.2f: %s\n", ratio, e.what());
    }
    const double a0 = (1.0 - ratio) / (ratio + 1.0) * 9.81;
    std::printf("%6.2f  %6s  %17.3f  %17.3f  %11.3f  %11.4f\n", ratio, stable ? "yes" : "NO", v20, a0, v20 / a0,
                co.bodies().kinematics(0).position[1] - centre[1]);
  }
}
