// Two-way coupling of a rigid body with the fluid (coupling/BodyCoupling), 2D.
//  - Step order and zero-order hold: the wrench Simbody applies over a fluid step is
//    the sum of the boundary reactions of the predicted state, and the body's
//    velocity change over the step is (F/m + g) dt (Newton, translation only).
//  - A box of half the density of water floats at the Archimedes draught
//    m / (rho w) within 2% (time average, every step, after release).
#include <gtest/gtest.h>

#include <cmath>
#include <moorsph/coupling/body_coupling.hpp>
#include <moorsph/fluid/box_geometry.hpp>
#include <moorsph/fluid/fluid_simulation.hpp>
#include <moorsph/fluid/tank_scene.hpp>

using namespace moorsph;

namespace {

struct FloatingBox {
  double tank_length = 0.8, depth = 0.2, dx = 0.01, width = 0.2, height = 0.1, density_ratio = 0.5;
  double mass() const { return density_ratio * 1000.0 * width * height; }  // kg per metre of span
  double draught() const { return mass() / (1000.0 * width); }             // Archimedes, 2D
};

/// Records, after each corrector, the wrench the coupling applied, the reactions
/// it was taken from and the body's velocity.
class StepProbe final : public fluid::FluidEffect<2> {
 public:
  StepProbe(const coupling::BodyCoupling<2>& c, const fluid::Walls<2>& w, const bodies::MultibodySystem& s)
      : coupling_(c), walls_(w), system_(s) {}
  const char* name() const override { return "step_probe"; }
  void addRates(fluid::FluidContext<2>&) override {}
  void advanceTo(double t, fluid::StepStage stage) override {
    if (stage != fluid::StepStage::Corrected || t <= coupling_.options().release_time) return;
    const auto reactions = walls_.calcSurfaceWrench(1, walls_.surfaceMotion(1).position);
    max_hold_error = std::max(max_hold_error, (reactions.force - coupling_.appliedWrench(0).force).norm());
    forces.push_back(coupling_.appliedWrench(0).force);
    velocities.push_back(system_.kinematics(0).velocity);
    times.push_back(t);
    bottoms.push_back(system_.kinematics(0).position[1]);
  }
  double max_hold_error = 0.0;
  std::vector<Eigen::Vector3d> forces, velocities;
  std::vector<double> times, bottoms;

 private:
  const coupling::BodyCoupling<2>& coupling_;
  const fluid::Walls<2>& walls_;
  const bodies::MultibodySystem& system_;
};

}  // namespace

TEST(FloatingBody, BoxFloatsAtArchimedesDraughtAndCouplingHoldsPredictedWrench) {
  const FloatingBox box;
  fluid::TankSpec<2> spec;
  spec.size = fluid::Vec<2>(box.tank_length, 0.4);
  spec.water_upper = fluid::Vec<2>(box.tank_length, box.depth);
  spec.dx = box.dx;
  spec.fluid.sound_speed = 20.0;  // 10 sqrt(2 g depth)
  spec.fluid.mu = 0.05;           // raised to damp the sloshing the box radiates (METHOD 1 allows it)
  spec.fluid.effects = {"pressure", "viscosity", "xsph", "gravity", "walls"};
  auto scene = fluid::buildTankScene<2>(spec);

  // Box at the Archimedes draught below the still level of the final state, which is
  // raised by the displaced area: level = (water area + w d) / L.
  fluid::FluidParticles<2> water;
  const double level0 = box.depth;  // level before the box is placed
  const fluid::Vec<2> centre(box.tank_length / 2, level0 - box.draught() + box.height / 2);
  for (std::size_t i = 0; i < scene.fluid.size(); ++i) {
    const auto& r = scene.fluid.r[i];
    if (std::abs(r[0] - centre[0]) < box.width / 2 && std::abs(r[1] - centre[1]) < box.height / 2) continue;
    water.add(r, scene.fluid.v[i], scene.fluid.rho[i], scene.fluid.m[i]);
  }
  const double level = (water.size() * box.dx * box.dx + box.width * box.draught()) / box.tank_length;
  const fluid::Vec<2> half(box.width / 2, box.height / 2);
  scene.boundary.addSurface(fluid::sampleBoxSurface<2>(centre - half, centre + half, box.dx, fluid::allFaces<2>(),
                                                       fluid::NormalSide::Outward),
                            fluid::SurfaceInfo{"box", true, true, Eigen::Vector3d(centre[0], centre[1], 0.0)});
  fluid::FluidSimulation<2> sim(scene.setup, water, scene.boundary);

  bodies::MultibodySystem system;
  bodies::RigidBodySpec body;
  body.name = "box";
  body.mass = box.mass();
  body.mobilizer = bodies::Mobilizer::Planar;
  body.fixedDofs[static_cast<int>(bodies::Dof::RotationZ)] = true;  // heave and surge only: Newton check below
  body.inertiaAboutCom = Eigen::Matrix3d::Identity() * box.mass() * (box.width * box.width + box.height * box.height) / 12;
  body.initial.position = Eigen::Vector3d(centre[0], centre[1], 0.0);
  system.addBody(body);
  system.initialize();
  auto link = std::make_unique<coupling::BodyCoupling<2>>(system, sim.updWalls(), std::vector<coupling::CoupledBody>{{0, 1}},
                                                          coupling::CouplingOptions{0.2, 0.0});
  auto probe = std::make_unique<StepProbe>(*link, *sim.walls(), system);
  StepProbe* p = probe.get();
  sim.addEffect(std::move(link));
  sim.addEffect(std::move(probe));
  sim.advanceTo(2.2);

  // Zero-order hold of the predicted-state reactions, and Newton per step.
  EXPECT_EQ(p->max_hold_error, 0.0);
  double worst_newton = 0.0;
  for (std::size_t k = 1; k < p->times.size(); ++k) {
    const double dt = p->times[k] - p->times[k - 1];
    const Eigen::Vector3d expected = p->velocities[k - 1] + dt * (p->forces[k] / box.mass() + Eigen::Vector3d(0, -9.81, 0));
    worst_newton = std::max(worst_newton, (p->velocities[k] - expected).norm());
  }
  EXPECT_LT(worst_newton, 1e-6) << "body velocity change differs from (F/m + g) dt";

  // Draught: time average of the box bottom over the last 1.5 s (several heave periods).
  double sum = 0.0;
  int n = 0;
  for (std::size_t k = 0; k < p->times.size(); ++k)
    if (p->times[k] > 0.7) {
      sum += p->bottoms[k] - box.height / 2;
      ++n;
    }
  const double draught = level - sum / n;
  std::printf("draught %.5f m (Archimedes %.5f m, error %.2f%%), %zu fluid particles, %zu steps\n", draught,
              box.draught(), 100.0 * (draught / box.draught() - 1.0), sim.fluid().size(), sim.stepCount());
  EXPECT_NEAR(draught, box.draught(), 0.02 * box.draught());
}
