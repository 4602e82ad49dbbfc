// Light-body sweep (issue 5): a 2D box started at its Archimedes draught, held while
// the fluid settles, released, and run for a while, for a range of density ratios.
// Prints per ratio: whether the run stayed finite, the time-averaged draught against
// Archimedes, the largest body speed, and the wall time. Explicit coupling is
// expected to fail first for the lightest bodies (added mass >> body mass).
// Usage: moorsph_light_body_sweep [dx=0.01] [end=1.4] [ratios...]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>
#include <moorsph/cases/command_line.hpp>
#include <moorsph/cases/floating_box.hpp>
#include <moorsph/coupling/co_simulation.hpp>

int main(int argc, char** argv) {
  using namespace moorsph;
  const double dx = argc > 1 ? moorsph::cases::numberArgument(argv[1], "DX", "moorsph_light_body_sweep") : 0.01;
  const double end = argc > 2 ? moorsph::cases::numberArgument(argv[2], "END", "moorsph_light_body_sweep") : 1.4;
  std::vector<double> ratios{0.05, 0.1, 0.2, 0.3, 0.5, 0.8};
  if (argc > 3) ratios.clear();
  for (int a = 3; a < argc; ++a) ratios.push_back(moorsph::cases::numberArgument(argv[a], "density ratio", "moorsph_light_body_sweep"));
  std::printf("# dx = %.4f m, mu = 0.01 Pa s, release at 0.2 s, end %.2f s\n", dx, end);
  std::printf("# ratio  stable  draught_err_%%  max_speed_m/s  steps  wall_s\n");
  for (double ratio : ratios) {
    cases::FloatingBox box;
    box.dx = dx;
    box.density_ratio = ratio;
    box.mu = 0.01;
    auto scene = cases::buildFloatingBox(box);
    scene.system->initialize();
    coupling::CoSimulation<2> co(std::move(scene.fluid), std::move(scene.system), {{0, 1}}, {0.2, 0.0});
    const auto start = std::chrono::steady_clock::now();
    double sum = 0.0, vmax = 0.0;
    long n = 0;
    bool stable = true;
    try {
      while (co.time() < end) {
        co.step();
        const auto k = co.bodies().kinematics(0);
        vmax = std::max(vmax, k.velocity.norm());
        if (co.time() > end - 1.0) {
          sum += k.position[1] - box.height / 2;
          ++n;
        }
      }
    } catch (const std::exception& e) {
      stable = false;
      std::fprintf(stderr, "ratio %.2f: %s\n", ratio, e.what());
    }
    const double draught = n > 0 ? scene.still_level - sum / n : 0.0;
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("%6.2f  %6s  %13.2f  %13.4f  %5zu  %6.1f\n", ratio, stable ? "yes" : "NO",
                100.0 * (draught / box.draught() - 1.0), vmax, co.fluid().stepCount(), wall);
  }
}
