// Throughput benchmark: a 2D or 3D dam break of about N fluid particles, timed over
// a fixed number of steps after a short warm-up. Prints one line of figures:
// particles, neighbours per particle, steps, wall seconds, particle-steps per
// second, neighbour interactions per second (pairs within 2h per force evaluation,
// two evaluations per step), nanoseconds per particle-step, bytes per particle
// (peak RSS / particles) and the thread count. Run one configuration per process so
// the peak RSS belongs to it: bench/run_throughput.sh drives the sweep.
#include <omp.h>
#include <sys/resource.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <moorsph/cases/dam_break.hpp>
#include <moorsph/fluid/fluid_simulation.hpp>

namespace {

template <int D>
int run(double target_particles, int steps) {
  using namespace moorsph;
  cases::DamBreakSpec<D> spec;
  spec.column_width = 0.2;
  spec.tank_length = 0.8;
  spec.tank_height = 0.5;
  spec.tank_width = 0.4;
  // Column a x 2a (x W in 3D): N = 2 a^2 / dx^2 (2D) or 2 a^2 W / dx^3 (3D).
  const double volume = 2.0 * spec.column_width * spec.column_width * (D == 3 ? spec.tank_width : 1.0);
  spec.dx = std::pow(volume / target_particles, 1.0 / D);
  auto scene = cases::buildDamBreak<D>(spec);
  fluid::FluidSimulation<D> sim(scene.setup, scene.fluid, scene.boundary);
  for (int n = 0; n < 3; ++n) sim.step();  // warm-up: first list build, page faults
  const auto interactions0 = sim.totalInteractions();
  const auto phases0 = sim.phaseTimers().seconds();
  const auto rebuilds0 = sim.neighbours().rebuildCount();
  const auto t0 = std::chrono::steady_clock::now();
  for (int n = 0; n < steps; ++n) sim.step();
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const double interactions = static_cast<double>(sim.totalInteractions() - interactions0);
  const double n = static_cast<double>(sim.fluid().size());
  struct rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  const double rss_bytes = usage.ru_maxrss * 1024.0;
  std::printf("%dD particles=%.0f boundary=%zu dx=%.5f neighbours=%.1f steps=%d wall_s=%.3f "
              "particle_steps_per_s=%.4g interactions_per_s=%.4g ns_per_particle_step=%.1f "
              "bytes_per_particle=%.0f threads=%d\n",
              D, n, sim.walls()->particles().size(), spec.dx, interactions / (2.0 * steps * n), steps, wall,
              n * steps / wall, interactions / wall, 1e9 * wall / (n * steps), rss_bytes / n, omp_get_max_threads());
  std::printf("   list rebuilds: %zu in %d steps;", sim.neighbours().rebuildCount() - rebuilds0, steps);
  std::printf(" phases:");
  const auto& names = sim.phaseTimers().names();
  const auto& secs = sim.phaseTimers().seconds();
  for (std::size_t k = 0; k < names.size(); ++k) std::printf(" %s=%.1f%%", names[k].c_str(), 100.0 * (secs[k] - phases0[k]) / wall);
  std::printf("\n");
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 4) {
    std::fprintf(stderr, "usage: moorsph_bench_throughput DIM PARTICLES STEPS  (threads from OMP_NUM_THREADS)\n");
    return 1;
  }
  const int dim = std::atoi(argv[1]);
  const double particles = std::atof(argv[2]);
  const int steps = std::atoi(argv[3]);
  return dim == 2 ? run<2>(particles, steps) : run<3>(particles, steps);
}
