// The mirror_floor effect (MirrorFloorTerm, pair_terms.hpp): a free-slip floor of
// mirror images with the pressure continued hydrostatically. Checked against
// hydrostatics and against free slip, in a 2D block periodic along x:
//  - the images carry the water's weight: the sum of m dv/dt over the fluid (gravity
//    included) averages within 0.5% of M g of zero once the start-up sound has passed
//    (and never exceeds 3% of it);
//  - the water stays where it was put: the pressure is rho0 g (depth - y) within 2% down
//    to the row next to the floor (a row of wall particles cannot do this: it pushes
//    only, so its neighbours carry a distorted pressure, and at h = 2 dx it holds the
//    water 0.45 dx higher, docs/validation/wave-propagation.md), no particle goes below
//    the floor, and the kinetic energy stays below 1e-4 of the weight times dx;
//  - a uniform stream along the floor keeps its speed to 0.1% over 0.5 s and the row
//    next to the floor moves with the rest (no boundary layer, nothing to slow it);
//  - a dam break with side walls: the floor holds and the energy does not grow.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <moorsph/fluid/box_geometry.hpp>
#include <moorsph/fluid/fluid_simulation.hpp>
#include <moorsph/fluid/tank_scene.hpp>

using namespace moorsph::fluid;

namespace {

constexpr double kDx = 0.01, kWidth = 0.2, kDepth = 0.2, kG = 9.81;

FluidSimulation<2> mirrorFloorBlock(double stream_speed) {
  FluidSetup<2> s;
  s.dx = kDx;
  s.sound_speed = 10.0 * std::sqrt(2.0 * kG * kDepth);
  s.method.h_factor = 2.0;
  s.method.predictor_fraction = 0.5;
  s.method.density_diffusion_form = DensityDiffusionForm::Renormalised;
  s.effects = {"pressure", "viscosity", "density_diffusion", "gravity", "mirror_floor"};
  s.mirror_floor_height = 0.0;
  s.domain.lower = Vec<2>(0.0, -0.1);
  s.domain.upper = Vec<2>(kWidth, 3.0 * kDepth);
  s.domain.periodic = {true, false};
  FluidParticles<2> water;
  fillBox<2>(water, Vec<2>(0.0, 0.0), Vec<2>(kWidth, kDepth), kDx, TaitEos(s.rho0, s.sound_speed, s.method.gamma), kG,
             kDepth);
  for (auto& v : water.v) v = Vec<2>(stream_speed, 0.0);
  return FluidSimulation<2>(s, water, BoundaryGeometry<2>{});
}

/// A 2D tank with side walls on the mirror floor and the wave settings (h = 2 dx, wall
/// law on 1.2 dx, renormalised density diffusion): water from the floor to
/// `water_upper`, c_s = 10 sqrt(2 g depth).
TankSpec<2> wallsOnTheMirrorFloor(const Vec<2>& size, const Vec<2>& water_upper, double dx, double depth,
                                  double predictor_fraction) {
  TankSpec<2> spec;
  spec.size = size;
  spec.water_upper = water_upper;
  spec.dx = dx;
  spec.fluid.sound_speed = 10.0 * std::sqrt(2.0 * kG * depth);
  spec.fluid.method.h_factor = 2.0;
  spec.fluid.method.boundary_h_factor = 1.2;
  spec.fluid.method.predictor_fraction = predictor_fraction;
  spec.fluid.method.density_diffusion_form = DensityDiffusionForm::Renormalised;
  spec.fluid.effects = {"pressure", "viscosity", "density_diffusion", "gravity", "walls", "mirror_floor"};
  return spec;
}

/// Sum over the fluid of m dv/dt (gravity included) [N per metre of width].
Vec<2> netForce(const FluidParticles<2>& f) {
  Vec<2> sum = Vec<2>::Zero();
  for (std::size_t i = 0; i < f.size(); ++i) sum += f.m[i] * f.dvdt[i];
  return sum;
}

double totalMass(const FluidParticles<2>& f) {
  double m = 0.0;
  for (double mi : f.m) m += mi;
  return m;
}

}  // namespace

TEST(MirrorFloor, CarriesTheWeightWhereTheWaterWasPut) {
  auto sim = mirrorFloorBlock(0.0);
  const double weight = totalMass(sim.fluid()) * kG;
  double worst_net = 0.0, late_net = 0.0;
  long late_steps = 0;
  double bottom_p = 0.0, bottom_y = 0.0;
  long bottom_samples = 0;
  while (sim.time() < 1.0) {
    sim.step();
    const auto& f = sim.fluid();
    worst_net = std::max(worst_net, std::abs(netForce(f)[1]));
    if (sim.time() > 0.5) {
      late_net += netForce(f)[1];
      ++late_steps;
    }
    for (std::size_t i = 0; i < f.size(); ++i) {
      ASSERT_GT(f.r[i][1], 0.0) << "particle " << f.id[i] << " went below the floor at t = " << sim.time();
      if (sim.time() > 0.5 && f.r[i][1] < kDx) {
        bottom_p += f.p[i];
        bottom_y += f.r[i][1];
        ++bottom_samples;
      }
    }
  }
  const auto& f = sim.fluid();
  late_net /= static_cast<double>(late_steps);
  bottom_p /= bottom_samples;
  bottom_y /= bottom_samples;
  const double rho0 = sim.setup().rho0;
  const double expected = rho0 * kG * (kDepth - bottom_y);
  double top = 0.0;
  for (const auto& r : f.r) top = std::max(top, r[1]);
  const double ke = sim.calcEnergy().kinetic;
  std::printf("sum m a_y: mean over 0.5-1 s %.3e N/m (%.2e of the weight), worst %.2e of it; bottom row at y = %.4f m: p = %.1f Pa, "
              "rho0 g (d - y) = %.1f Pa (ratio %.4f); top particle %.4f m (initial %.4f); KE %.3e J/m\n",
              late_net, late_net / weight, worst_net / weight, bottom_y, bottom_p, expected, bottom_p / expected, top, kDepth - 0.5 * kDx,
              ke);
  EXPECT_LT(std::abs(late_net), 0.005 * weight) << "the images do not carry the water's weight";
  EXPECT_LT(worst_net, 0.03 * weight);
  EXPECT_NEAR(bottom_p, expected, 0.02 * expected);
  EXPECT_NEAR(top, kDepth - 0.5 * kDx, 0.1 * kDx);
  EXPECT_LT(ke, 1e-4 * weight * kDx);
}

TEST(MirrorFloor, IsFreeSlip) {
  const double U = 0.2;
  auto sim = mirrorFloorBlock(U);
  while (sim.time() < 0.5) sim.step();
  const auto& f = sim.fluid();
  double mean_u = 0.0, bottom_u = 0.0;
  long bottom = 0;
  for (std::size_t i = 0; i < f.size(); ++i) {
    mean_u += f.v[i][0];
    if (f.r[i][1] < kDx) {
      bottom_u += f.v[i][0];
      ++bottom;
    }
  }
  mean_u /= static_cast<double>(f.size());
  bottom_u /= static_cast<double>(bottom);
  std::printf("after 0.5 s: mean u = %.6f m/s, row next to the floor u = %.6f m/s (stream %.3f m/s)\n", mean_u,
              bottom_u, U);
  EXPECT_NEAR(mean_u, U, 1e-3 * U);
  EXPECT_NEAR(bottom_u, U, 1e-3 * U);
}

// A dam break in a tank with side walls and the mirror floor: the front runs along the
// floor, slams into the far wall's corner and falls back. The floor must hold (no
// particle below it, however hard it is hit in the corner: MirrorFloorReflection) and
// the total energy may only fall (kinetic + potential + elastic; nothing here adds
// any). Side walls at h = 2 dx with the wall law on the reference length
// (boundary_h_factor 1.2, b_off 0.5: reach 0.7 dx): the front must not enter the far wall.
// The largest energy gain measured is 0.9% of the peak kinetic energy, at the slam
// (0.15% with a softer wall, b_off 1.3 on h): the stiff wall under the non-damping
// midpoint predictor; the bound is 2%.
TEST(MirrorFloor, HoldsADamBreakWithSideWalls) {
  const TankSpec<2> spec = wallsOnTheMirrorFloor(Vec<2>(0.4, 0.3), Vec<2>(0.1, 0.2), kDx / 2, 0.2, 0.5);
  auto scene = buildTankScene<2>(spec);
  FluidSimulation<2> sim(scene.setup, scene.fluid, scene.boundary);
  const auto e0 = sim.calcEnergy();
  const double total0 = e0.kinetic + e0.potential + e0.elastic;
  double worst_gain = 0.0, ke_peak = 0.0, front = 0.0;
  while (sim.time() < 0.6) {
    sim.step();
    const auto e = sim.calcEnergy();
    worst_gain = std::max(worst_gain, e.kinetic + e.potential + e.elastic - total0);
    ke_peak = std::max(ke_peak, e.kinetic);
    for (const auto& r : sim.fluid().r) {
      ASSERT_GE(r[1], 0.0) << "a particle is below the floor at t = " << sim.time();
      front = std::max(front, r[0]);
    }
  }
  const auto e = sim.calcEnergy();
  std::printf("dam break on the mirror floor: front reached x = %.3f m; KE peak %.3f J/m, at 0.6 s %.3f J/m; "
              "largest energy gain %.2e J/m (%.2e of the peak KE); lost %.3f J/m\n",
              front, ke_peak, e.kinetic, worst_gain, worst_gain / ke_peak, total0 - (e.kinetic + e.potential + e.elastic));
  EXPECT_GT(front, 0.39) << "the front did not reach the far wall";
  EXPECT_LT(front, 0.4) << "a particle went into the far wall";
  EXPECT_LT(worst_gain, 0.02 * ke_peak);
}

// A floor has no meaning in a domain periodic along y: refused at construction.
TEST(MirrorFloor, RefusesAPeriodicVertical) {
  FluidSetup<2> s;
  s.dx = kDx;
  s.effects = {"pressure", "gravity", "mirror_floor"};
  s.domain.lower = Vec<2>(0.0, 0.0);
  s.domain.upper = Vec<2>(kWidth, kDepth);
  s.domain.periodic = {true, true};
  FluidParticles<2> water;
  fillBox<2>(water, Vec<2>(0.0, 0.0), Vec<2>(kWidth, kDepth), kDx, TaitEos(s.rho0, s.sound_speed, s.method.gamma), 0.0,
             kDepth);
  EXPECT_THROW(FluidSimulation<2>(s, water, BoundaryGeometry<2>{}), std::invalid_argument);
}

// Still water in a tank with side walls on the mirror floor, with the wave settings
// (h = 2 dx, wall law on 1.2 dx, predictor_fraction 0.55, renormalised diffusion): the
// corners where a side wall meets the floor plane must calm down like the rest. A
// particle pressed into such a corner crosses the plane every step. When the predicted
// state was reflected but the corrector restarted from the unreflected velocity, each
// step added dt a to its downward speed while it stayed on the plane: here the fastest
// particle of the row next to the floor reached 0.52 m/s (0.33 sqrt(g d)) over 1.0-1.5 s,
// up from 0.21 m/s over 0.3-0.8 s, in the corner (0.88 m/s at 1.5 s with predictor
// fraction 0.52), and in a 3 m piston flume at the same spacing 1.3 m/s while the water
// around was still. Asserted for that row (y < dx), over 1.0-1.5 s: no particle faster
// than 0.1 sqrt(g d) and no faster than over 0.3-0.8 s (the start-up noise of the
// lattice against the walls must decay, not grow). Measured: 0.098 m/s (0.062 sqrt(g d))
// against 0.195 m/s; none below the floor.
namespace {

/// The fastest particle of the row next to the floor (y < dx) over 0.3-0.8 s and over
/// 1.0-1.5 s of still water in `spec`'s tank; asserts that none goes below the floor.
struct FloorRowSpeeds {
  double early = 0.0, late = 0.0;
};

FloorRowSpeeds floorRowSpeeds(const TankSpec<2>& spec) {
  auto scene = buildTankScene<2>(spec);
  FluidSimulation<2> sim(scene.setup, scene.fluid, scene.boundary);
  FloorRowSpeeds speeds;
  while (sim.time() < 1.5) {
    sim.step();
    const auto& f = sim.fluid();
    const double t = sim.time();
    double* window = t >= 1.0 ? &speeds.late : (t >= 0.3 && t <= 0.8 ? &speeds.early : nullptr);
    for (std::size_t i = 0; i < f.size(); ++i) {
      EXPECT_GE(f.r[i][1], 0.0) << "a particle is below the floor at t = " << t;
      if (window && f.r[i][1] < spec.dx) *window = std::max(*window, f.v[i].norm());
    }
  }
  return speeds;
}

void expectStillCorners(const TankSpec<2>& spec, const char* integrator) {
  const FloorRowSpeeds speeds = floorRowSpeeds(spec);
  const double scale = std::sqrt(kG * 0.25);
  std::printf("still water on the mirror floor with side walls (%s), fastest particle of the floor row: %.4f m/s "
              "(%.3f sqrt(g d)) over 0.3-0.8 s, %.4f m/s (%.3f sqrt(g d)) over 1.0-1.5 s\n",
              integrator, speeds.early, speeds.early / scale, speeds.late, speeds.late / scale);
  EXPECT_LT(speeds.late, 0.1 * scale);
  EXPECT_LE(speeds.late, speeds.early);
}

}  // namespace

TEST(MirrorFloor, StillWaterStaysStillInTheCorners) {
  expectStillCorners(wallsOnTheMirrorFloor(Vec<2>(0.5, 0.4), Vec<2>(0.5, 0.25), 0.0125, 0.25, 0.55),
                     "predictor_fraction 0.55");
}

// The same with the symplectic step, which the wave scenes run. Measured: 0.194 m/s over
// 0.3-0.8 s, 0.129 m/s (0.082 sqrt(g d)) over 1.0-1.5 s. This case guards the wave scenes'
// corners, not the fix above: with the predicted state reflected as well, the symplectic
// step did not pump here (0.115 m/s over 1.0-1.5 s; its corrector advances the position
// from the predicted state, not from the step's start).
TEST(MirrorFloor, StillWaterStaysStillInTheCornersWithTheSymplecticStep) {
  TankSpec<2> spec = wallsOnTheMirrorFloor(Vec<2>(0.5, 0.4), Vec<2>(0.5, 0.25), 0.0125, 0.25, 0.5);
  spec.fluid.method.integrator = Integrator::Symplectic;
  expectStillCorners(spec, "symplectic");
}
