// Wave-making effects against closed forms: rigid surface motion rebuilt exactly
// from body-frame references, the piston following its prescribed displacement
// exactly, the natural cubic spline, the damping zone's exponential decay, the
// forcing region's relaxation rate 10^kappa mu / rho, and METHOD.md's periodic dx.
#include <gtest/gtest.h>

#include <cmath>
#include <moorsph/fluid/box_geometry.hpp>
#include <moorsph/fluid/cubic_spline.hpp>
#include <moorsph/fluid/damping_zone.hpp>
#include <moorsph/fluid/fluid_simulation.hpp>
#include <moorsph/fluid/forcing_region.hpp>
#include <moorsph/fluid/piston.hpp>
#include <moorsph/fluid/tank_scene.hpp>

using namespace moorsph::fluid;

TEST(MovableSurface, RebuiltExactlyFromReferencesWithoutDrift) {
  FluidSetup<3> setup;
  setup.dx = 0.01;
  setup.effects = {"pressure", "walls"};
  BoundaryGeometry<3> geometry;
  SurfaceInfo info{"box", true, true, Eigen::Vector3d(0.5, 0.5, 0.5)};
  geometry.addSurface(sampleBoxSurface<3>(Vec<3>(0.45, 0.45, 0.45), Vec<3>(0.55, 0.55, 0.55), 0.01, allFaces<3>(),
                                          NormalSide::Outward),
                      info);
  const auto initial = geometry.particles;
  Walls<3> walls(geometry, setup);
  // Many small incremental rotations: positions must equal the one-shot pose exactly.
  const double angle_step = 0.001;
  RigidMotion<3> m;
  for (int n = 1; n <= 1000; ++n) {
    m.rotation = Eigen::AngleAxisd(n * angle_step, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
    m.position = Vec<3>(0.5 + 1e-4 * n, 0.5, 0.5 - 2e-4 * n);
    walls.setSurfaceMotion(0, m);
  }
  const auto& b = walls.particles();
  double worst = 0.0;
  for (std::size_t k = 0; k < b.size(); ++k) {
    const Vec<3> expected = m.position + m.rotation * (initial.r[k] - Vec<3>(0.5, 0.5, 0.5));
    worst = std::max(worst, (b.r[k] - expected).norm());
    for (std::uint32_t a = b.normal_begin[k]; a < b.normal_begin[k + 1]; ++a)
      EXPECT_NEAR((b.normals[a] - m.rotation * initial.normals[a]).norm(), 0.0, 1e-15);
  }
  EXPECT_EQ(worst, 0.0);
  // Rigid: distances between particles unchanged.
  EXPECT_NEAR((b.r[0] - b.r[b.size() - 1]).norm(), (initial.r[0] - initial.r[b.size() - 1]).norm(), 1e-15);
  EXPECT_THROW(walls.setSurfaceMotion(1, m), std::invalid_argument);
}

TEST(CubicSpline, InterpolatesKnotsAndSmoothFunctions) {
  std::vector<double> t, x;
  for (int i = 0; i <= 400; ++i) {
    t.push_back(0.01 * i);
    x.push_back(0.05 * std::sin(2.0 * M_PI * t.back()));
  }
  const CubicSpline s(t, x);
  for (std::size_t i = 0; i < t.size(); ++i) EXPECT_NEAR(s.value(t[i]), x[i], 1e-15);
  for (double q = 0.2; q < 3.8; q += 0.137) {
    EXPECT_NEAR(s.value(q), 0.05 * std::sin(2 * M_PI * q), 1e-7);  // h^4 accuracy away from the ends
    EXPECT_NEAR(s.derivative(q), 0.1 * M_PI * std::cos(2 * M_PI * q), 1e-5);
  }
  const CubicSpline line({0.0, 1.0, 3.0, 4.0}, {1.0, 3.0, 7.0, 9.0});  // x = 1 + 2t: reproduced exactly
  EXPECT_NEAR(line.value(2.2), 5.4, 1e-14);
  EXPECT_NEAR(line.derivative(0.7), 2.0, 1e-14);
  EXPECT_THROW(CubicSpline({0.0, 0.0}, {1.0, 2.0}), std::invalid_argument);
}

TEST(Piston, BoundaryFollowsPrescribedDisplacementExactly) {
  TankSpec<2> spec;
  spec.size = Vec<2>(1.0, 0.3);
  spec.water_lower = Vec<2>(0.05, 0.0);
  spec.water_upper = Vec<2>(1.0, 0.15);
  spec.dx = 0.01;
  spec.fluid.effects = {"pressure", "gravity", "walls"};
  auto scene = buildTankScene<2>(spec);
  BoundaryParticles<2> plate = sampleBoxSurface<2>(Vec<2>(0.0, 0.0), Vec<2>(0.04, 0.3), 0.01,
                                                   {false, true, false, false}, NormalSide::Outward);
  scene.boundary.addSurface(plate, SurfaceInfo{"piston", true, true, Eigen::Vector3d(0.04, 0.0, 0.0)});
  FluidSimulation<2> sim(scene.setup, scene.fluid, scene.boundary);
  const double stroke = 0.02, omega = 2.0 * M_PI;
  auto X = [&](double t) { return stroke * std::sin(omega * t); };
  auto V = [&](double t) { return stroke * omega * std::cos(omega * t); };
  sim.addEffect(std::make_unique<Piston<2>>(sim.updWalls(), 1, X, V));
  const auto [first, last] = sim.walls()->surfaceRange(1);
  for (int n = 0; n < 200; ++n) {
    sim.step();
    for (std::size_t k = first; k < last; ++k)
      ASSERT_NEAR(sim.walls()->particles().r[k][0], 0.04 + X(sim.time()), 1e-15) << "step " << n;
  }
  EXPECT_EQ(sim.effectNames().back(), "piston");
  EXPECT_THROW(Piston<2>(nullptr, 1, X, V), std::invalid_argument);
}

namespace {
// A periodic box of fluid moving uniformly: pair forces cancel, so only the effect acts.
FluidSimulation<2> uniformFlow(double u) {
  FluidSetup<2> s;
  s.dx = 0.01;
  s.sound_speed = 10.0;
  s.effects = {"pressure"};
  s.domain.upper = Vec<2>(0.1, 0.1);
  s.domain.periodic = {true, true};
  FluidParticles<2> f;
  fillBox<2>(f, s.domain.lower, s.domain.upper, s.dx, TaitEos(s.rho0, s.sound_speed), 0.0, 0.0);
  for (auto& v : f.v) v = Vec<2>(u, 0.0);
  return FluidSimulation<2>(s, f);
}
}  // namespace

TEST(DampingZone, HorizontalVelocityDecaysExponentially) {
  auto sim = uniformFlow(0.3);
  const double k = 4.0;
  sim.addEffect(std::make_unique<DampingZone<2>>(-1.0, -0.5, k, sim.cflDt()));  // whole box beyond x_end
  sim.advanceTo(0.5);
  // The reference predictor-corrector multiplies v by 1 - k dt + (k dt)^2 per step
  // (first order; METHOD.md section 1): exact for the scheme, and within
  // k^2 dt t / 2 of the exponential.
  const double kdt = k * sim.lastDt();
  const double discrete = 0.3 * std::pow(1.0 - kdt + kdt * kdt, static_cast<double>(sim.stepCount()));
  const double exact = 0.3 * std::exp(-k * sim.time());
  for (const auto& v : sim.fluid().v) {
    ASSERT_NEAR(v[0], discrete, 1e-9 * discrete);
    ASSERT_NEAR(v[0], exact, (k * kdt * sim.time()) * exact);
  }
  EXPECT_THROW(DampingZone<2>(0.0, 1.0, 1.0 / sim.cflDt(), sim.cflDt()), std::invalid_argument);
}

TEST(ForcingRegion, RelaxesTowardTargetAtRateTenToKappaMuOverRho) {
  auto sim = uniformFlow(0.0);
  ForcingRegionSpec spec;
  spec.x_start = -1.0;
  spec.length = 2.0;
  spec.floor = -1.0;
  spec.still_level = 1.0;  // the whole box; kappa = 7, mu = 1e-3: rate 10 1/s for rho = 1000
  const double U = 0.2;
  sim.addEffect(std::make_unique<ForcingRegion<2>>(spec, [U](double, double, double) { return Eigen::Vector2d(U, 0.0); },
                                                   sim.cflDt()));
  sim.advanceTo(0.2);
  const double expected = U * (1.0 - std::exp(-10.0 * sim.time()));
  for (const auto& v : sim.fluid().v) ASSERT_NEAR(v[0], expected, 2e-3 * expected);
}

TEST(ForcingRegion, PeriodicSpacingOfMethodExample) {
  // METHOD.md 4a: L = 4.669 m, dx* = 10 mm, h_f = 1.2 gives dx = 10.24 mm.
  EXPECT_NEAR(periodicSpacing(4.669, 0.010, 1.2), 0.01024, 5e-6);
  EXPECT_THROW(periodicSpacing(0.05, 0.01, 1.2), std::invalid_argument);
}
