// Green water (coupling/green_water.hpp): the fluid volume above a deck inside its
// outline equals the geometric volume of a lattice-filled slab, for a rectangle and a
// triangle outline, at any pose of the body (the particles are moved with it).
#include <gtest/gtest.h>

#include <cmath>
#include <moorsph/coupling/green_water.hpp>

using namespace moorsph;

namespace {

/// A lattice of spacing s filling [lo, hi] (body frame), each particle of volume s^3,
/// placed in ground by the pose.
fluid::FluidParticles<3> slab(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, double s,
                              const bodies::BodyKinematics& pose) {
  fluid::FluidParticles<3> f;
  for (double x = lo.x() + s / 2; x < hi.x(); x += s)
    for (double y = lo.y() + s / 2; y < hi.y(); y += s)
      for (double z = lo.z() + s / 2; z < hi.z(); z += s)
        f.add(pose.pointToGround(Eigen::Vector3d(x, y, z)), fluid::Vec<3>::Zero(), 1000.0, 1000.0 * s * s * s);
  return f;
}

}  // namespace

TEST(GreenWater, SlabOnARectangularAndATriangularDeck) {
  bodies::BodyKinematics pose;
  pose.position = Eigen::Vector3d(10.0, -3.0, 4.0);
  pose.orientation = Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitY()) * Eigen::AngleAxisd(-0.2, Eigen::Vector3d::UnitZ());
  // Water 0.5 m deep over the deck (y 1.0 -> 1.5) and around it, and below the deck.
  const auto water = slab(Eigen::Vector3d(-0.5, 0.5, -0.5), Eigen::Vector3d(2.5, 1.5, 1.5), 0.05, pose);
  coupling::DeckOutline deck;
  deck.deck_height = 1.0;
  deck.outline = {{0.0, 0.0}, {2.0, 0.0}, {2.0, 1.0}, {0.0, 1.0}};
  EXPECT_NEAR(coupling::greenWaterVolume<3>(water, pose, deck), 2.0 * 1.0 * 0.5, 1e-9);
  deck.outline = {{0.0, 0.0}, {2.0, 0.0}, {0.0, 1.0}};  // area 1 m^2 under 0.5 m of water
  EXPECT_NEAR(coupling::greenWaterVolume<3>(water, pose, deck), 1.0 * 0.5, 0.01 * 0.5);
  deck.deck_height = 2.0;  // above all the water
  EXPECT_EQ(coupling::greenWaterVolume<3>(water, pose, deck), 0.0);
}

TEST(GreenWater, TwoDimensionalDeckIsAnInterval) {
  bodies::BodyKinematics pose;
  pose.position = Eigen::Vector3d(1.0, 2.0, 0.0);
  pose.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitZ()));
  fluid::FluidParticles<2> f;
  const double s = 0.01;
  for (double x = -0.2 + s / 2; x < 0.5; x += s)
    for (double y = 0.1 + s / 2; y < 0.2; y += s) {
      const Eigen::Vector3d r = pose.pointToGround(Eigen::Vector3d(x, y, 0.0));
      f.add(fluid::Vec<2>(r.x(), r.y()), fluid::Vec<2>::Zero(), 1000.0, 1000.0 * s * s);
    }
  coupling::DeckOutline deck;
  deck.deck_height = 0.15;
  deck.outline = {{0.0, 0.0}, {0.3, 0.0}};
  EXPECT_NEAR(coupling::greenWaterVolume<2>(f, pose, deck), 0.3 * 0.05, 1e-9);
  EXPECT_TRUE(coupling::insideOutline({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 0.5, 0.5));
  EXPECT_FALSE(coupling::insideOutline({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 1.5, 0.5));
}
