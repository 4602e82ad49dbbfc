// Cost of the ship scenes' packing probes (cases/ship/ship_base.yaml): a still tank of the
// ship's size at dx = 4 m (700 x 132 x 72 m of water, about the base's 104,000 particles),
// timed over steps and over readings of the two bulk boxes (spacing 1.545 dx). Prints the
// wall time per step, per reading, and the share of the run the readings take at the
// scene's output interval (0.05 s, one reading per about 10.6 steps of 4.7 ms). Figures
// are recorded in docs/scene-reference.md (packing_probes). The printed xi is below 1: this
// tank's side walls cut the kernel near the boxes' z faces (the ship's tank is periodic in z).
#include <omp.h>

#include <chrono>
#include <cstdio>
#include <moorsph/fluid/packing_probe.hpp>
#include <moorsph/fluid/tank_scene.hpp>

int main() {
  using namespace moorsph;
  using fluid::Vec;
  using Clock = std::chrono::steady_clock;
  fluid::TankSpec<3> spec;
  spec.size = Vec<3>(700.0, 170.0, 72.0);
  spec.water_upper = Vec<3>(700.0, 132.0, 72.0);
  spec.dx = 4.0;
  spec.fluid.sound_speed = 10.0 * std::sqrt(2.0 * 9.81 * 132.0);
  spec.fluid.effects = {"pressure", "viscosity", "xsph", "density_diffusion", "gravity", "walls"};
  auto scene = fluid::buildTankScene<3>(spec);
  fluid::FluidSimulation<3> sim(scene.setup, scene.fluid, scene.boundary);
  for (int n = 0; n < 3; ++n) sim.step();  // warm-up: lists built, pages touched
  const auto box = [](Vec<3> lower, Vec<3> upper) {
    fluid::PackingProbeSpec<3> s;
    s.lower = lower;
    s.upper = upper;
    s.spacing = 1.545 * 4.0;
    return fluid::PackingProbe<3>(s);
  };
  const fluid::PackingProbe<3> fore = box(Vec<3>(36, 30, 0), Vec<3>(146, 100, 72));
  const fluid::PackingProbe<3> aft = box(Vec<3>(440, 30, 0), Vec<3>(520, 100, 72));
  const int steps = 20, reads = 50;
  auto t0 = Clock::now();
  for (int n = 0; n < steps; ++n) sim.step();
  const double per_step = std::chrono::duration<double>(Clock::now() - t0).count() / steps;
  double sink = 0.0;
  t0 = Clock::now();
  for (int n = 0; n < reads; ++n) sink += fore.read(sim).mean + aft.read(sim).mean;
  const double per_read = std::chrono::duration<double>(Clock::now() - t0).count() / reads;
  const double steps_per_output = 0.05 / sim.cflDt();
  std::printf("particles=%zu points=%zu+%zu threads=%d step_s=%.4f reading_s=%.5f steps_per_output=%.1f "
              "share_of_run=%.2f%% (xi %.4f)\n",
              sim.fluid().size(), fore.pointCount(), aft.pointCount(), omp_get_max_threads(), per_step, per_read,
              steps_per_output, 100.0 * per_read / (per_read + steps_per_output * per_step), sink / (2.0 * reads));
  return 0;
}
