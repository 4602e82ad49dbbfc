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

namespace {

/// Two boundary particles with one normal each, on surface 0 unless told otherwise.
fl::BoundaryParticles<2> pair(fl::Vec<2> rk, fl::Vec<2> nk, fl::Vec<2> rk2, fl::Vec<2> nk2, std::uint16_t surface2 = 0) {
  fl::BoundaryParticles<2> b;
  b.add(rk * kDx, {nk}, 0);
  b.add(rk2 * kDx, {nk2}, surface2);
  return b;
}

/// Whether particle 1 cancels particle 0's push on a fluid particle at r (in dx), which
/// is behind particle 0's plane unless told otherwise.
bool cancelled(const fl::BoundaryParticles<2>& b, fl::Vec<2> r, bool behind = true) {
  const fl::BoundaryForceLaw<2> law(kStrength, kC, kH, kDx, kOffset);
  r *= kDx;
  EXPECT_GT(law.acceleration(r - b.r[0], b, 0).norm(), 0.0) << "the case must be inside the force's range";
  EXPECT_EQ((r - b.r[0]).dot(b.normals[0]) < 0.0, behind) << "the case is on the wrong side of particle 0's plane";
  return law.beyondEdge(r - b.r[0], 0, r - b.r[1], 1, b);
}

}  // namespace

// Behind a particle's plane (boundary_force_law.hpp "Beyond an edge"): outside a convex
// edge or a thin part the push is cancelled; through a flat wall or a concave corner it
// is kept.
TEST(BoundaryForceLaw, BeyondAnEdgeThePushIsCancelled) {
  const fl::Vec<2> up(0, 1), down(0, -1), right(1, 0);
  // A plate 0.2 dx thick: fluid 0.25 dx below its underside is 0.35 dx behind the top face.
  EXPECT_TRUE(cancelled(pair({0, 0.1}, up, {0.3, -0.1}, down), {0.2, -0.35}));
  // A body's convex corner at the origin (top face y = 0, side face x = 0 below it): fluid
  // beside the side face, 0.2 dx below the top face's plane and 0.7 dx from its particle.
  EXPECT_TRUE(cancelled(pair({-0.4, 0}, up, {0, -0.4}, right), {0.3, -0.2}));
  // A tank's concave corner (side wall x = 0, floor y = 0): fluid through the side wall
  // above the floor keeps the side wall's push.
  EXPECT_FALSE(cancelled(pair({0, 0.4}, right, {0.4, 0}, up), {-0.2, 0.3}));
  // Under a tank's floor beside its corner particle (normals +x and +y at the origin):
  // in front of the corner's wall normal, yet the floor's push is kept.
  {
    fl::BoundaryParticles<2> b;
    b.add(fl::Vec<2>(0.4 * kDx, 0.0), {up}, 0);
    b.add(fl::Vec<2>(0.0, 0.0), {right, up}, 0);
    EXPECT_FALSE(cancelled(b, {0.3, -0.2}));
  }
  // The same corner particle on a body's convex corner (normals +x and +y, top face to
  // its left): fluid beside the side face below the top face's plane is cancelled.
  {
    fl::BoundaryParticles<2> b;
    b.add(fl::Vec<2>(-0.4 * kDx, 0.0), {up}, 0);
    b.add(fl::Vec<2>(0.0, 0.0), {right, up}, 0);
    EXPECT_TRUE(cancelled(b, {0.3, -0.2}));
  }
  // A channel 1.5 dx high (floor y = 0, lid y = 1.5 dx): fluid through the floor is in
  // front of the lid, faces facing each other, not back to back: the floor keeps its push.
  EXPECT_FALSE(cancelled(pair({0, 0}, up, {0.3, 1.5}, down), {0.2, -0.3}));
  // In front of the top face's plane at that convex corner: past the corner along the
  // side normal the top face's push is cancelled, above the top face it is kept.
  {
    fl::BoundaryParticles<2> b;
    b.add(fl::Vec<2>(-0.4 * kDx, 0.0), {up}, 0);
    b.add(fl::Vec<2>(0.0, 0.0), {right, up}, 0);
    EXPECT_TRUE(cancelled(b, {0.3, 0.1}, false));
    EXPECT_FALSE(cancelled(b, {-0.2, 0.3}, false));
  }
  // A smooth convex surface (a circle of radius 3 dx, particles 50 deg apart): fluid at
  // the stand-off 10 deg from the first keeps its push.
  {
    const double a = 50.0 * M_PI / 180.0, f = 10.0 * M_PI / 180.0;
    EXPECT_FALSE(cancelled(pair({0, 3}, up, {3 * std::sin(a), 3 * std::cos(a)}, {std::sin(a), std::cos(a)}),
                           {3.5 * std::sin(f), 3.5 * std::cos(f)}, false));
  }
  // Through a flat wall: behind both particles' planes.
  EXPECT_FALSE(cancelled(pair({0, 0}, up, {1, 0}, up), {0.3, -0.2}));
  // Another surface's particle never cancels (a body beside a wall is not an edge of it).
  EXPECT_FALSE(cancelled(pair({0, 0.1}, up, {0.3, -0.1}, down, 1), {0.2, -0.35}));
  // Out of range (beyond 2h) the other particle does not count.
  EXPECT_FALSE(cancelled(pair({0, 0.1}, up, {3.0, -0.1}, down), {0.2, -0.35}));
}
