// Cost of the four mooring models (docs/moorings.md): one force evaluation of each
// stateless model, one internal sub-step of lumped_mass at several segment counts, and
// one coupling step (setExternalWrench + advanceTo(t + 1 ms) + kinematics) of a
// MultibodySystem with one body and each model. Process CPU time (std::clock, so that
// other processes on a shared machine count less than in wall time), median of 5
// repeats. Usage: moorsph_bench_mooring_cost
#include <moorsph/bodies/cable_path.hpp>
#include <moorsph/bodies/elastic_catenary.hpp>
#include <moorsph/bodies/lumped_mass_line.hpp>
#include <moorsph/bodies/multibody_system.hpp>
#include <moorsph/bodies/tension_only_spring.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <functional>
#include <memory>
#include <vector>

namespace mb = moorsph::bodies;

namespace {

constexpr double kPi = 3.14159265358979323846;

// Median over 5 repeats of the CPU time of `run` divided by `count`, in microseconds.
double microsecondsPer(long count, const std::function<void()>& run) {
  std::vector<double> t;
  for (int r = 0; r < 5; ++r) {
    const std::clock_t c0 = std::clock();
    run();
    t.push_back(1e6 * static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC / static_cast<double>(count));
  }
  std::sort(t.begin(), t.end());
  return t[2];
}

double sink = 0.0;  // keeps the evaluations from being optimised away

double perEvaluation(const mb::MooringLine& line, const mb::LineEnds& ends) {
  const long n = 200000;
  return microsecondsPer(n, [&] {
    mb::LineEnds e = ends;
    for (long i = 0; i < n; ++i) {
      e.fairlead.x() = ends.fairlead.x() + 1e-9 * static_cast<double>(i % 7);
      sink += line.calcForces(e).fairleadTension;
    }
  });
}

// MoorDyn's chain (refdata/moordyn_quasistatic_chain), y up, 50 m depth.
mb::LumpedMassParams chain(int segments) {
  mb::LumpedMassParams p;
  p.length = 410.0;
  p.segments = segments;
  p.massPerLength = 390.0;
  p.diameter = 0.252;
  p.axialStiffness = 1.674e9;
  p.internalDampingRatio = 0.5;
  p.cdNormal = 1.37;
  p.cdAxial = 0.64 / kPi;
  p.caNormal = 1.0;
  p.seabedStiffness = 1e5;
  p.seabedDamping = 1e4;
  p.seabedFriction = 0.5;
  return p;
}
mb::ElasticCatenaryParams chainCatenary() {
  mb::ElasticCatenaryParams p;
  p.length = 410.0;
  p.axialStiffness = 1.674e9;
  p.weightPerLength = (390.0 - 1025.0 * kPi / 4.0 * 0.252 * 0.252) * 9.81;
  p.seabedFriction = 0.5;
  return p;
}
const Eigen::Vector3d kChainAnchor(400.0, -50.0, 0.0);

// One body of 1e7 kg at the origin on `line` (or none), heaving 1 m at 0.1 Hz via its
// external force; microseconds per 1 ms coupling step over 2 s.
double perCouplingStep(std::function<std::unique_ptr<mb::MooringLine>()> make, mb::LineAttachment at) {
  return microsecondsPer(2000, [&] {
    mb::MultibodySystem sys;
    mb::RigidBodySpec body;
    body.mass = 1e7;
    body.inertiaAboutCom = Eigen::Matrix3d::Identity() * 1e9;
    sys.addBody(body);
    if (make) sys.addLine("line", at, make());
    sys.initialize();
    for (int k = 1; k <= 2000; ++k) {
      mb::BodyWrench w;
      w.force.y() = 9.81e7 * (1.0 + 0.1 * std::sin(0.2 * kPi * k * 1e-3));
      sys.setExternalWrench(0, w);
      sys.advanceTo(k * 1e-3);
      sink += sys.kinematics(0).position.y();
    }
  });
}

}  // namespace

int main() {
  std::printf("# mooring model cost (process CPU time, median of 5; shared 2-vCPU machine, so approximate)\n");
  mb::LineEnds taut;
  taut.fairlead = Eigen::Vector3d(0.3, 2.0, 0.1);

  mb::TensionOnlySpringParams sp;
  sp.stiffness = 100.0;
  sp.restLength = 1.5;
  sp.damping = 1.0;
  std::printf("tension_only_spring  calcForces            %8.3f us\n", perEvaluation(mb::TensionOnlySpring(sp), taut));

  mb::CablePathParams cp;
  cp.stiffness = 100.0;
  cp.restLength = 1.5;
  cp.viaPoints = {{mb::LineAttachment::kGround, Eigen::Vector3d(0.0, 3.0, 0.0)},
                  {mb::LineAttachment::kGround, Eigen::Vector3d(1.0, 3.0, 0.0)}};
  std::printf("cable_path           calcForces (2 vias)   %8.3f us (plain evaluation; in a system Simbody's CablePath)\n",
              perEvaluation(mb::CablePathLine(cp), taut));

  mb::LineEnds chainEnds;
  chainEnds.anchor = kChainAnchor;
  std::printf("elastic_catenary     calcForces (50 m chain, seabed, friction) %8.3f us\n",
              perEvaluation(mb::ElasticCatenary(chainCatenary()), chainEnds));

  for (int n : {20, 40, 82, 170}) {
    mb::LumpedMassLine line(chain(n));
    line.initialize(chainEnds);
    const double h = line.timeStep();
    const long steps = 2000;
    const double us = microsecondsPer(steps, [&] { line.advance(steps * h, chainEnds, chainEnds); });
    std::printf("lumped_mass N=%3d    one sub-step          %8.3f us (dt %.2e s: %.4f s CPU per simulated s)\n", n, us,
                h, us * 1e-6 / h);
  }

  mb::LineAttachment chainAt;
  chainAt.anchorPoint = kChainAnchor;
  std::printf("MultibodySystem, one body, 1 ms coupling step (setExternalWrench + advanceTo + kinematics):\n");
  std::printf("  no line              %8.1f us\n", perCouplingStep(nullptr, chainAt));
  mb::LineAttachment springAt;
  springAt.anchorPoint = Eigen::Vector3d(0.0, -60.0, 0.0);
  mb::TensionOnlySpringParams big;
  big.stiffness = 1e6;
  big.restLength = 59.0;
  std::printf("  tension_only_spring  %8.1f us\n",
              perCouplingStep([&] { return std::make_unique<mb::TensionOnlySpring>(big); }, springAt));
  mb::CablePathParams bigCable;
  bigCable.stiffness = 1e6;
  bigCable.restLength = 69.0;
  bigCable.viaPoints = {{mb::LineAttachment::kGround, Eigen::Vector3d(10.0, -60.0, 0.0)}};
  std::printf("  cable_path (1 via)   %8.1f us\n",
              perCouplingStep([&] { return std::make_unique<mb::CablePathLine>(bigCable); }, springAt));
  std::printf("  elastic_catenary     %8.1f us\n",
              perCouplingStep([&] { return std::make_unique<mb::ElasticCatenary>(chainCatenary()); }, chainAt));
  for (int n : {20, 82}) {
    std::printf("  lumped_mass N=%-3d    %8.1f us\n", n,
                perCouplingStep([&] { return std::make_unique<mb::LumpedMassLine>(chain(n)); }, chainAt));
  }
  return sink == 12345.678 ? 1 : 0;
}
