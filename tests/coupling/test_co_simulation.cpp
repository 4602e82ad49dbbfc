// The co-simulation as a whole (2D floating box):
//  - Newton's third law: over a run, the change of fluid plus body momentum equals
//    the external impulse (gravity on both, and the tank walls' push on the fluid,
//    taken from the tank's own reactions), to round-off: the fluid's wall force on
//    the box and the box's reaction cancel exactly.
//  - The same scene runs with each mooring model, chosen by one word.
#include <gtest/gtest.h>

#include <moorsph/bodies/mooring_factory.hpp>
#include <moorsph/coupling/co_simulation.hpp>

#include <moorsph/cases/floating_box.hpp>

using namespace moorsph;

namespace {

/// Sums, after each corrector, dt times the predicted-state external force on
/// fluid + box: (M_fluid + M_box) g minus the tank's reactions (the force the fluid
/// exerts on the tank, whose opposite pushes the fluid).
class ImpulseProbe final : public fluid::FluidEffect<2> {
 public:
  ImpulseProbe(const fluid::Walls<2>& walls, double total_mass) : walls_(walls), weight_(0.0, -9.81 * total_mass, 0.0) {}
  const char* name() const override { return "impulse_probe"; }
  void addRates(fluid::FluidContext<2>&) override {}
  void advanceTo(double t, fluid::StepStage stage) override {
    if (stage == fluid::StepStage::Start) last_t_ = t;
    if (stage != fluid::StepStage::Corrected) return;
    const auto tank = walls_.calcSurfaceWrench(0, fluid::Vec<2>::Zero());
    impulse += (t - last_t_) * (weight_ - tank.force);
    last_t_ = t;
  }
  Eigen::Vector3d impulse = Eigen::Vector3d::Zero();

 private:
  const fluid::Walls<2>& walls_;
  Eigen::Vector3d weight_;
  double last_t_ = 0.0;
};

Eigen::Vector3d totalMomentum(const coupling::CoSimulation<2>& co, double body_mass) {
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  const auto& f = co.fluid().fluid();
  for (std::size_t i = 0; i < f.size(); ++i) p.head<2>() += f.m[i] * f.v[i];
  return p + body_mass * co.bodies().kinematics(0).velocity;
}

}  // namespace

TEST(CoSimulation, MomentumChangeEqualsExternalImpulse) {
  cases::FloatingBox box;
  box.track_tank = true;
  box.density_ratio = 0.35;  // released high in the water: it rises and sloshes
  auto scene = cases::buildFloatingBox(box);
  scene.system->initialize();
  double fluid_mass = 0.0;
  for (double m : scene.fluid->fluid().m) fluid_mass += m;
  auto probe = std::make_unique<ImpulseProbe>(*scene.fluid->walls(), fluid_mass + box.mass());
  ImpulseProbe* impulse = probe.get();
  coupling::CoSimulation<2> co(std::move(scene.fluid), std::move(scene.system), {{0, 1}}, {0.0, 0.0});
  co.updFluid().addEffect(std::move(probe));
  const Eigen::Vector3d p0 = totalMomentum(co, box.mass());
  co.advanceTo(0.4);
  const Eigen::Vector3d dp = totalMomentum(co, box.mass()) - p0;
  std::printf("momentum change (%.6e, %.6e) N s, external impulse (%.6e, %.6e) N s\n", dp[0], dp[1],
              impulse->impulse[0], impulse->impulse[1]);
  EXPECT_GT(co.bodies().kinematics(0).velocity.norm(), 0.01) << "the box should be moving";
  EXPECT_LT((dp - impulse->impulse).norm(), 1e-6 * impulse->impulse.norm());
  const auto ledger = co.calcEnergy();
  EXPECT_NE(ledger.work_by_fluid_on_bodies, 0.0);
  EXPECT_GT(co.fluidSeconds(), 0.0);
  EXPECT_GT(co.bodySeconds(), 0.0);
}

TEST(CoSimulation, RunsWithEachMooringModelByOneWord) {
  for (const std::string word : {"tension_only_spring", "cable_path", "elastic_catenary", "lumped_mass"}) {
    cases::FloatingBox box;
    auto scene = cases::buildFloatingBox(box);
    // A line from the box's bottom centre to an anchor on the floor below, slack
    // enough at rest for the catenary models, described once for all models.
    bodies::MooringLineParams line;
    line.model = word;
    line.length = 0.17;  // fairlead-anchor distance at rest: 0.158 m
    line.axialStiffness = 2000.0;
    line.massPerLength = 0.05;
    line.diameter = 0.005;
    line.waterDensity = 1000.0;
    line.segments = 8;
    bodies::LineAttachment at;
    at.fairleadBody = 0;
    at.fairleadPoint = Eigen::Vector3d(0.0, -box.height / 2, 0.0);
    at.anchorPoint = Eigen::Vector3d(scene.centre[0] - 0.05, 0.0, 0.0);
    scene.system->addLine("line", at, bodies::makeMooringLine(line));
    scene.system->initialize();
    coupling::CoSimulation<2> co(std::move(scene.fluid), std::move(scene.system), {{0, 1}}, {0.1, 0.05});
    ASSERT_NO_THROW(co.advanceTo(0.3)) << word;
    const auto k = co.bodies().kinematics(0);
    const auto diag = co.bodies().lineDiagnostics(0);
    EXPECT_TRUE(std::isfinite(diag.fairleadTension)) << word;
    EXPECT_GE(diag.fairleadTension, 0.0) << word;
    EXPECT_LT((k.position.head<2>() - scene.centre).norm(), 0.03) << word << ": the box should float near where it was";
    EXPECT_EQ(diag.model, word);
  }
}
