// Elastic catenary against MoorPy's published test values, the MoorDyn/OrcaFlex chain
// reference (refdata/moordyn_quasistatic_chain), the inextensible closed form, and the
// energy principle (force = -grad of the line's potential energy).
#include <moorsph/bodies/catenary_solver.hpp>
#include <moorsph/bodies/elastic_catenary.hpp>
#include <moorsph/bodies/multibody_system.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>

namespace mb = moorsph::bodies;

namespace {
constexpr double kPi = 3.14159265358979323846;

mb::CatenaryInput moorPyCase(double friction) {
  // MoorPy tests/test_catenary.py: x = 400, z = 200, L = 500, EA = 7.51e12, w = 800.
  mb::CatenaryInput in;
  in.horizontalSpan = 400.0;
  in.verticalSpan = 200.0;
  in.length = 500.0;
  in.axialStiffness = 7.51e12;
  in.weightPerLength = 800.0;
  in.seabedFriction = friction;
  return in;
}
}  // namespace

TEST(ElasticCatenary, MatchesMoorPyReferenceValues) {
  for (double friction : {0.0, 0.1, 5.0}) {
    const mb::CatenarySolution s = mb::solveCatenary(moorPyCase(friction));
    const double expectedHa = friction == 0.0 ? 96643.43 : (friction == 0.1 ? 80418.60 : 0.0);
    std::printf("[figure] MoorPy cb=%.1f: HF %.4f (rel %.1e) VF %.4f (rel %.1e) LB %.4f HA %.4f, %d iterations\n",
                friction, s.fairleadHorizontal, std::abs(s.fairleadHorizontal / 96643.43 - 1.0), s.fairleadVertical,
                std::abs(s.fairleadVertical / 237751.76 - 1.0), s.seabedLength, s.anchorHorizontal, s.iterations);
    EXPECT_NEAR(s.fairleadHorizontal, 96643.43, 1e-5 * 96643.43);
    EXPECT_NEAR(s.fairleadVertical, 237751.76, 1e-5 * 237751.76);
    EXPECT_NEAR(s.seabedLength, 202.81, 0.005);  // given to 0.01 m
    EXPECT_NEAR(s.anchorHorizontal, expectedHa, 1e-5 * 96643.43);
    EXPECT_EQ(s.anchorVertical, 0.0);
  }
}

TEST(ElasticCatenary, InextensibleSymmetricSpanMatchesTheClosedForm) {
  // Both ends at the same height, no seabed: L = 2 a sinh(x/(2a)), H = w a, V = w L/2.
  const double x = 100.0, l = 120.0, w = 50.0;
  double lo = 1.0, hi = 1e4;  // bisection for a, independent of the Newton solver
  for (int i = 0; i < 200; ++i) {
    const double a = 0.5 * (lo + hi);
    (2.0 * a * std::sinh(x / (2.0 * a)) > l ? lo : hi) = a;
  }
  const double a = 0.5 * (lo + hi);
  mb::CatenaryInput in;
  in.horizontalSpan = x;
  in.verticalSpan = 0.0;
  in.length = l;
  in.axialStiffness = 1e15;
  in.weightPerLength = w;
  in.anchorOnSeabed = false;
  const mb::CatenarySolution s = mb::solveCatenary(in);
  EXPECT_NEAR(s.fairleadHorizontal, w * a, 1e-9 * w * a);
  EXPECT_NEAR(s.fairleadVertical, 0.5 * w * l, 1e-9 * w * l);
  EXPECT_NEAR(s.anchorVertical, -0.5 * w * l, 1e-9 * w * l);
  // Sag at mid-span a (cosh(x/2a) - 1), from the shape function.
  const double sag = a * (std::cosh(x / (2.0 * a)) - 1.0);
  EXPECT_NEAR(mb::catenaryPoint(in, s, 0.5 * l).y(), -sag, 1e-9 * sag);
  EXPECT_NEAR(mb::catenaryPoint(in, s, l).x(), x, 1e-9 * x);
}

TEST(ElasticCatenary, ElasticStretchOfATautVerticalLine) {
  // Vertical hanging line, no seabed: stretched length L + (T_top + T_bottom) L/(2 EA),
  // with T_bottom = T_top - w L. Take the span z and check VF from the closed form.
  const double l = 50.0, ea = 1e6, w = 100.0, vf = 20000.0;
  const double z = l + (vf - 0.5 * w * l) * l / ea;
  mb::CatenaryInput in;
  in.horizontalSpan = 0.0;
  in.verticalSpan = z;
  in.length = l;
  in.axialStiffness = ea;
  in.weightPerLength = w;
  in.anchorOnSeabed = false;
  const mb::CatenarySolution s = mb::solveCatenary(in);
  EXPECT_NEAR(s.fairleadVertical, vf, 1e-6 * vf);
  EXPECT_LT(s.fairleadHorizontal, 1e-3);
}

TEST(ElasticCatenary, FairleadForceIsMinusTheGradientOfTheLineEnergy) {
  // Frictionless line resting partly on the seabed, y up: central differences of the
  // potential energy in each direction give the force on the fairlead.
  mb::ElasticCatenaryParams p;
  p.length = 500.0;
  p.axialStiffness = 5e8;
  p.weightPerLength = 800.0;
  const mb::ElasticCatenary line(p);
  mb::LineEnds ends;
  ends.anchor = Eigen::Vector3d(0.0, -200.0, 0.0);
  ends.fairlead = Eigen::Vector3d(320.0, 0.0, 240.0);
  const Eigen::Vector3d force = line.calcForces(ends).onFairlead;
  const double h = 1e-3;
  for (int d = 0; d < 3; ++d) {
    mb::LineEnds a = ends, b = ends;
    a.fairlead(d) += h;
    b.fairlead(d) -= h;
    const double grad = (line.calcPotentialEnergy(a) - line.calcPotentialEnergy(b)) / (2.0 * h);
    EXPECT_NEAR(-grad, force(d), 2e-5 * force.norm()) << "direction " << d;
  }
  EXPECT_GT(force.norm(), 1e5);
}

TEST(ElasticCatenary, MatchesTheMoorDynOrcaFlexChainStaticTensions) {
  // refdata/moordyn_quasistatic_chain/README.md: chain 390 kg/m, volumetric diameter
  // 0.252 m, EA 1.674e9 N, water 1025 kg/m^3; z up, fairlead at origin. The reference
  // static tensions are frictionless (their anchor tension equals the fairlead's
  // horizontal component), so no friction here; MoorDyn's own test allows 10 %.
  const double g = 9.81;
  const double w = (390.0 - 1025.0 * kPi / 4.0 * 0.252 * 0.252) * g;
  struct Case { double x, z, l, fairleadKn, anchorKn; };
  const Case cases[] = {{400.0, -50.0, 410.0, 991.6, 826.2},
                        {700.0, -200.0, 760.0, 2065.4, 1402.2},
                        {1500.0, -600.0, 1700.0, 5232.6, 3244.2}};
  for (const Case& c : cases) {
    mb::ElasticCatenaryParams p;
    p.length = c.l;
    p.axialStiffness = 1.674e9;
    p.weightPerLength = w;
    p.up = Eigen::Vector3d::UnitZ();
    const mb::ElasticCatenary line(p);
    mb::LineEnds ends;
    ends.anchor = Eigen::Vector3d(c.x, 0.0, c.z);
    const mb::LineForces f = line.calcForces(ends);
    const double ef = f.fairleadTension / 1e3 / c.fairleadKn - 1.0;
    const double ea = f.anchorTension / 1e3 / c.anchorKn - 1.0;
    std::printf("[figure] chain depth %4.0f m: fairlead %.1f kN (ref %.1f, %+.2f%%), anchor %.1f kN (ref %.1f, %+.2f%%)\n",
                -c.z, f.fairleadTension / 1e3, c.fairleadKn, 100 * ef, f.anchorTension / 1e3, c.anchorKn, 100 * ea);
    EXPECT_LT(std::abs(ef), 0.015);
    EXPECT_LT(std::abs(ea), 0.015);
  }
}

TEST(ElasticCatenary, MooredBodyConservesEnergyWithAFrictionlessLine) {
  // A 2000 t body in 2D (Planar, y up, heave and roll held fixed) between two 200 m-depth
  // chains, displaced 20 m and released: kinetic + line energy is conserved, which
  // holds only if the Newton-solved fairlead force is the exact gradient of the line
  // energy.
  const double w = (390.0 - 1025.0 * kPi / 4.0 * 0.252 * 0.252) * 9.81;
  mb::SystemOptions opt;
  opt.maxStep = 0.05;
  opt.accuracy = 1e-9;
  mb::MultibodySystem sys(opt);
  mb::RigidBodySpec body;
  body.mass = 2.0e6;
  body.inertiaAboutCom = Eigen::Matrix3d::Identity() * 1e8;
  body.mobilizer = mb::Mobilizer::Planar;
  body.initial.position = Eigen::Vector3d(-20.0, 0.0, 0.0);
  body.fixedDofs[static_cast<int>(mb::Dof::TranslationY)] = true;
  body.fixedDofs[static_cast<int>(mb::Dof::RotationZ)] = true;
  sys.addBody(body);
  mb::ElasticCatenaryParams p;
  p.length = 760.0;
  p.axialStiffness = 1.674e9;
  p.weightPerLength = w;
  mb::LineAttachment at;
  at.anchorPoint = Eigen::Vector3d(700.0, -200.0, 0.0);
  sys.addLine("chain", at, std::make_unique<mb::ElasticCatenary>(p));
  mb::LineAttachment other = at;
  other.anchorPoint.x() = -700.0;
  sys.addLine("chain2", other, std::make_unique<mb::ElasticCatenary>(p));
  sys.initialize();
  const mb::EnergyReport e0 = sys.energy();
  double xMax = -1e9;
  for (int i = 1; i <= 60; ++i) {
    sys.advanceTo(i * 1.0);
    xMax = std::max(xMax, sys.kinematics(0).position.x());
  }
  const mb::EnergyReport e1 = sys.energy();
  const double drift = (e1.mechanical() - e1.externalWork) - (e0.mechanical() - e0.externalWork);
  const double scale = std::abs(e0.lineElastic - sys.energy().lineElastic) + e1.kinetic;
  std::printf("[figure] moored body: energy drift %.3e J over 60 s (kinetic %.3e J, line energy change %.3e J)\n",
              drift, e1.kinetic, e1.lineElastic - e0.lineElastic);
  EXPECT_GT(xMax, 19.0);  // it swung through to the other side
  EXPECT_LT(std::abs(drift), 1e-5 * std::max(scale, 1.0));
  const mb::LineDiagnostics d = sys.lineDiagnostics(0, true);
  ASSERT_EQ(d.shape.size(), 41u);
  EXPECT_LT((d.shape.front() - sys.kinematics(0).position).norm(), 1e-6);
  EXPECT_LT((d.shape.back() - at.anchorPoint).norm(), 1e-6);
}

TEST(ElasticCatenary, EndsBelowTheAnchorMirrorTheSwappedLine) {
  // A line hanging between two points with the "fairlead" below the "anchor" (no
  // seabed) is the same catenary with the roles exchanged: forces and tensions swap.
  mb::ElasticCatenaryParams p;
  p.length = 150.0;
  p.axialStiffness = 1e8;
  p.weightPerLength = 300.0;
  p.anchorOnSeabed = false;
  const mb::ElasticCatenary line(p);
  mb::LineEnds low, high;
  low.fairlead = Eigen::Vector3d(10.0, -40.0, 5.0);
  low.anchor = Eigen::Vector3d(100.0, 0.0, 60.0);
  high.fairlead = low.anchor;
  high.anchor = low.fairlead;
  const mb::LineForces a = line.calcForces(low), b = line.calcForces(high);
  EXPECT_LT((a.onFairlead - b.onAnchor).norm(), 1e-9 * b.onAnchor.norm());
  EXPECT_LT((a.onAnchor - b.onFairlead).norm(), 1e-9 * b.onFairlead.norm());
  EXPECT_NEAR(a.fairleadTension, b.anchorTension, 1e-9 * b.anchorTension);
  // Statics of the whole line: the end forces carry its weight, w L downwards.
  EXPECT_NEAR((a.onFairlead + a.onAnchor).y(), -300.0 * 150.0, 1e-6 * 300.0 * 150.0);
  EXPECT_LT(std::abs((a.onFairlead + a.onAnchor).x()) + std::abs((a.onFairlead + a.onAnchor).z()), 1e-6);
  const std::vector<Eigen::Vector3d> shape = line.calcShape(low);
  EXPECT_LT((shape.front() - low.fairlead).norm(), 1e-6);
  EXPECT_LT((shape.back() - low.anchor).norm(), 1e-6);
}
