// Light-body hard case (issue 5): a fully submerged body lighter than water, a
// circular cylinder in 2D or a sphere in 3D, held while the fluid settles, then
// released from rest. Potential flow gives the unbounded cylinder an added mass C_a = 1
// times the displaced mass and the sphere C_a = 1/2; in this 2D tank the floor, walls and
// free surface raise the cylinder's to 1.0547 (cases/floating_box/confined_added_mass.py,
// a boundary-element solution; the 3D tank's correction is not computed, so 3D uses 1/2).
// The initial acceleration is a0 = (1 - r)/(r + C_a) g for density ratio r; at r = 0.1
// the cylinder's added mass is ten times its own, the classic failure case of explicit
// coupling.
// Prints per ratio whether the run stayed finite, the mean acceleration over the first
// 100 ms, 2 (y - y0)/t^2, and the speed at 100 ms against potential flow's. A 20 ms mean
// is not used: the tank's acoustic period (about 64 ms in 2D) and the water's residual
// motion after the hold move it by 0.3-1.7 a0 (docs/accuracy-cost.md, added mass).
// Usage: moorsph_submerged_release [--3d] [dx=0.01] [ratios...]
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>
#include <moorsph/cases/command_line.hpp>
#include <moorsph/cases/submerged_body.hpp>

namespace {

using namespace moorsph;

template <int D>
void sweep(double dx, const std::vector<double>& ratios) {
  const double radius = 0.05, release = 0.3, window = 0.1;
  const double added_mass_coefficient = cases::tankAddedMassCoefficient<D>();
  fluid::Vec<D> centre = fluid::Vec<D>::Constant(D == 2 ? 0.3 : 0.15);
  centre[1] = 0.2;
  std::printf("# %s R = %.3f m (%.1f dx), dx = %.4f m, release at %.2f s, C_a = %.4f\n", D == 2 ? "cylinder" : "sphere",
              radius, radius / dx, dx, release, added_mass_coefficient);
  std::printf("# ratio  stable  mean_accel_0-100ms  potential_flow_a0  ratio_to_a0  speed_100ms/a0t  particles\n");
  for (double ratio : ratios) {
    auto co = cases::buildSubmergedBody<D>(dx, ratio, radius, centre, release);
    bool stable = true;
    try {
      while (co.time() < release + window - 1e-12) co.step();
    } catch (const std::exception& e) {
      stable = false;
      std::fprintf(stderr, "ratio %.2f: %s\n", ratio, e.what());
    }
    const double t = co.time() - release;
    const auto& kin = co.bodies().kinematics(0);
    const double mean_accel = 2.0 * (kin.position[1] - centre[1]) / (t * t);
    const double a0 = cases::releaseAcceleration(ratio, added_mass_coefficient);
    std::printf("%6.2f  %6s  %18.3f  %17.3f  %11.3f  %15.3f  %9zu\n", ratio, stable ? "yes" : "NO", mean_accel, a0,
                mean_accel / a0, kin.velocity[1] / (a0 * t), co.fluid().fluid().size());
  }
}

}  // namespace

int main(int argc, char** argv) {
  int arg = 1;
  const bool three_d = argc > 1 && std::string(argv[1]) == "--3d";
  if (three_d) ++arg;
  const double dx = argc > arg ? moorsph::cases::numberArgument(argv[arg], "DX", "moorsph_submerged_release") : 0.01;
  std::vector<double> ratios{0.1, 0.2, 0.5, 0.8};
  if (argc > arg + 1) ratios.clear();
  for (int a = arg + 1; a < argc; ++a) ratios.push_back(moorsph::cases::numberArgument(argv[a], "density ratio", "moorsph_submerged_release"));
  if (three_d) sweep<3>(dx, ratios);
  else sweep<2>(dx, ratios);
}
