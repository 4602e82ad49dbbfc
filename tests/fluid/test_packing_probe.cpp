// The packing probe (fluid/packing_probe.hpp) against facts outside the code: a lattice
// whose particle volumes tile the space reads xi = 1 (the kernel's partition of unity);
// squeezing the positions by a factor s with the volumes unchanged raises xi by s^-D
// (2D and 3D); a box straddling a still surface is wet below the volume's edge only; the
// cell-grid path after a step gives the brute-force kernel sums.
#include <gtest/gtest.h>

#include <cmath>
#include <moorsph/fluid/packing_probe.hpp>
#include <moorsph/fluid/tank_scene.hpp>

using namespace moorsph;
using fluid::Vec;

namespace {

/// A still tank at dx whose densities give every particle the volume dx^D.
template <int D>
fluid::Scene<D> tank(double dx) {
  fluid::TankSpec<D> spec;
  spec.size = Vec<D>::Constant(0.3);
  spec.size[1] = 0.4;
  spec.water_upper = spec.size;
  spec.water_upper[1] = 0.25;
  spec.dx = dx;
  spec.fluid.sound_speed = 10.0 * std::sqrt(2.0 * 9.81 * 0.25);
  spec.fluid.effects = {"pressure", "gravity", "walls"};
  fluid::Scene<D> scene = fluid::buildTankScene<D>(spec);
  for (std::size_t i = 0; i < scene.fluid.size(); ++i) scene.fluid.rho[i] = scene.fluid.m[i] / std::pow(dx, D);
  return scene;
}

template <int D>
fluid::PackingProbe<D> box(Vec<D> lower, Vec<D> upper, double spacing) {
  fluid::PackingProbeSpec<D> s;
  s.lower = lower;
  s.upper = upper;
  s.spacing = spacing;
  return fluid::PackingProbe<D>(s);
}

/// Squeezes the positions towards `centre` by the factor s (volumes unchanged): the
/// particles then sit closer than their volumes say, as in session 37's compacted tank.
template <int D>
void squeeze(fluid::Scene<D>& scene, const Vec<D>& centre, double s) {
  for (auto& r : scene.fluid.r) r = centre + s * (r - centre);
}

}  // namespace

TEST(PackingProbe, ReadsOneOnATilingLatticeAndSMinusDWhenSqueezed2D) {
  const double dx = 0.005;
  auto scene = tank<2>(dx);
  const auto probe = box<2>(Vec<2>(0.08, 0.06), Vec<2>(0.22, 0.16), 0.0037);  // off-lattice points
  fluid::PackingReading still;
  {
    fluid::FluidSimulation<2> sim(scene.setup, scene.fluid, scene.boundary);
    still = probe.read(sim);
  }
  std::printf("2D lattice: xi %.6f +- %.2e over %zu points\n", still.mean, still.spread, probe.pointCount());
  // Pointwise the Wendland kernel's partition of unity errs by up to about 1% at h = 1.2 dx
  // (measured spread 0.72%); averaged over points spread across the lattice cells the
  // error cancels (the kernel integrates to 1).
  EXPECT_NEAR(still.mean, 1.0, 5e-4);
  EXPECT_LT(still.spread, 1e-2);
  EXPECT_DOUBLE_EQ(still.wet_fraction, 1.0);
  const double s = 0.98;
  squeeze<2>(scene, Vec<2>(0.15, 0.11), s);
  fluid::FluidSimulation<2> sim(scene.setup, scene.fluid, scene.boundary);
  const fluid::PackingReading packed = probe.read(sim);
  std::printf("squeezed by %.2f: xi ratio %.6f against s^-2 = %.6f\n", s, packed.mean / still.mean, 1.0 / (s * s));
  EXPECT_NEAR(packed.mean / still.mean, 1.0 / (s * s), 1e-3);
}

TEST(PackingProbe, SqueezedBy1PercentIn3DReadsSMinus3) {
  const double dx = 0.02;
  auto scene = tank<3>(dx);
  const auto probe = box<3>(Vec<3>(0.08, 0.06, 0.08), Vec<3>(0.22, 0.16, 0.22), 0.013);
  fluid::PackingReading still;
  {
    fluid::FluidSimulation<3> sim(scene.setup, scene.fluid, scene.boundary);
    still = probe.read(sim);
  }
  const double s = 0.99;
  squeeze<3>(scene, Vec<3>(0.15, 0.11, 0.15), s);
  fluid::FluidSimulation<3> sim(scene.setup, scene.fluid, scene.boundary);
  const fluid::PackingReading packed = probe.read(sim);
  std::printf("3D lattice: xi %.6f; squeezed by %.2f: ratio %.6f against s^-3 = %.6f\n", still.mean, s,
              packed.mean / still.mean, std::pow(s, -3.0));
  EXPECT_NEAR(still.mean, 1.0, 1e-3);
  EXPECT_NEAR(packed.mean / still.mean, std::pow(s, -3.0), 1e-3);
}

// The volume's edge is 0.25 m (half a spacing above the top row). A box from 0.15 to 0.35 m
// is wet in its lower half: xi = 1/2 lies at the edge of a uniform half space.
TEST(PackingProbe, ABoxThroughTheSurfaceIsWetBelowTheVolumeEdge) {
  const double dx = 0.005;
  auto scene = tank<2>(dx);
  fluid::FluidSimulation<2> sim(scene.setup, scene.fluid, scene.boundary);
  const auto probe = box<2>(Vec<2>(0.1, 0.15), Vec<2>(0.2, 0.35), 0.001);  // 200 rows of points
  const fluid::PackingReading r = probe.read(sim);
  EXPECT_NEAR(r.wet_fraction, 0.5, 0.01);
  EXPECT_GT(r.mean, 0.5);
  EXPECT_LT(r.mean, 1.0);  // the wet rows near the surface hold a cut kernel
  const auto dry = box<2>(Vec<2>(0.1, 0.3), Vec<2>(0.2, 0.35), 0.005).read(sim);
  EXPECT_EQ(dry.wet_fraction, 0.0);
  EXPECT_TRUE(std::isnan(dry.mean));
}

TEST(PackingProbe, GridPathMatchesAScanOfEveryParticle) {
  auto scene = tank<2>(0.005);
  fluid::FluidSimulation<2> sim(scene.setup, scene.fluid, scene.boundary);
  for (int n = 0; n < 20; ++n) sim.step();  // densities and positions move off the lattice
  const auto probe = box<2>(Vec<2>(0.03, 0.02), Vec<2>(0.27, 0.2), 0.011);
  EXPECT_EQ(probe.pointCount(), 22u * 16u);  // 0.24 / 0.011 -> 22 cells, 0.18 / 0.011 -> 16
  const fluid::PackingReading r = probe.read(sim);
  const auto& f = sim.fluid();
  double sum = 0.0, sum2 = 0.0;
  int wet = 0;
  for (const Vec<2>& point : probe.points()) {
    ASSERT_TRUE((point.array() > Vec<2>(0.03, 0.02).array()).all() && (point.array() < Vec<2>(0.27, 0.2).array()).all());
    double xi = 0.0;
    for (std::size_t j = 0; j < f.size(); ++j) xi += sim.kernel().value((f.r[j] - point).norm()) * f.m[j] / f.rho[j];
    if (xi < 0.5) continue;
    sum += xi;
    sum2 += xi * xi;
    ++wet;
  }
  ASSERT_GT(wet, 0);
  EXPECT_NEAR(r.mean, sum / wet, 1e-13);
  EXPECT_NEAR(r.spread, std::sqrt(sum2 / wet - (sum / wet) * (sum / wet)), 1e-9);
}

TEST(PackingProbe, RefusesAnEmptyBoxOrNoSpacing) {
  EXPECT_THROW(box<2>(Vec<2>(0.1, 0.1), Vec<2>(0.1, 0.2), 0.01), std::invalid_argument);
  EXPECT_THROW(box<2>(Vec<2>(0.1, 0.1), Vec<2>(0.2, 0.2), 0.0), std::invalid_argument);
}
