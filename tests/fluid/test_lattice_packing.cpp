// The packed start (fluid/lattice_packing.hpp): a lattice block relaxed by descent on the
// particle concentration C = dx^D sum W, with its faces as mirrors.
// Outside numbers: C on the simple cubic lattice at h = 1.2 dx is 1.0175 in 3D (the sum of
// the Wendland kernel over the lattice, docs/stability.md); a packed block must be even
// (small spread of C), keep every particle inside its faces, keep its mean height (the
// mirrors are symmetric), and keep particles apart.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <moorsph/fluid/box_geometry.hpp>
#include <moorsph/fluid/lattice_packing.hpp>
#include <moorsph/fluid/tait_eos.hpp>

using namespace moorsph::fluid;

namespace {

struct Block {
  FluidParticles<3> f;
  Domain<3> domain;
  Vec<3> lower = Vec<3>::Zero(), upper;
};

// 10 x 12 x 10 spacings, periodic in x and z (the block spans the period), mirrors at y.
Block latticeBlock(double dx) {
  Block b;
  b.upper = Vec<3>(10 * dx, 12 * dx, 10 * dx);
  b.domain.lower = Vec<3>(0.0, -2 * dx, 0.0);
  b.domain.upper = Vec<3>(10 * dx, 20 * dx, 10 * dx);
  b.domain.periodic = {true, false, true};
  fillBox<3>(b.f, b.lower, b.upper, dx, TaitEos(1000.0, 10.0, 7.0), 0.0, b.upper[1]);
  return b;
}

double meanHeight(const FluidParticles<3>& f) {
  double s = 0.0;
  for (const auto& r : f.r) s += r[1];
  return s / static_cast<double>(f.size());
}

}  // namespace

TEST(LatticePacking, MirrorsOnlyWhereTheBlockDoesNotSpanAPeriod) {
  const Block b = latticeBlock(0.1);
  const auto planes = packingMirrors<3>(b.lower, b.upper, b.domain);
  ASSERT_EQ(planes.size(), 2u);
  EXPECT_EQ(planes[0].axis, 1);
  EXPECT_EQ(planes[1].axis, 1);
  Vec<3> half = b.upper;
  half[0] *= 0.5;  // no longer spans x: two more faces
  EXPECT_EQ(packingMirrors<3>(b.lower, half, b.domain).size(), 4u);
}

TEST(LatticePacking, PackedBlockIsEvenInsideItsFacesAndKeepsItsHeight) {
  const double dx = 0.1, h = 1.2 * dx;
  Block b = latticeBlock(dx);
  const std::size_t n = b.f.size();
  const double height = meanHeight(b.f);
  const PackingReport r = packBlock<3>(b.f, b.lower, b.upper, b.domain, dx, h, PackingSpec{});
  std::printf("C %.4f +- %.4f -> %.4f +- %.4f, last rms move %.2e dx\n", r.mean_before, r.spread_before, r.mean_after,
              r.spread_after, r.last_rms_shift);
  EXPECT_NEAR(r.mean_before, 1.0175, 5e-4);  // the cubic lattice's kernel sum
  EXPECT_LT(r.spread_before, 1e-9);
  EXPECT_LT(r.mean_after, r.mean_before - 0.002);  // disordered: below the lattice
  EXPECT_LT(r.spread_after, 0.004);                // and even (the jitter alone: ~0.02)
  EXPECT_LT(r.last_rms_shift, 0.005);              // converged
  ASSERT_EQ(b.f.size(), n);
  double closest2 = 1e30;
  for (std::size_t i = 0; i < n; ++i) {
    EXPECT_GE(b.f.r[i][1], b.lower[1]);
    EXPECT_LE(b.f.r[i][1], b.upper[1]);
    for (std::size_t j = i + 1; j < n; ++j) closest2 = std::min(closest2, b.domain.minimumImage(b.f.r[i] - b.f.r[j]).squaredNorm());
  }
  std::printf("closest pair %.3f dx, mean height moved %.4f dx\n", std::sqrt(closest2) / dx, (meanHeight(b.f) - height) / dx);
  EXPECT_GT(std::sqrt(closest2), 0.6 * dx);
  EXPECT_NEAR(meanHeight(b.f), height, 0.02 * dx);
}

TEST(LatticePacking, TheSameSeedGivesTheSameStart) {
  const double dx = 0.1, h = 1.2 * dx;
  Block a = latticeBlock(dx), b = latticeBlock(dx), c = latticeBlock(dx);
  PackingSpec spec;
  spec.iterations = 50;
  packBlock<3>(a.f, a.lower, a.upper, a.domain, dx, h, spec);
  packBlock<3>(b.f, b.lower, b.upper, b.domain, dx, h, spec);
  spec.seed = 2;
  packBlock<3>(c.f, c.lower, c.upper, c.domain, dx, h, spec);
  double diff_same = 0.0, diff_other = 0.0;
  for (std::size_t i = 0; i < a.f.size(); ++i) {
    diff_same = std::max(diff_same, (a.f.r[i] - b.f.r[i]).norm());
    diff_other = std::max(diff_other, (a.f.r[i] - c.f.r[i]).norm());
  }
  EXPECT_EQ(diff_same, 0.0);
  EXPECT_GT(diff_other, 0.01 * dx);
}
