// Lumped-mass line against the catenary (static limit), the Lowe & Langley jumper
// static top force (refdata), its energy balance, and its stable-step rule. The
// MoorDyn/OrcaFlex imposed-heave chain cases are in imposed_heave_chain_test.cpp.
#include <moorsph/bodies/elastic_catenary.hpp>
#include <moorsph/bodies/lumped_mass_line.hpp>
#include <moorsph/bodies/multibody_system.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>

namespace mb = moorsph::bodies;

namespace {
constexpr double kPi = 3.14159265358979323846;

// MoorDyn chain (refdata/moordyn_quasistatic_chain/README.md), z up.
mb::LumpedMassParams chain(double length, int segments) {
  mb::LumpedMassParams p;
  p.length = length;
  p.segments = segments;
  p.massPerLength = 390.0;
  p.diameter = 0.252;
  p.axialStiffness = 1.674e9;
  p.cdNormal = 1.37;
  p.cdAxial = 0.64;
  p.caNormal = 1.0;
  p.waterDensity = 1025.0;
  p.gravity = Eigen::Vector3d(0.0, 0.0, -9.81);
  return p;
}
}  // namespace

TEST(LumpedMassLine, StableStepIsHalfSegmentOverWaveSpeedAndLargerIsRefused) {
  mb::LumpedMassParams p = chain(410.0, 20);
  p.seabed = false;
  const mb::LumpedMassLine line(p);
  const double l = 410.0 / 20, c = std::sqrt(1.674e9 / 390.0);
  EXPECT_NEAR(line.stableTimeStep(), 0.5 * l / c, 1e-12);
  p.timeStep = 1.01 * line.stableTimeStep();
  try {
    mb::LumpedMassLine bad(p);
    FAIL() << "a step above the stable step must be refused";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("stable step"), std::string::npos);
  }
}

TEST(LumpedMassLine, RunsWithoutNaNAtItsStableStepAndFlagsBlowUp) {
  // Exactly at the stated stable step, a violently moved fairlead keeps the line finite.
  mb::LumpedMassParams p = chain(410.0, 20);
  p.timeStep = mb::LumpedMassLine(p).stableTimeStep();
  mb::LumpedMassLine line(p);
  mb::LineEnds a;
  a.anchor = Eigen::Vector3d(400.0, 0.0, -50.0);
  line.initialize(a);
  for (int k = 0; k < 200; ++k) {
    mb::LineEnds b = a;
    b.fairlead.x() = -5.0 * std::sin(0.05 * (k + 1));
    ASSERT_NO_THROW(line.advance(0.05, a, b));
    a = b;
  }
  for (const auto& r : line.nodePositions()) EXPECT_TRUE(r.allFinite());
  // A state gone non-finite (as a blow-up would leave it) is an error naming the node
  // and the steps, never a silent NaN in the tensions.
  std::vector<double> state = line.saveState();
  state[6 * 7 + 1] = std::numeric_limits<double>::quiet_NaN();  // node 7, y
  line.restoreState(state);
  try {
    line.advance(0.05, a, a);
    FAIL() << "a non-finite node must be reported";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("non-finite"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("stable step"), std::string::npos);
  }
}

TEST(LumpedMassLine, StaticShapeConvergesToTheCatenaryAsSegmentsIncrease) {
  const double w = (390.0 - 1025.0 * kPi / 4.0 * 0.252 * 0.252) * 9.81;
  mb::ElasticCatenaryParams cp;
  cp.length = 410.0;
  cp.axialStiffness = 1.674e9;
  cp.weightPerLength = w;
  cp.up = Eigen::Vector3d::UnitZ();
  mb::LineEnds ends;
  ends.anchor = Eigen::Vector3d(400.0, 0.0, -50.0);
  const double exact = mb::ElasticCatenary(cp).calcForces(ends).fairleadTension;
  double previous = 1e9;
  for (int n : {5, 10, 20, 40}) {
    mb::LumpedMassParams p = chain(410.0, n);
    p.relaxationTime = 400.0;
    p.relaxationDamping = 0.5;
    mb::LumpedMassLine line(p);
    line.initialize(ends);
    const double err = std::abs(line.calcForces(ends).fairleadTension / exact - 1.0);
    std::printf("[figure] lumped mass N=%2d: static fairlead tension %.2f kN vs catenary %.2f kN (rel %.2e)\n", n,
                line.calcForces(ends).fairleadTension / 1e3, exact / 1e3, err);
    EXPECT_LT(err, previous);
    previous = err;
  }
  EXPECT_LT(previous, 0.005);
}

TEST(LumpedMassLine, LoweLangleyJumperStaticTopForceWithinTwoPercent) {
  // refdata/lowe_langley_2006_jumper: 165 kg/m, d 0.396 m, EA 500e6 N, L 170 m, 68
  // segments, bottom (-100, 0, -55), top (0, 0, -5), water 1000 kg/m^3, depth 100 m,
  // g 9.807, EI 120.8e3 N m^2. Reference top force (11.40, 0, 45.71) kN.
  mb::LumpedMassParams p;
  p.length = 170.0;
  p.segments = 68;
  p.massPerLength = 165.0;
  p.diameter = 0.396;
  p.axialStiffness = 500e6;
  p.bendingStiffness = 120.8e3;
  p.cdNormal = 1.0;
  p.caNormal = 1.0;
  p.waterDensity = 1000.0;
  p.gravity = Eigen::Vector3d(0.0, 0.0, -9.807);
  p.seabedPoint = Eigen::Vector3d(0.0, 0.0, -100.0);
  p.relaxationTime = 300.0;
  p.relaxationDamping = 0.5;
  mb::LumpedMassLine line(p);
  mb::LineEnds ends;
  ends.anchor = Eigen::Vector3d(-100.0, 0.0, -55.0);
  ends.fairlead = Eigen::Vector3d(0.0, 0.0, -5.0);
  line.initialize(ends);
  const Eigen::Vector3d top = -line.calcForces(ends).onFairlead / 1e3;  // support force, kN
  const Eigen::Vector3d ref(11.40, 0.0, 45.71);
  std::printf("[figure] jumper top force (%.3f, %.3f, %.3f) kN vs (11.40, 0, 45.71): |diff|/|ref| = %.2e\n", top.x(),
              top.y(), top.z(), (top - ref).norm() / ref.norm());
  EXPECT_LT((top - ref).norm(), 0.02 * ref.norm());
}

TEST(LumpedMassLine, EnergyBalanceWithDragDampingSeabedAndMovingEnd) {
  // From the relaxed shape, the fairlead is moved smoothly by a few metres: kinetic +
  // potential + dissipated (drag, internal damping, seabed damper and friction) - work
  // of the moving ends must stay constant (bending energy included). Semi-implicit Euler makes the balance close
  // to first order in the step, so the test asks for 0.5 % of the energy throughput.
  mb::LumpedMassParams p = chain(120.0, 24);
  p.internalDamping = 2e6;  // about 25 % of critical for the segment axial mode
  p.bendingStiffness = 2e6; // N m^2: bending forces must be the gradient of bending energy
  p.seabedFriction = 0.3;
  p.relaxationTime = 100.0;
  p.relaxationDamping = 0.5;
  mb::LumpedMassLine line(p);
  mb::LineEnds a;
  a.anchor = Eigen::Vector3d(100.0, 0.0, -30.0);
  line.initialize(a);
  const double e0 = line.kineticEnergy() + line.calcPotentialEnergy(a);
  double maxErr = 0.0;
  for (int k = 1; k <= 1000; ++k) {
    const double t = 0.02 * k;
    mb::LineEnds b = a;
    b.fairlead = Eigen::Vector3d(-4.0 * std::sin(0.8 * t), 0.0, 3.0 * std::sin(0.6 * t));
    line.advance(0.02, a, b);
    a = b;
    const double e = line.kineticEnergy() + line.calcPotentialEnergy(a);
    maxErr = std::max(maxErr, std::abs(e + line.dissipatedEnergy() - line.endWork() - e0));
  }
  const double throughput = std::max(std::abs(line.endWork()), line.dissipatedEnergy());
  std::printf("[figure] lumped mass energy balance: max error %.3e J, end work %.3e J, dissipated %.3e J "
              "(error/throughput %.2e)\n", maxErr, line.endWork(), line.dissipatedEnergy(), maxErr / throughput);
  EXPECT_GT(line.dissipatedEnergy(), 0.0);
  EXPECT_LT(maxErr, 5e-3 * throughput);
}

TEST(LumpedMassLine, CoupledToABodyTheTotalEnergyBalances) {
  // A 2000 t body (surge only) between two 50 m-depth chains, displaced 10 m and
  // released. Body kinetic energy + line kinetic and potential energy + energy the
  // lines dissipated is conserved up to the lag of the staggered force exchange.
  mb::SystemOptions opt;
  opt.gravity = Eigen::Vector3d(0.0, 0.0, -9.81);
  opt.lineSyncStep = 2e-3;  // energy error 0.74 % here, 0.48 % at 1e-3 s
  opt.maxStep = 2e-3;
  mb::MultibodySystem sys(opt);
  mb::RigidBodySpec body;
  body.mass = 2.0e6;
  body.inertiaAboutCom = Eigen::Matrix3d::Identity() * 1e8;
  body.initial.position = Eigen::Vector3d(-10.0, 0.0, 0.0);
  for (mb::Dof d : {mb::Dof::TranslationY, mb::Dof::TranslationZ, mb::Dof::RotationX, mb::Dof::RotationY,
                    mb::Dof::RotationZ}) {
    body.fixedDofs[static_cast<int>(d)] = true;
  }
  sys.addBody(body);
  for (double side : {1.0, -1.0}) {
    mb::LumpedMassParams p = chain(410.0, 20);
    p.internalDampingRatio = 1.0;
    p.relaxationTime = 200.0;
    p.relaxationDamping = 0.5;
    mb::LineAttachment at;
    at.anchorPoint = Eigen::Vector3d(side * 400.0, 0.0, -50.0);
    sys.addLine(side > 0 ? "east" : "west", at, std::make_unique<mb::LumpedMassLine>(p));
  }
  sys.initialize();
  auto total = [&]() {
    double e = sys.energy().kinetic;
    for (int i = 0; i < 2; ++i) {
      const auto& line = dynamic_cast<const mb::LumpedMassLine&>(sys.line(i));
      e += line.kineticEnergy() + line.calcPotentialEnergy({}) + line.dissipatedEnergy();
    }
    return e;
  };
  const double e0 = total();
  double maxErr = 0.0, maxKinetic = 0.0, xMax = -1e9;
  for (int k = 1; k <= 100; ++k) {
    sys.advanceTo(0.1 * k);
    maxErr = std::max(maxErr, std::abs(total() - e0));
    maxKinetic = std::max(maxKinetic, sys.energy().kinetic);
    xMax = std::max(xMax, sys.kinematics(0).position.x());
  }
  const mb::LineDiagnostics d = sys.lineDiagnostics(0, true);
  std::printf("[figure] body on two lumped-mass chains: energy error %.3e J, max body kinetic %.3e J, "
              "east tension %.1f kN\n", maxErr, maxKinetic, d.fairleadTension / 1e3);
  EXPECT_GT(xMax, -9.0);  // it moved towards the middle
  EXPECT_EQ(d.shape.size(), 21u);
  EXPECT_LT(maxErr, 0.01 * maxKinetic);
}
