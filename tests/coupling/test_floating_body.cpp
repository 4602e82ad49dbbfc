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

#include <moorsph/cases/floating_box.hpp>

using namespace moorsph;


namespace {

/// Records, after each corrector, the wrench the coupling applied, the reactions
/// it was taken from and the body's velocity.
class StepProbe final : public fluid::FluidEffect<2> {
 public:
  StepProbe(const coupling::BodyCoupling<2>& c, const fluid::Walls<2>& w, const bodies::MultibodySystem& s)
      : coupling_(c), walls_(w), system_(s) {}
  const char* name() const override { return "step_probe"; }
  void addRates(fluid::FluidContext<2>&) override {}
  void advanceTo(double t, fluid::StepStage stage) override {
    if (stage != fluid::StepStage::Corrected) return;
    const auto reactions = walls_.calcSurfaceWrench(1, walls_.surfaceMotion(1).position);
    // (Force only: the surface has moved since the torque was taken about its origin.)
    max_fluid_error = std::max(max_fluid_error, (reactions.force - coupling_.fluidWrench(0).force).norm());
    if (t <= coupling_.options().release_time) {  // held: nothing applied, the fluid's load still read
      max_held_applied = std::max(max_held_applied, coupling_.appliedWrench(0).force.norm());
      max_held_load = std::max(max_held_load, coupling_.fluidWrench(0).force.norm());
      return;
    }
    max_hold_error = std::max(max_hold_error, (reactions.force - coupling_.appliedWrench(0).force).norm());
    forces.push_back(coupling_.appliedWrench(0).force);
    velocities.push_back(system_.kinematics(0).velocity);
    times.push_back(t);
    bottoms.push_back(system_.kinematics(0).position[1]);
  }
  double max_hold_error = 0.0;
  double max_fluid_error = 0.0;   ///< fluidWrench against the surface's reactions, every corrector
  double max_held_applied = 0.0;  ///< largest wrench applied while the body is held
  double max_held_load = 0.0;     ///< largest fluid force on the held body
  std::vector<Eigen::Vector3d> forces, velocities;
  std::vector<double> times, bottoms;

 private:
  const coupling::BodyCoupling<2>& coupling_;
  const fluid::Walls<2>& walls_;
  const bodies::MultibodySystem& system_;
};

}  // namespace

TEST(FloatingBody, BoxFloatsAtArchimedesDraughtAndCouplingHoldsPredictedWrench) {
  cases::FloatingBox box;
  box.fix_rotation = true;  // heave and surge only: Newton check below
  auto scene = cases::buildFloatingBox(box);
  auto& sim = *scene.fluid;
  auto& system = *scene.system;
  system.initialize();
  const double level = scene.still_level;
  auto link = std::make_unique<coupling::BodyCoupling<2>>(system, sim.updWalls(), std::vector<coupling::CoupledBody>{{0, 1}},
                                                          coupling::CouplingOptions{0.2, 0.0});
  auto probe = std::make_unique<StepProbe>(*link, *sim.walls(), system);
  StepProbe* p = probe.get();
  sim.addEffect(std::move(link));
  sim.addEffect(std::move(probe));
  sim.advanceTo(2.2);

  // Zero-order hold of the predicted-state reactions, and Newton per step.
  EXPECT_EQ(p->max_hold_error, 0.0);
  // The fluid's own wrench is the surface's reactions at every corrector, the hold included;
  // while held nothing reaches the body, though the water pushes on it (Archimedes 98.1 N/m).
  EXPECT_EQ(p->max_fluid_error, 0.0);
  EXPECT_EQ(p->max_held_applied, 0.0);
  EXPECT_GT(p->max_held_load, 0.5 * box.mass() * 9.81);
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
