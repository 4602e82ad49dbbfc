// cable_path (Simbody CablePath + ViaPoint + CableSpring) against the ideal pulley:
// length = sum of the segments, one uniform tension, forces along the segments; the
// pulley rig of METHOD.md 6.2 equals a straight spring from the pulley; and Simbody's
// debug printing stays off stdout.
#include <moorsph/bodies/cable_path.hpp>
#include <moorsph/bodies/multibody_system.hpp>
#include <moorsph/bodies/tension_only_spring.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>

namespace mb = moorsph::bodies;

namespace {
mb::RigidBodySpec pointMass(const Eigen::Vector3d& at) {
  mb::RigidBodySpec spec;
  spec.mass = 2.0;
  spec.inertiaAboutCom = Eigen::Matrix3d::Identity() * 1e-2;
  spec.initial.position = at;
  return spec;
}
}  // namespace

TEST(CablePath, IdealPulleyLengthTensionAndDirections) {
  // Fairlead at the body origin (0, 0, 0); pulleys at (0, 2, 0) and (3, 2, 1) in ground;
  // anchor at (3, 0, 1). L = 2 + sqrt(10) + 2.
  mb::MultibodySystem sys;
  sys.addBody(pointMass(Eigen::Vector3d::Zero()));
  mb::CablePathParams p;
  p.stiffness = 100.0;
  p.restLength = 5.0;
  p.viaPoints = {{mb::LineAttachment::kGround, Eigen::Vector3d(0, 2, 0)},
                 {mb::LineAttachment::kGround, Eigen::Vector3d(3, 2, 1)}};
  mb::LineAttachment at;
  at.anchorPoint = Eigen::Vector3d(3, 0, 1);
  sys.addLine("rig", at, std::make_unique<mb::CablePathLine>(p));
  testing::internal::CaptureStdout();
  sys.initialize();
  const std::string printed = testing::internal::GetCapturedStdout();
  EXPECT_EQ(printed, "");  // Simbody's CablePath diagnostics were captured ...
  EXPECT_NE(sys.capturedSimbodyOutput().find("realizeTopology"), std::string::npos);  // ... not lost

  const double length = 4.0 + std::sqrt(10.0);
  const double tension = 100.0 * (length - 5.0);
  const mb::LineDiagnostics d = sys.lineDiagnostics(0, true);
  EXPECT_NEAR(d.fairleadTension, tension, 1e-9);
  EXPECT_NEAR(d.anchorTension, tension, 1e-9);
  EXPECT_LT((d.forceOnFairlead - tension * Eigen::Vector3d::UnitY()).norm(), 1e-9);
  EXPECT_LT((d.forceOnAnchor - tension * Eigen::Vector3d::UnitY()).norm(), 1e-9);  // pulled up to the pulley
  ASSERT_EQ(d.shape.size(), 4u);
  EXPECT_NEAR(sys.energy().lineElastic, 0.5 * 100.0 * (length - 5.0) * (length - 5.0), 1e-9);
  // The body feels T up (plus gravity): its acceleration is (T - m g)/m along y.
  const mb::BodyKinematics k = sys.kinematics(0);
  EXPECT_NEAR(k.acceleration.y(), tension / 2.0 - 9.81, 1e-9);
  EXPECT_NEAR(k.acceleration.x(), 0.0, 1e-12);
  // The plain evaluation (ground via points) agrees with Simbody's.
  mb::CablePathLine plain(p);
  mb::LineEnds ends;
  ends.anchor = at.anchorPoint;
  EXPECT_NEAR(plain.calcForces(ends).fairleadTension, tension, 1e-9);
}

TEST(CablePath, LabPulleyRigEqualsAStraightSpringFromThePulley) {
  // METHOD.md 6.2: the buoy's tether runs down to a pulley 0.09 m above the floor and
  // up to a spring above the water. An ideal pulley makes it equivalent to a straight
  // spring anchored at the pulley with the same k and pretension: compare the motion.
  const double depth = 0.8, r = 0.1015, k = 30.88, buoyancy = 21.4839, m = 1.745;
  auto run = [&](bool viaPulley) {
    mb::SystemOptions opt;
    opt.accuracy = 1e-10;
    mb::MultibodySystem sys(opt);
    mb::RigidBodySpec spec;
    spec.mass = m;
    spec.centreOfMass = Eigen::Vector3d(0.0, -0.027, 0.0);
    spec.inertiaAboutCom = Eigen::Vector3d(1.735209e-3, 1.776363e-3, 1.735209e-3).asDiagonal();
    spec.mobilizer = mb::Mobilizer::Planar;
    spec.initial.position = Eigen::Vector3d(0.2, depth, 0.0);  // pulled 0.2 m along the surface
    sys.addBody(spec);
    mb::LineAttachment at;
    at.fairleadPoint = Eigen::Vector3d(0.0, -r, 0.0);
    const Eigen::Vector3d pulley(0.0, 0.09, 0.0);
    const double pretension = buoyancy - m * 9.81;
    if (viaPulley) {
      mb::CablePathParams p;
      p.stiffness = k;
      p.pretension = pretension;
      p.viaPoints = {{mb::LineAttachment::kGround, pulley}};
      at.anchorPoint = Eigen::Vector3d(0.0, 1.5, 0.0);  // spring above the water
      sys.addLine("tether", at, std::make_unique<mb::CablePathLine>(p));
    } else {
      mb::TensionOnlySpringParams p;
      p.stiffness = k;
      p.pretension = pretension;
      at.anchorPoint = pulley;
      sys.addLine("tether", at, std::make_unique<mb::TensionOnlySpring>(p));
    }
    mb::BodyWrench up;
    up.force = Eigen::Vector3d(0.0, buoyancy, 0.0);
    sys.setExternalWrench(0, up);
    sys.initialize();
    std::vector<Eigen::Vector3d> track;
    for (int i = 1; i <= 20; ++i) {
      sys.advanceTo(0.1 * i);
      track.push_back(sys.kinematics(0).position);
    }
    return track;
  };
  const auto straight = run(false), pulley = run(true);
  double maxDiff = 0.0, maxMotion = 0.0;
  for (std::size_t i = 0; i < straight.size(); ++i) {
    maxDiff = std::max(maxDiff, (straight[i] - pulley[i]).norm());
    maxMotion = std::max(maxMotion, (straight[i] - straight.front()).norm());
  }
  std::printf("[figure] pulley rig vs straight spring: max position difference %.2e m over 2 s (motion %.3f m)\n",
              maxDiff, maxMotion);
  EXPECT_GT(maxMotion, 0.05);
  EXPECT_LT(maxDiff, 1e-7);
}

TEST(CablePath, ViaPointOnAMovingBodyAndEnergyBalance) {
  // Two bodies: body 0 is the fairlead, body 1 carries a pulley; no gravity, with
  // dissipation: kinetic + cable energy + dissipated is conserved.
  mb::SystemOptions opt;
  opt.gravity.setZero();
  opt.accuracy = 1e-10;
  mb::MultibodySystem sys(opt);
  sys.addBody(pointMass(Eigen::Vector3d(0.0, 0.0, 0.0)));
  mb::RigidBodySpec carrier = pointMass(Eigen::Vector3d(1.0, 1.5, 0.0));
  carrier.initial.velocity = Eigen::Vector3d(0.3, 0.0, 0.2);
  sys.addBody(carrier);
  mb::CablePathParams p;
  p.stiffness = 40.0;
  p.pretension = 5.0;
  p.dissipation = 0.5;
  p.viaPoints = {{1, Eigen::Vector3d(0.0, 0.1, 0.0)}};
  mb::LineAttachment at;
  at.anchorPoint = Eigen::Vector3d(2.0, 0.0, 0.0);
  sys.addLine("moving pulley", at, std::make_unique<mb::CablePathLine>(p));
  sys.initialize();
  EXPECT_NEAR(sys.lineDiagnostics(0).fairleadTension, 5.0, 1e-9);
  const mb::EnergyReport e0 = sys.energy();
  sys.advanceTo(3.0);
  const mb::EnergyReport e1 = sys.energy();
  std::printf("[figure] moving pulley: dissipated %.4e J, balance error %.2e J\n", e1.dissipated,
              e1.mechanical() + e1.dissipated - e0.mechanical());
  EXPECT_GT(e1.dissipated, 1e-4);
  EXPECT_NEAR(e1.mechanical() + e1.dissipated, e0.mechanical(), 1e-7);
  EXPECT_GT(sys.kinematics(0).velocity.norm(), 0.01);  // the cable pulled the fairlead body
}
