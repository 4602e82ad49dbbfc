// The cell-grid Verlet lists hold exactly the pairs a brute-force search finds,
// also across periodic boundaries (METHOD.md section 1).
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>
#include <moorsph/fluid/neighbour_search.hpp>

using namespace moorsph::fluid;

namespace {

template <int D>
FluidParticles<D> randomCloud(const Domain<D>& domain, int n, unsigned seed) {
  std::mt19937 gen(seed);
  FluidParticles<D> f;
  for (int i = 0; i < n; ++i) {
    Vec<D> r;
    for (int k = 0; k < D; ++k)
      r[k] = std::uniform_real_distribution<double>(domain.lower[k], domain.upper[k])(gen);
    f.add(r, Vec<D>::Zero(), 1000.0, 1.0);
  }
  return f;
}

template <int D>
void expectListsMatchBruteForce(const Domain<D>& domain, int n) {
  const double support = 0.1, skin = 0.01;
  auto fluid = randomCloud<D>(domain, n, 7);
  BoundaryParticles<D> boundary;
  auto extra = randomCloud<D>(domain, n / 4, 11);
  for (std::size_t k = 0; k < extra.size(); ++k) boundary.add(extra.r[k], {Vec<D>::UnitX()}, 0);
  std::vector<char> tracked(boundary.size(), 1);

  NeighbourSearch<D> search(domain, support, skin);
  search.rebuild(fluid, &boundary, tracked);
  const double R2 = search.listRadius() * search.listRadius();

  std::size_t pairs_checked = 0, periodic_pairs = 0;
  for (std::size_t i = 0; i < fluid.size(); ++i) {
    std::set<std::uint32_t> expected, found;
    for (std::size_t j = 0; j < fluid.size(); ++j) {
      const Vec<D> d = domain.minimumImage(fluid.r[i] - fluid.r[j]);
      if (j != i && d.squaredNorm() < R2) {
        expected.insert(static_cast<std::uint32_t>(j));
        if ((fluid.r[i] - fluid.r[j]).squaredNorm() >= R2) ++periodic_pairs;
      }
    }
    const auto& l = search.fluidFluid();
    for (auto s = l.begin[i]; s < l.begin[i + 1]; ++s) found.insert(l.index[s]);
    ASSERT_EQ(found.size(), l.begin[i + 1] - l.begin[i]) << "duplicate neighbour of " << i;
    ASSERT_EQ(expected, found) << "particle " << i;
    pairs_checked += expected.size();

    std::set<std::uint32_t> expected_b, found_b;
    for (std::size_t k = 0; k < boundary.size(); ++k)
      if (domain.minimumImage(fluid.r[i] - boundary.r[k]).squaredNorm() < R2) expected_b.insert(k);
    const auto& lb = search.fluidBoundary();
    for (auto s = lb.begin[i]; s < lb.begin[i + 1]; ++s) found_b.insert(lb.index[s]);
    ASSERT_EQ(expected_b, found_b) << "boundary neighbours of " << i;
  }
  EXPECT_GT(pairs_checked, 10u * fluid.size());
  if (domain.anyPeriodic()) {
    EXPECT_GT(periodic_pairs, 0u) << "test did not exercise the periodic wrap";
  }
}

}  // namespace

TEST(NeighbourSearch, MatchesBruteForce2D) {
  Domain<2> d;
  d.lower = Vec<2>(0, 0);
  d.upper = Vec<2>(1.0, 0.7);
  expectListsMatchBruteForce<2>(d, 3000);
}

TEST(NeighbourSearch, MatchesBruteForce2DPeriodicX) {
  Domain<2> d;
  d.lower = Vec<2>(-0.3, 0);
  d.upper = Vec<2>(0.77, 0.5);
  d.periodic = {true, false};
  expectListsMatchBruteForce<2>(d, 3000);
}

TEST(NeighbourSearch, MatchesBruteForce3DPeriodicXZ) {
  Domain<3> d;
  d.lower = Vec<3>(0, 0, 0);
  d.upper = Vec<3>(0.5, 0.4, 0.37);
  d.periodic = {true, false, true};
  expectListsMatchBruteForce<3>(d, 4000);
}

TEST(NeighbourSearch, RejectsPeriodicAxisShorterThanThreeCells) {
  Domain<2> d;
  d.upper = Vec<2>(0.25, 1.0);
  d.periodic = {true, false};
  EXPECT_THROW(NeighbourSearch<2>(d, 0.1, 0.01), std::invalid_argument);
}

TEST(NeighbourSearch, ResortKeepsParticleIdentity) {
  Domain<3> d;
  d.upper = Vec<3>(1, 1, 1);
  auto fluid = randomCloud<3>(d, 2000, 3);
  auto copy = fluid;
  NeighbourSearch<3> search(d, 0.1, 0.01);
  search.rebuild(fluid, nullptr, {});
  for (std::size_t k = 0; k < fluid.size(); ++k) EXPECT_EQ(fluid.r[k], copy.r[fluid.id[k]]);
  // Sorted by cell: cell indices never decrease along the arrays.
  for (std::size_t k = 1; k < fluid.size(); ++k)
    EXPECT_LE(search.grid().cellOf(fluid.r[k - 1]), search.grid().cellOf(fluid.r[k]));
}
