// Sphere surface sampling (fluid/shape_sampling): points on the sphere with outward
// radial unit normals, no point farther than the requested spacing from its nearest
// neighbour (METHOD 2: a boundary
// coarser than the fluid lets fluid leak in), and, for the latitude-ring sampling, no
// sideways force from a pressure that depends on height alone: sum p(y) n_x = sum p(y)
// n_z = 0, the discrete form of the fact that hydrostatic pressure pushes a sphere
// straight up. The Fibonacci lattice leaves a residual (printed for the record).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <moorsph/fluid/shape_sampling.hpp>

using namespace moorsph::fluid;

namespace {

struct Check {
  double max_radius_error = 0.0, max_normal_error = 0.0, widest_gap = 0.0, lateral_over_vertical = 0.0;
};

// Sideways over vertical force of the pressure p = max(level - y, 0) with equal weights.
Check inspect(const BoundaryParticles<3>& s, const Vec<3>& centre, double radius, double level) {
  Check c;
  Vec<3> force = Vec<3>::Zero();
  for (std::size_t i = 0; i < s.size(); ++i) {
    const Vec<3> d = s.r[i] - centre;
    const Vec<3> n = s.normals[s.normal_begin[i]];
    c.max_radius_error = std::max(c.max_radius_error, std::abs(d.norm() - radius));
    c.max_normal_error = std::max(c.max_normal_error, (n - d / radius).norm());
    double nearest = 1e300;
    for (std::size_t j = 0; j < s.size(); ++j)
      if (j != i) nearest = std::min(nearest, (s.r[j] - s.r[i]).norm());
    c.widest_gap = std::max(c.widest_gap, nearest);
    force -= std::max(level - s.r[i][1], 0.0) * n;
  }
  c.lateral_over_vertical = std::hypot(force[0], force[2]) / std::abs(force[1]);
  return c;
}

}  // namespace

TEST(ShapeSampling, RingSphereIsOnTheSurfaceWithNoGapAndNoSidewaysHydrostaticForce) {
  const Vec<3> centre(0.3, 0.2, 0.1);
  for (double spacing : {0.0254, 0.0169, 0.0101}) {
    const double radius = 0.1015;
    const auto rings = sampleSphereRings(centre, radius, spacing);
    const auto fib = sampleSphere<3>(centre, radius, spacing);
    for (double level : {centre[1], centre[1] + 0.37 * radius, centre[1] + 2 * radius}) {
      const Check r = inspect(rings, centre, radius, level), f = inspect(fib, centre, radius, level);
      std::printf("spacing %.4f level %+.3f R: rings %zu points, nearest-neighbour distance <= %.4f, sideways/vertical %.1e; "
                  "Fibonacci %zu points, <= %.4f, sideways/vertical %.1e\n",
                  spacing, (level - centre[1]) / radius, rings.size(), r.widest_gap, r.lateral_over_vertical, fib.size(),
                  f.widest_gap, f.lateral_over_vertical);
      EXPECT_LT(r.max_radius_error, 1e-12);
      EXPECT_LT(r.max_normal_error, 1e-12);
      EXPECT_LE(r.widest_gap, spacing * (1 + 1e-9));
      EXPECT_LT(r.lateral_over_vertical, 1e-12);
      EXPECT_LT(f.max_normal_error, 1e-12);
    }
  }
}
