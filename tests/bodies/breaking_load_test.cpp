// A line with a breaking load breaks when its tension exceeds it: within one
// integrator step after the closed-form crossing instant (never before it), reported
// with its name, time and tension, stops acting, and the run continues.
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
  std::printf("[figure] spring break at %.6f s (closed form %.6f s, max step %.0e s), tension %.5f N (load %.5f N)\n",
              d.breakTime, tBreak, maxStep, d.breakTension, 1.5 * m * kG);
  ASSERT_TRUE(d.broken);
  EXPECT_EQ(d.name, "cable");
  // Within one step after the crossing, and the reported tension is the closed form's
  // there: T = m g (1 - cos w t), just above the load.
  EXPECT_GE(d.breakTime, tBreak);
  EXPECT_LE(d.breakTime - tBreak, maxStep);
  EXPECT_GT(d.breakTension, 1.5 * m * kG);
  EXPECT_NEAR(d.breakTension, m * kG * (1.0 - std::cos(w * d.breakTime)), 1e-6);
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
  EXPECT_GE(d.breakTime, tBreak);
  EXPECT_LE(d.breakTime - tBreak, 1e-4);  // one (maximum) step
  EXPECT_GT(d.breakTension, 1.5 * kG);
  EXPECT_NEAR(sys->kinematics(0).acceleration.y(), -kG, 1e-9);
  EXPECT_EQ(sys->energy().lineElastic, 0.0);
}

// A straight weightless lumped-mass line of rest length L pulled at constant speed v
// from its rest length: once the start-up wave has been damped (here after ~50 L/c),
// T(t) = EA v t / L + BA v / L, so a load P is crossed at t* = (P - BA v/L) L/(EA v).
namespace {
mb::LumpedMassParams pulledLine() {
  mb::LumpedMassParams p;
  p.length = 10.0;
  p.segments = 10;
  p.massPerLength = 1.0;
  p.diameter = 0.0;  // no water forces
  p.waterDensity = 0.0;
  p.axialStiffness = 1e6;  // c = 1000 m/s, L/c = 0.01 s
  p.internalDampingRatio = 1.0;  // BA = 2 l sqrt(EA m) = 2000 N s
  p.seabed = false;
  p.gravity = Eigen::Vector3d(0.0, -1e-9, 0.0);  // the line's weight is negligible
  return p;
}
constexpr double kPullSpeed = 0.01, kLoad = 500.0;
double pulledLineCrossing() {
  const double ea = 1e6, ba = 2000.0, length = 10.0;
  return (kLoad - ba * kPullSpeed / length) * length / (ea * kPullSpeed);  // 0.498 s
}
}  // namespace

TEST(BreakingLoad, LumpedMassLineBreaksWithinOneSubStepOfTheClosedFormCrossing) {
  mb::LumpedMassLine line(pulledLine());
  line.setBreakingLoad(kLoad);
  mb::LineEnds a;
  a.fairlead = Eigen::Vector3d(0.0, 10.0, 0.0);
  line.initialize(a);
  const double dt = 1e-3, tStar = pulledLineCrossing(), h = line.timeStep();
  double t = 0.0;
  while (!std::isfinite(line.lastExceedance().timeIntoAdvance) && t < 1.0) {
    mb::LineEnds b = a;
    b.fairlead.y() += kPullSpeed * dt;
    b.fairleadVelocity = Eigen::Vector3d(0.0, kPullSpeed, 0.0);
    line.advance(dt, a, b);
    if (!std::isfinite(line.lastExceedance().timeIntoAdvance)) t += dt;
    a = b;
  }
  ASSERT_TRUE(std::isfinite(line.lastExceedance().timeIntoAdvance));
  const double tBreak = t + line.lastExceedance().timeIntoAdvance;
  std::printf("[figure] lumped-mass break at %.6f s (closed form %.6f s, sub-step %.2e s), tension %.3f N (load %.0f N)\n",
              tBreak, tStar, h, line.lastExceedance().tension, kLoad);
  EXPECT_GE(tBreak, tStar - 1e-9);
  EXPECT_LE(tBreak - tStar, h + 1e-9);
  // dT/dt = EA v / L = 1000 N/s: at most one sub-step's rise above the load.
  EXPECT_GT(line.lastExceedance().tension, kLoad);
  EXPECT_LT(line.lastExceedance().tension - kLoad, 1000.0 * h + 1e-6);
}

TEST(BreakingLoad, LumpedMassLineOnABodyIsReportedAndTheRunContinues) {
  // The same line pulled by a very heavy body coasting at v (no gravity): the system
  // reports the break to one line sub-step, and the body coasts on free of it.
  mb::SystemOptions opt;
  opt.gravity = Eigen::Vector3d::Zero();
  opt.lineSyncStep = 1e-3;
  mb::MultibodySystem sys(opt);
  mb::RigidBodySpec spec;
  spec.mass = 1e9;  // 500 N changes its speed by 2.5e-7 m/s over the pull
  spec.inertiaAboutCom = Eigen::Matrix3d::Identity() * 1e9;
  spec.initial.position = Eigen::Vector3d(0.0, 10.0, 0.0);
  spec.initial.velocity = Eigen::Vector3d(0.0, kPullSpeed, 0.0);
  sys.addBody(spec);
  auto line = std::make_unique<mb::LumpedMassLine>(pulledLine());
  const double h = line->timeStep();
  line->setBreakingLoad(kLoad);
  sys.addLine("pulled", mb::LineAttachment{}, std::move(line));
  sys.initialize();
  sys.advanceTo(0.4);
  EXPECT_FALSE(sys.lineDiagnostics(0).broken);
  sys.advanceTo(1.0);  // the run continues past the break
  const mb::LineDiagnostics d = sys.lineDiagnostics(0);
  const double tStar = pulledLineCrossing();
  std::printf("[figure] lumped-mass line on a body: '%s' broke at %.6f s (closed form %.6f s), tension %.3f N\n",
              d.name.c_str(), d.breakTime, tStar, d.breakTension);
  ASSERT_TRUE(d.broken);
  EXPECT_EQ(d.name, "pulled");
  EXPECT_GE(d.breakTime, tStar - 1e-6);
  EXPECT_LE(d.breakTime - tStar, h + 1e-6);
  EXPECT_GT(d.breakTension, kLoad);
  EXPECT_EQ(d.fairleadTension, 0.0);
  EXPECT_NEAR(sys.time(), 1.0, 1e-12);
  EXPECT_LT(sys.kinematics(0).acceleration.norm(), 1e-12);  // nothing acts on it any more
  // A checkpoint keeps the report.
  const mb::SystemSnapshot snap = sys.snapshot();
  ASSERT_EQ(snap.lines.size(), 1u);
  EXPECT_TRUE(snap.lines[0].broken);
  EXPECT_EQ(snap.lines[0].breakTime, d.breakTime);
  EXPECT_EQ(snap.lines[0].breakTension, d.breakTension);
}
