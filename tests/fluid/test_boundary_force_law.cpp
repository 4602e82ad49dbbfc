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

namespace {

/// A flat 3D wall patch: boundary particles on a square lattice of spacing dx in the
/// plane y = 0, normals +y, (2 n + 1)^2 of them centred on the origin.
fl::BoundaryParticles<3> latticeWall(int n) {
  fl::BoundaryParticles<3> b;
  for (int i = -n; i <= n; ++i)
    for (int k = -n; k <= n; ++k) b.add(fl::Vec<3>(i * kDx, 0.0, k * kDx), {fl::Vec<3>(0.0, 1.0, 0.0)}, 0);
  return b;
}

fl::Vec<3> wallAcceleration(const fl::BoundaryForceLaw<3>& law, const fl::BoundaryParticles<3>& b, const fl::Vec<3>& r) {
  fl::Vec<3> a = fl::Vec<3>::Zero();
  for (std::size_t k = 0; k < b.size(); ++k) a += law.acceleration(r - b.r[k], b, k);
  return a;
}

/// Work per unit mass of the wall force around a rectangle in the x-y plane at z, from
/// (x0, y0) to (x1, y1) [in dx], by Simpson's rule on each side.
double loopWork(const fl::BoundaryForceLaw<3>& law, const fl::BoundaryParticles<3>& b, double x0, double y0,
                double x1, double y1, double z) {
  const fl::Vec<3> corner[5] = {{x0, y0, z}, {x1, y0, z}, {x1, y1, z}, {x0, y1, z}, {x0, y0, z}};
  const int n = 20000;  // intervals per side (even); the along-wall part jumps where |r_par| = dx
  double work = 0.0;
  for (int s = 0; s < 4; ++s) {
    const fl::Vec<3> p = corner[s] * kDx, d = (corner[s + 1] - corner[s]) * kDx;
    double side = 0.0;
    for (int i = 0; i <= n; ++i) {
      const double w = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
      side += w * wallAcceleration(law, b, p + (double(i) / n) * d).dot(d);
    }
    work += side / (3.0 * n);
  }
  return work;
}

}  // namespace

// The reference law pushes along n_k with a size that depends on the position along the
// wall (B), so it is not the gradient of a potential: round a closed path in front of a
// 3D lattice wall a fluid particle gains or loses work. The conservative form
// (boundary_force_law.hpp) is minus the gradient of strength c^2 B(r_par) Psi(q), so the
// same path gives no work (to the quadrature error), and its normal part is the reference
// law's.
TEST(BoundaryForceLaw, ConservativeFormDoesNoWorkRoundAClosedPath) {
  const fl::BoundaryForceLaw<3> reference(kStrength, kC, kH, kDx, kOffset);
  const fl::BoundaryForceLaw<3> conservative(kStrength, kC, kH, kDx, kOffset, true);
  const auto wall = latticeWall(3);
  // The path crosses from over a wall particle to between four and spans the force's
  // range in depth (0.15 dx to 0.6 dx from the wall; the law reaches 0.7 dx).
  const double ref = loopWork(reference, wall, 0.0, 0.15, 0.5, 0.6, 0.3);
  const double con = loopWork(conservative, wall, 0.0, 0.15, 0.5, 0.6, 0.3);
  // Scale: the work of the push from 0.6 dx in to 0.15 dx on the normal.
  const double scale = std::abs(loopWork(reference, wall, 0.0, 0.15, 1e-9, 0.6, 0.3)) +
                       reference.acceleration(fl::Vec<3>(0, 0.15 * kDx, 0), wall, 24).y() * 0.45 * kDx;
  std::printf("closed-path work per unit mass: reference %.3e, conservative %.3e, scale %.3e [m^2/s^2]\n", ref, con,
              scale);
  EXPECT_GT(std::abs(ref), 1e-3 * scale);
  EXPECT_LT(std::abs(con), 1e-6 * scale);
  // Same normal push, and the along-wall part vanishes straight over a particle.
  const fl::Vec<3> r(0.2 * kDx, 0.3 * kDx, 0.1 * kDx);
  EXPECT_NEAR(conservative.acceleration(r, wall, 0).y(), reference.acceleration(r, wall, 0).y(), 1e-12);
  EXPECT_EQ(conservative.acceleration(fl::Vec<3>(0, 0.3 * kDx, 0), wall, 0).x(), 0.0);
}

// Along a flat 2D wall the B of the particles a fluid particle sees sum to one wherever it
// is, so the conservative form's along-wall parts cancel: the wall stays frictionless.
TEST(BoundaryForceLaw, ConservativeFormIsFrictionlessAlongAFlat2DWall) {
  const fl::BoundaryForceLaw<2> law(kStrength, kC, kH, kDx, kOffset, true);
  fl::BoundaryParticles<2> b;
  for (int i = -4; i <= 4; ++i) b.add(fl::Vec<2>(i * kDx, 0.0), {fl::Vec<2>(0.0, 1.0)}, 0);
  for (double x : {0.13, 0.37, 0.5}) {
    const fl::Vec<2> r(x * kDx, 0.35 * kDx);
    fl::Vec<2> a = fl::Vec<2>::Zero();
    double along = 0.0;  // the largest single along-wall push, for scale
    for (std::size_t k = 0; k < b.size(); ++k) {
      const fl::Vec<2> ak = law.acceleration(r - b.r[k], b, k);
      a += ak;
      along = std::max(along, std::abs(ak.x()));
    }
    EXPECT_GT(along, 0.0);
    EXPECT_LT(std::abs(a.x()), 1e-9 * along) << "x = " << x << " dx";
  }
}
