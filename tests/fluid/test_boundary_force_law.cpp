// The wall force of METHOD.md section 2 against its formula, evaluated by hand here,
// and its bound behind the boundary particle's plane (boundary_force_law.hpp).
#include <moorsph/fluid/boundary_force_law.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace fl = moorsph::fluid;

namespace {

constexpr double kDx = 0.01, kH = 1.2 * kDx, kC = 20.0, kStrength = 0.01, kOffset = 0.5;

fl::BoundaryParticles<2> flatWallParticle() {
  fl::BoundaryParticles<2> b;
  b.add(fl::Vec<2>(0.0, 0.0), {fl::Vec<2>(0.0, 1.0)}, 0);
  return b;
}

double pushAt(double perp_over_dx, double par_over_dx = 0.0) {
  const fl::BoundaryForceLaw<2> law(kStrength, kC, kH, kDx, kOffset);
  return law.acceleration(fl::Vec<2>(par_over_dx * kDx, perp_over_dx * kDx), flatWallParticle(), 0).y();
}

}  // namespace

// In front of the wall: 0.01 c^2 / h B S(q), q = (r_perp + 0.5 dx) / h.
TEST(BoundaryForceLaw, InFrontFollowsMethodFormula) {
  const double scale = kStrength * kC * kC / kH;
  // r_perp = 0.3 dx, on the normal: q = 0.8 dx / 1.2 dx = 2/3, S = (0.8 / q)^8 = 1.2^8.
  EXPECT_NEAR(pushAt(0.3), scale * std::pow(1.2, 8), 1e-9 * scale);
  // r_perp = 0.5 dx, 0.4 dx along the wall: q = 5/6 (second branch), B = 0.6.
  EXPECT_NEAR(pushAt(0.5, 0.4), scale * 0.6 * 25.0 * std::pow(5.0 / 6.0 - 1.0, 2), 1e-9 * scale);
  // Beyond q = 1 (r_perp = 0.7 dx) nothing; along the wall beyond dx nothing.
  EXPECT_EQ(pushAt(0.71), 0.0);
  EXPECT_EQ(pushAt(0.3, 1.01), 0.0);
}

// Behind the particle's plane the push is held at its value on the plane, S(0.5/1.2) =
// 1.92^8 = 184.6, where the formula would rise to infinity at r_perp = -0.5 dx (the
// thin-hull blow-up of docs/validation/ship.md finding 1). Beyond the offset plane
// there is still nothing.
TEST(BoundaryForceLaw, BehindThePlaneThePushIsBounded) {
  const double scale = kStrength * kC * kC / kH;
  const double on_plane = scale * std::pow(0.8 * 1.2 / 0.5, 8);
  EXPECT_NEAR(pushAt(0.0), on_plane, 1e-9 * on_plane);
  for (double perp : {-0.1, -0.3, -0.49, -0.4999999})
    EXPECT_NEAR(pushAt(perp), on_plane, 1e-7 * on_plane) << "r_perp = " << perp << " dx";
  EXPECT_EQ(pushAt(-0.5000001), 0.0);
  // Continuous at the plane, and falling off in front of it.
  EXPECT_NEAR(pushAt(1e-9), on_plane, 1e-6 * on_plane);
  EXPECT_LT(pushAt(0.05), on_plane);
}
