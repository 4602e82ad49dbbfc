// Light-body hard case (issue 5): a fully submerged body lighter than water, a
// circular cylinder in 2D or a sphere in 3D, held while the fluid settles, then
// released from rest. Potential flow gives the cylinder an added mass C_a = 1 times
// the displaced mass and the sphere C_a = 1/2, so the initial acceleration is
// a0 = (1 - r)/(r + C_a) g for density ratio r; at r = 0.1 the cylinder's added mass is
// ten times its own, the classic failure case of explicit coupling.
// Prints per ratio whether the run stayed finite, the mean acceleration over the first
// 20 ms against a0, and the rise after 0.1 s.
// Usage: moorsph_submerged_release [--3d] [dx=0.01] [ratios...]
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>
#include <moorsph/cases/submerged_body.hpp>

namespace {

using namespace moorsph;

template <int D>
void sweep(double dx, const std::vector<double>& ratios) {
  const double radius = 0.05, release = 0.3, added_mass_coefficient = cases::addedMassCoefficient<D>();
  fluid::Vec<D> centre = fluid::Vec<D>::Constant(D == 2 ? 0.3 : 0.15);
  centre[1] = 0.2;
  std::printf("# %s R = %.3f m (%.1f dx), dx = %.4f m, release at %.2f s, C_a = %.1f\n", D == 2 ? "cylinder" : "sphere",
              radius, radius / dx, dx, release, added_mass_coefficient);
  std::printf("# ratio  stable  mean_accel_0-20ms  potential_flow_a0  ratio_to_a0  rise_0.1s_m  particles\n");
  for (double ratio : ratios) {
    auto co = cases::buildSubmergedBody<D>(dx, ratio, radius, centre, release);
    double v20 = 0.0;
    bool stable = true;
    try {
      while (co.time() < release + 0.1) {
        co.step();
        if (v20 == 0.0 && co.time() >= release + 0.02) v20 = co.bodies().kinematics(0).velocity[1] / (co.time() - release);
      }
    } catch (const std::exception& e) {
      stable = false;
      std::fprintf(stderr, "ratio %.2f: %s\n", ratio, e.what());
    }
    const double a0 = cases::releaseAcceleration<D>(ratio);
    std::printf("%6.2f  %6s  %17.3f  %17.3f  %11.3f  %11.4f  %9zu\n", ratio, stable ? "yes" : "NO", v20, a0, v20 / a0,
                co.bodies().kinematics(0).position[1] - centre[1], co.fluid().fluid().size());
  }
}

}  // namespace

int main(int argc, char** argv) {
  int arg = 1;
  const bool three_d = argc > 1 && std::string(argv[1]) == "--3d";
  if (three_d) ++arg;
  const double dx = argc > arg ? std::atof(argv[arg]) : 0.01;
  std::vector<double> ratios{0.1, 0.2, 0.5, 0.8};
  if (argc > arg + 1) ratios.clear();
  for (int a = arg + 1; a < argc; ++a) ratios.push_back(std::atof(argv[a]));
  if (three_d) sweep<3>(dx, ratios);
  else sweep<2>(dx, ratios);
}
