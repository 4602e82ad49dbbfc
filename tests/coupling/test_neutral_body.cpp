// A neutrally buoyant body (density ratio 1) released under water stays put (issue 5).
// It is not exactly weightless in SPH: the fluid sees the body's surface eps_R dx
// away from where it is sampled (METHOD 6.1), which changes the buoyancy by
// D eps_R dx / R of the weight (D = 2: area, 3: volume) and accelerates the body at
//   a = (dB / W) g / (1 + C_a),   C_a = 1 (cylinder), 1/2 (sphere).
// The boundary-offset study (docs/validation/sphere-offset.md) measured |eps_R| <= 0.06
// at the default b_off = 0.5; the bound here is |eps_R| <= 0.1, so the test fails if the
// offset, the wrench sum or the coupling adds a spurious force of a few percent of the
// weight. A sideways force has no such cause (the tank and the sampling are symmetric
// to within the lattice), so sideways motion is held to a fifth of that bound.
// The 3D case takes minutes: it is compiled separately with label slow.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <moorsph/cases/submerged_body.hpp>

using namespace moorsph;

namespace {

template <int D>
void expectNeutralBodyStaysPut(double dx, double radius, double duration) {
  const double release = 0.3, g = 9.81, eps_bound = 0.1, sideways_fraction = 0.2;
  fluid::Vec<D> centre = fluid::Vec<D>::Constant(D == 2 ? 0.3 : 0.15);
  centre[1] = 0.25;
  auto co = cases::buildSubmergedBody<D>(dx, 1.0, radius, centre, release);
  co.advanceTo(release + duration);
  const auto k = co.bodies().kinematics(0);
  const double rise = k.position[1] - centre[1];
  const double mean_acceleration = 2.0 * rise / (duration * duration);
  const double bound = D * eps_bound * dx / radius * g / (1.0 + cases::addedMassCoefficient<D>());
  double sideways = std::abs(k.position[0] - centre[0]);
  if (D == 3) sideways = std::hypot(sideways, k.position[2] - centre[D - 1]);
  std::printf("%dD neutral body, R = %.0f dx: rise %.2e m in %.2f s (mean acceleration %.4f m/s^2 = eps_R %.3f dx; "
              "bound %.4f), sideways %.2e m, %zu particles\n",
              D, radius / dx, rise, duration, mean_acceleration,
              mean_acceleration * (1.0 + cases::addedMassCoefficient<D>()) / g * radius / (D * dx), bound, sideways,
              co.fluid().fluid().size());
  EXPECT_LT(std::abs(mean_acceleration), bound);
  EXPECT_LT(sideways, sideways_fraction * 0.5 * bound * duration * duration);
  EXPECT_LT(std::abs(k.velocity[1]), bound * duration * 2.0);  // not accelerating away
}

}  // namespace

#ifndef MOORSPH_NEUTRAL_BODY_3D
TEST(NeutralBody, CylinderStaysPut2D) { expectNeutralBodyStaysPut<2>(0.01, 0.05, 0.3); }
#else
TEST(NeutralBody, SphereStaysPut3D) { expectNeutralBodyStaysPut<3>(0.01, 0.05, 0.3); }
#endif
