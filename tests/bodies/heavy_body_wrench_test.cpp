// The moored ship of METHOD.md 6.5 on its own (no SPH): a 52,196 t free body on three
// tension-only springs, driven by a wrench that is piecewise constant per fluid step,
// as the co-simulation applies it (docs/validation/ship.md, finding 2).
#include <moorsph/bodies/multibody_system.hpp>
#include <moorsph/bodies/tension_only_spring.hpp>

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <random>
#include <stdexcept>

namespace mb = moorsph::bodies;

namespace {

constexpr double kMass = 52196000.0;  // kg (cases/ship/ship_base.yaml)

// The ship of cases/ship/ship_tiny.yaml: bow keel at the origin of the body frame,
// fairlead on the keel 40 m aft of the bow, three springs k = 1.7e6 N/m, L0 = 157.1 m.
std::unique_ptr<mb::MultibodySystem> makeShip() {
  auto sys = std::make_unique<mb::MultibodySystem>();
  mb::RigidBodySpec spec;
  spec.name = "ship";
  spec.mass = kMass;
  spec.centreOfMass = Eigen::Vector3d(152.1, 12.6, 0.0);
  spec.inertiaAboutCom = Eigen::Vector3d(6.3848e9, 2.1917e11, 2.1917e11).asDiagonal();
  spec.initial.position = Eigen::Vector3d(40.0, 27.3117, 36.0);
  spec.initial.orientation = Eigen::AngleAxisd(0.21263 * M_PI / 180.0, Eigen::Vector3d::UnitZ());
  sys->addBody(spec);
  const Eigen::Vector3d anchors[3] = {{39.5855, -135, 36}, {100.2073, -135, 1}, {100.2073, -135, 71}};
  for (const Eigen::Vector3d& a : anchors) {
    mb::TensionOnlySpringParams p;
    p.stiffness = 1.7e6;
    p.restLength = 157.1;
    mb::LineAttachment where;
    where.fairleadPoint = Eigen::Vector3d(40.0, 0.0, 0.0);
    where.anchorPoint = a;
    sys->addLine("line", where, std::make_unique<mb::TensionOnlySpring>(p));
  }
  sys->initialize();
  return sys;
}

// The fluid wrench of the tiny ship run just after its release (measured: force about
// (-8e6, 8.7e8, 1.4e7) N, torque (2e8, -4e9, 1.3e11) N m), redrawn at random every
// fluid step of 0.01713 s: jumps of 10 % of the vertical force and of the pitch moment
// between steps, as SPH gives them. The integrator must take about dt/maxStep steps per
// fluid step (maxStep = 1 ms: 18), and the energy ledger (multibody_system.hpp) must
// hold: kinetic + gravitational + spring energy - work of the wrench is conserved.
mb::BodyWrench shipLikeWrench(std::mt19937& rng) {
  std::normal_distribution<double> z(0.0, 1.0);
  mb::BodyWrench w;
  w.force = Eigen::Vector3d(-8e6 + 1e7 * z(rng), 5.6e8 * (1.0 + 0.1 * z(rng)), 1.5e7 * z(rng));
  w.torque = Eigen::Vector3d(2e8 * z(rng), 4e9 * z(rng), 1.3e11 * (1.0 + 0.1 * z(rng)));
  return w;
}

constexpr double kFluidStep = 1.713e-2;  // s, dt of cases/ship/ship_tiny.yaml

}  // namespace

TEST(HeavyBodyWrench, PiecewiseConstantShipWrenchAdvancesInNominalSteps) {
  auto sys = makeShip();
  std::mt19937 rng(7);
  const mb::EnergyReport e0 = sys->energy();
  double workScale = 0.0;
  const long nominal = static_cast<long>(std::ceil(kFluidStep / mb::SystemOptions{}.maxStep));
  for (int n = 1; n <= 300; ++n) {  // 5.1 s
    sys->setExternalWrench(0, shipLikeWrench(rng));
    const long before = sys->internalStepCount();
    sys->advanceTo(n * kFluidStep);
    EXPECT_LE(sys->internalStepCount() - before, nominal + 1) << "fluid step " << n;
    workScale = std::max(workScale, std::abs(sys->energy().externalWork));
  }
  const mb::EnergyReport e1 = sys->energy();
  const double drift = (e1.mechanical() - e1.externalWork) - (e0.mechanical() - e0.externalWork);
  ASSERT_GT(workScale, 1e8);  // the wrench did real work (J)
  EXPECT_LT(std::abs(drift), 1e-6 * workScale) << "energy drift " << drift << " J, work " << workScale << " J";
}

// The stall of docs/validation/ship.md finding 2: the run's fluid wrench jumped to
// 4.8e23 N and 1.2e26 N m (a fluid particle deep in the wall law's singular range) and
// the error-controlled integrator then shrank its step without end. It must now stop
// with an error naming the forces, after bounded work (well under a second here).
TEST(HeavyBodyWrench, OutOfScaleWrenchFailsInBoundedWork) {
  auto sys = makeShip();
  std::mt19937 rng(7);
  for (int n = 1; n <= 10; ++n) {
    sys->setExternalWrench(0, shipLikeWrench(rng));
    sys->advanceTo(n * kFluidStep);
  }
  mb::BodyWrench wild;
  wild.force = Eigen::Vector3d(-5.9e21, 4.8e23, -3.7e23);
  wild.torque = Eigen::Vector3d(-2.9e24, 9.4e25, 1.2e26);
  sys->setExternalWrench(0, wild);
  const auto start = std::chrono::steady_clock::now();
  try {
    sys->advanceTo(11 * kFluidStep);
    FAIL() << "advanced through a 5e23 N wrench without complaint";
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    std::printf("%s\n", what.c_str());
    EXPECT_NE(what.find("out of scale"), std::string::npos) << what;
    EXPECT_NE(what.find("'ship'"), std::string::npos) << what;
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(seconds, 5.0);
}
