// A line with a breaking load breaks when its tension exceeds it, is reported with
// its break time, stops acting, and the run continues (closed-form break instant).
#include <moorsph/bodies/cable_path.hpp>
#include <moorsph/bodies/lumped_mass_line.hpp>
#include <moorsph/bodies/multibody_system.hpp>
#include <moorsph/bodies/tension_only_spring.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>

namespace mb = moorsph::bodies;

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kG = 9.81;

// Mass released at rest at the slack length below a spring: after contact,
// T(t) = m g (1 - cos w t), w = sqrt(k/m). A breaking load of 1.5 m g is reached at
// w t = 2 pi / 3, before the 2 m g snap peak.
std::unique_ptr<mb::MultibodySystem> snapRig(std::unique_ptr<mb::MooringLine> line, double maxStep) {
  mb::SystemOptions opt;
  opt.maxStep = maxStep;
  opt.accuracy = 1e-10;
  auto sys = std::make_unique<mb::MultibodySystem>(opt);
  mb::RigidBodySpec spec;
  spec.mass = 1.0;
  spec.inertiaAboutCom = Eigen::Matrix3d::Identity() * 1e-3;
  spec.initial.position = Eigen::Vector3d(0.0, -1.0, 0.0);
  sys->addBody(spec);
  sys->addLine("cable", mb::LineAttachment{}, std::move(line));
  sys->initialize();
  return sys;
}
}  // namespace

TEST(BreakingLoad, SpringBreaksAtTheClosedFormInstantAndTheBodyFliesFree) {
  const double k = 400.0, m = 1.0, w = std::sqrt(k / m), maxStep = 1e-4;
  mb::TensionOnlySpringParams p;
  p.stiffness = k;
  p.restLength = 1.0;
  auto line = std::make_unique<mb::TensionOnlySpring>(p);
  line->setBreakingLoad(1.5 * m * kG);
  auto sys = snapRig(std::move(line), maxStep);
  const double tBreak = (2.0 * kPi / 3.0) / w;
  sys->advanceTo(0.5 * tBreak);
  EXPECT_FALSE(sys->lineDiagnostics(0).broken);
  sys->advanceTo(2.0 * tBreak);  // the run continues past the break
  const mb::LineDiagnostics d = sys->lineDiagnostics(0);
  std::printf("[figure] spring break at %.6f s (closed form %.6f s, max step %.0e s)\n", d.breakTime, tBreak, maxStep);
  ASSERT_TRUE(d.broken);
  EXPECT_NEAR(d.breakTime, tBreak, maxStep);
  EXPECT_EQ(d.fairleadTension, 0.0);
  // After the break only gravity acts.
  EXPECT_NEAR(sys->kinematics(0).acceleration.y(), -kG, 1e-9);
  // Velocity at the break from the closed form: v = -(g/w) sin(w t), then free fall.
  const double vBreak = -(kG / w) * std::sin(w * tBreak);
  EXPECT_NEAR(sys->kinematics(0).velocity.y(), vBreak - kG * (2.0 * tBreak - d.breakTime), 1e-3);
}

TEST(BreakingLoad, UnbreakableBelowTheLoad) {
  mb::TensionOnlySpringParams p;
  p.stiffness = 400.0;
  p.restLength = 1.0;
  auto line = std::make_unique<mb::TensionOnlySpring>(p);
  line->setBreakingLoad(2.01 * kG);  // above the 2 m g snap peak
  auto sys = snapRig(std::move(line), 1e-4);
  sys->advanceTo(1.0);
  EXPECT_FALSE(sys->lineDiagnostics(0).broken);
  EXPECT_TRUE(std::isnan(sys->lineDiagnostics(0).breakTime));
}

TEST(BreakingLoad, CablePathBreaksToo) {
  mb::CablePathParams p;
  p.stiffness = 400.0;
  p.restLength = 1.0;
  auto line = std::make_unique<mb::CablePathLine>(p);
  line->setBreakingLoad(1.5 * kG);
  auto sys = snapRig(std::move(line), 1e-4);
  const double tBreak = (2.0 * kPi / 3.0) / std::sqrt(400.0);
  sys->advanceTo(0.3);
  const mb::LineDiagnostics d = sys->lineDiagnostics(0);
  ASSERT_TRUE(d.broken);
  EXPECT_NEAR(d.breakTime, tBreak, 1e-4);
  EXPECT_NEAR(sys->kinematics(0).acceleration.y(), -kG, 1e-9);
  EXPECT_EQ(sys->energy().lineElastic, 0.0);
}

TEST(BreakingLoad, LumpedMassLineBreaksAtASyncStep) {
  // A heavy hanging chain (no seabed) holding a body: pulling the body down by an
  // external force raises the top tension above the breaking load.
  mb::SystemOptions opt;
  opt.lineSyncStep = 1e-3;
  mb::MultibodySystem sys(opt);
  mb::RigidBodySpec spec;
  spec.mass = 100.0;
  spec.inertiaAboutCom = Eigen::Matrix3d::Identity();
  // Near static equilibrium: tension ~ body + line weight = 1.95 kN, stretch 0.2 %.
  spec.initial.position = Eigen::Vector3d(0.0, -9.919, 0.0);
  for (mb::Dof d : {mb::Dof::TranslationX, mb::Dof::TranslationZ, mb::Dof::RotationX, mb::Dof::RotationY,
                    mb::Dof::RotationZ}) {
    spec.fixedDofs[static_cast<int>(d)] = true;
  }
  sys.addBody(spec);
  mb::LumpedMassParams p;
  p.length = 9.9;
  p.segments = 10;
  p.massPerLength = 10.0;
  p.diameter = 0.02;
  p.axialStiffness = 1e6;
  p.internalDampingRatio = 1.0;
  p.seabed = false;
  auto line = std::make_unique<mb::LumpedMassLine>(p);
  line->setBreakingLoad(5000.0);
  mb::LineAttachment at;  // anchor above at the origin
  sys.addLine("chain", at, std::move(line));
  sys.initialize();
  sys.advanceTo(0.2);
  EXPECT_FALSE(sys.lineDiagnostics(0).broken);
  mb::BodyWrench pull;
  pull.force = Eigen::Vector3d(0.0, -8000.0, 0.0);
  sys.setExternalWrench(0, pull);
  sys.advanceTo(1.0);
  const mb::LineDiagnostics d = sys.lineDiagnostics(0);
  ASSERT_TRUE(d.broken);
  EXPECT_GT(d.breakTime, 0.2);
  // Once broken the body feels only gravity and the pull.
  EXPECT_NEAR(sys.kinematics(0).acceleration.y(), -kG - 80.0, 1e-6);
}
