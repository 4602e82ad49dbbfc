// Snapshot/restore: a restored system continues the run as if never interrupted, and
// restoring into a system with a different mass gives the new closed-form period, and a
// lumped-mass line restored from a stateless model's snapshot starts from the restored pose.
#include <moorsph/bodies/elastic_catenary.hpp>
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

// Body on a damped spring from above plus a light lumped-mass line from below.
std::unique_ptr<mb::MultibodySystem> makeRig(double mass, bool withChain) {
  mb::SystemOptions opt;
  opt.accuracy = 1e-10;
  auto sys = std::make_unique<mb::MultibodySystem>(opt);
  mb::RigidBodySpec spec;
  spec.mass = mass;
  spec.inertiaAboutCom = Eigen::Vector3d(0.1, 0.2, 0.3).asDiagonal();
  spec.initial.position = Eigen::Vector3d(0.3, -1.2, 0.1);
  spec.initial.angularVelocity = Eigen::Vector3d(0.1, 0.0, 0.2);
  sys->addBody(spec);
  mb::TensionOnlySpringParams p;
  p.stiffness = 200.0;
  p.restLength = 1.0;
  p.damping = 1.0;
  mb::LineAttachment up;
  up.fairleadPoint = Eigen::Vector3d(0.05, 0.1, 0.0);
  sys->addLine("spring", up, std::make_unique<mb::TensionOnlySpring>(p));
  if (withChain) {
    mb::LumpedMassParams c;
    c.length = 1.0;
    c.segments = 8;
    c.massPerLength = 0.5;
    c.diameter = 0.01;
    c.axialStiffness = 1e4;
    c.internalDampingRatio = 1.0;
    c.cdNormal = 1.2;
    c.seabed = false;
    mb::LineAttachment down;
    down.anchorPoint = Eigen::Vector3d(0.5, -2.0, 0.0);
    sys->addLine("chain", down, std::make_unique<mb::LumpedMassLine>(c));
  }
  sys->initialize();
  return sys;
}
}  // namespace

TEST(SystemSnapshot, RestoredRunContinuesTheOriginal) {
  auto a = makeRig(2.0, true);
  mb::BodyWrench w;
  w.force = Eigen::Vector3d(0.5, 0.0, -0.2);
  w.torque = Eigen::Vector3d(0.0, 0.01, 0.0);
  a->setExternalWrench(0, w);
  a->advanceTo(0.5);
  const mb::SystemSnapshot snap = a->snapshot();
  a->advanceTo(1.0);

  auto b = makeRig(2.0, true);
  b->restore(snap);
  EXPECT_DOUBLE_EQ(b->time(), 0.5);
  b->advanceTo(1.0);
  const mb::BodyKinematics ka = a->kinematics(0), kb = b->kinematics(0);
  const double dx = (ka.position - kb.position).norm(), dv = (ka.velocity - kb.velocity).norm();
  const double dq = ka.orientation.angularDistance(kb.orientation);
  std::printf("[figure] restore: |dx| %.2e m, |dv| %.2e m/s, angle %.2e rad after 0.5 s\n", dx, dv, dq);
  EXPECT_LT(dx, 1e-6);
  EXPECT_LT(dv, 1e-5);
  EXPECT_LT(dq, 1e-6);
  EXPECT_NEAR(a->energy().dissipated, b->energy().dissipated, 1e-6);
  EXPECT_NEAR(a->energy().externalWork, b->energy().externalWork, 1e-6);
  EXPECT_NEAR(a->lineDiagnostics(1).fairleadTension, b->lineDiagnostics(1).fairleadTension,
              1e-3 * a->lineDiagnostics(1).fairleadTension);
  EXPECT_NEAR(b->externalWrench(0).force.x(), 0.5, 0.0);
}

TEST(SystemSnapshot, RestoringIntoAHeavierBodyGivesTheNewPeriod) {
  // A spring oscillator (no damping, no chain) doubled in mass mid-run oscillates with
  // 2 pi sqrt(2m/k) about its new equilibrium (Planar, vertical; small amplitude so the
  // spring stays taut throughout: amplitude < 2 m g / k).
  auto build = [](double m) {
    mb::SystemOptions opt;
    opt.accuracy = 1e-10;
    auto sys = std::make_unique<mb::MultibodySystem>(opt);
    mb::RigidBodySpec spec;
    spec.mass = m;
    spec.inertiaAboutCom = Eigen::Matrix3d::Identity() * 1e-3;
    spec.mobilizer = mb::Mobilizer::Planar;
    spec.initial.position = Eigen::Vector3d(0.0, -1.07, 0.0);
    sys->addBody(spec);
    mb::TensionOnlySpringParams p;
    p.stiffness = 200.0;
    p.restLength = 1.0;
    sys->addLine("spring", mb::LineAttachment{}, std::make_unique<mb::TensionOnlySpring>(p));
    sys->initialize();
    return sys;
  };
  auto light = build(1.0);
  light->advanceTo(0.3);
  auto heavy = build(2.0);
  heavy->restore(light->snapshot());
  const double yEq = -(1.0 + 2.0 * 9.81 / 200.0);
  double prev = heavy->kinematics(0).position.y() - yEq, prevT = 0.3;
  std::vector<double> crossings;
  for (int i = 1; i <= 4000; ++i) {
    const double t = 0.3 + i * 1e-3;
    heavy->advanceTo(t);
    const double y = heavy->kinematics(0).position.y() - yEq;
    if (prev < 0.0 && y >= 0.0) crossings.push_back(prevT + 1e-3 * (-prev) / (y - prev));
    prev = y;
    prevT = t;
  }
  ASSERT_GE(crossings.size(), 3u);
  const double period = (crossings.back() - crossings.front()) / (crossings.size() - 1);
  const double expected = 2.0 * kPi * std::sqrt(2.0 / 200.0);
  std::printf("[figure] mass doubled by restore: period %.6f s vs %.6f s\n", period, expected);
  EXPECT_NEAR(period, expected, 1e-6 * expected);
  EXPECT_DOUBLE_EQ(heavy->massProperties(0).mass, 2.0);
}

namespace {
// A body hung from a spring above and tied by a 1.6 m line (4.905 N/m in air, EA 1e4 N) to an
// anchor 1.1 m aside and 1 m below its start, the line either an elastic catenary
// (stateless) or lumped masses (32 segments, the state a snapshot carries).
std::unique_ptr<mb::MultibodySystem> makeTiedBody(bool lumped) {
  mb::SystemOptions opt;
  opt.accuracy = 1e-10;
  auto sys = std::make_unique<mb::MultibodySystem>(opt);
  mb::RigidBodySpec spec;
  spec.mass = 2.0;
  spec.inertiaAboutCom = Eigen::Matrix3d::Identity() * 0.1;
  spec.mobilizer = mb::Mobilizer::Planar;
  spec.initial.position = Eigen::Vector3d(0.0, -1.0, 0.0);
  spec.initial.velocity = Eigen::Vector3d(-1.0, 0.0, 0.0);  // away from the anchor: the line tightens
  sys->addBody(spec);
  mb::TensionOnlySpringParams p;
  p.stiffness = 200.0;
  p.restLength = 0.9;
  sys->addLine("spring", mb::LineAttachment{}, std::make_unique<mb::TensionOnlySpring>(p));
  mb::LineAttachment tie;
  tie.anchorPoint = Eigen::Vector3d(1.1, -2.0, 0.0);
  if (lumped) {
    mb::LumpedMassParams c;
    c.length = 1.6;
    c.segments = 32;
    c.massPerLength = 0.5;
    c.diameter = 0.01;
    c.waterDensity = 0.0;  // in air: the catenary's weight is m g
    c.axialStiffness = 1e4;
    c.internalDampingRatio = 0.0;  // no strain-rate force: the tensions compared are static
    c.seabed = false;
    sys->addLine("tie", tie, std::make_unique<mb::LumpedMassLine>(c));
  } else {
    mb::ElasticCatenaryParams c;
    c.length = 1.6;
    c.axialStiffness = 1e4;
    c.weightPerLength = 0.5 * 9.81;
    c.anchorOnSeabed = false;
    sys->addLine("tie", tie, std::make_unique<mb::ElasticCatenary>(c));
  }
  sys->initialize();
  return sys;
}
}  // namespace

TEST(SystemSnapshot, LumpedLineRestartedFromAStatelessModelHangsFromTheRestoredPose) {
  // The ship variants may switch a line's model at a restart. A snapshot of a stateless
  // line has no nodes: the lumped line must start from the static shape between the
  // restored ends (where the catenary left it), not from the shape it had at t = 0.
  auto catenary = makeTiedBody(false);
  const double t0Tension = catenary->lineDiagnostics(1).fairleadTension;
  catenary->advanceTo(0.15);
  const mb::LineDiagnostics before = catenary->lineDiagnostics(1);
  const Eigen::Vector3d fairlead = catenary->kinematics(0).position;
  auto lumped = makeTiedBody(true);
  const double t0Lumped = lumped->lineDiagnostics(1).fairleadTension;
  lumped->restore(catenary->snapshot());
  const mb::LineDiagnostics after = lumped->lineDiagnostics(1, true);
  std::printf("[figure] tie tension at t = 0: catenary %.2f N, lumped %.2f N; at the restart (0.15 s): catenary %.2f N, "
              "lumped %.2f N\n", t0Tension, t0Lumped, before.fairleadTension, after.fairleadTension);
  ASSERT_GT(std::abs(before.fairleadTension - t0Tension), 0.3 * t0Tension);  // the pose has moved the line
  EXPECT_LT((after.shape.front() - fairlead).norm(), 1e-9);
  EXPECT_NEAR(after.fairleadTension, before.fairleadTension, 0.03 * before.fairleadTension);
  lumped->advanceTo(0.16);  // and it carries on from there without a jolt
  catenary->advanceTo(0.16);
  const double lumpedLater = lumped->lineDiagnostics(1).fairleadTension;
  const double catenaryLater = catenary->lineDiagnostics(1).fairleadTension;
  std::printf("[figure] 0.01 s later: catenary %.2f N, lumped %.2f N\n", catenaryLater, lumpedLater);
  EXPECT_NEAR(lumpedLater, catenaryLater, 0.1 * catenaryLater);
}
