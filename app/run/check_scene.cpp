// `moorsph check SCENE`: validate, then report what a run would cost, from the
// built scene and a short timed sample of steps (the sample is thrown away).
#include <omp.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <string>
#include <moorsph/fluid/waves/piston_signal.hpp>
#include <moorsph/io/scene_builder.hpp>
#include <moorsph/io/scene_loader.hpp>
#include "run_scene.hpp"
#if MOORSPH_HAS_BODIES
#include "scene_bodies.hpp"
#endif

namespace moorsph::app {
namespace {

/// Resident memory of this process [bytes], from /proc (0 where unavailable).
double residentBytes() {
  std::ifstream statm("/proc/self/statm");
  double pages = 0.0, resident = 0.0;
  statm >> pages >> resident;
  return resident * 4096.0;
}

template <int D>
int checkDim(const io::SceneConfig& c) {
  const double rss0 = residentBytes();
  auto built = io::buildScene<D>(c);
  std::unique_ptr<fluid::FluidSimulation<D>> plain;
  std::vector<std::string> body_lines;
#if MOORSPH_HAS_BODIES
  std::unique_ptr<coupling::CoSimulation<D>> co;
  if (!c.bodies.empty()) {
    co = makeCoSimulation<D>(c, built, built.scene.fluid, {});
    body_lines = describeBodies(c, co->bodies());
  }
  fluid::FluidSimulation<D>* coupled = co ? &co->updFluid() : nullptr;
#else
  if (!c.bodies.empty()) throw std::invalid_argument("this moorsph was built without bodies (MOORSPH_WITH_BODIES=OFF)");
  fluid::FluidSimulation<D>* coupled = nullptr;
#endif
  if (!coupled) {
    plain = std::make_unique<fluid::FluidSimulation<D>>(built.scene.setup, built.scene.fluid, built.scene.boundary);
    io::addSceneEffects(*plain, c, built);
  }
  fluid::FluidSimulation<D>& sim = coupled ? *coupled : *plain;
  const std::size_t nb = sim.walls() ? sim.walls()->particles().size() : 0;
  std::printf("scene %s: %dD '%s', valid\n", c.file.c_str(), D, c.name.c_str());
  std::printf("  particles: %zu fluid, %zu boundary\n", sim.fluid().size(), nb);
  for (const auto& note : built.notes) std::printf("  note: %s\n", note.c_str());
  std::printf("  dx = %g m, boundary spacing = %g m, h = %g m (h/dx = %g)\n", c.dx, c.spacing(), sim.setup().h(),
              c.method.h_factor);
  std::printf("  c_s = %g m/s (10 sqrt(2 g H) = %g m/s for H = %g m)\n", c.sound_speed, 10.0 * c.expectedSpeed(),
              c.waterHeight());
  const double dt = sim.cflDt();
  const double steps = std::ceil(c.end_time / dt);
  std::printf("  dt <= %.4e s (CFL %g); end time %g s: at least %.0f steps\n", dt, c.method.cfl, c.end_time, steps);
  std::string effects;
  for (const auto& e : sim.effectNames()) effects += " " + e;
  std::printf("  effects:%s (method %s)\n", effects.c_str(), c.method.name.c_str());
  std::printf("  sensors: %zu wave gauges, %zu pressure probes, %zu velocity probes, %zu packing probes\n", c.gauges.size(),
              c.probes.size(), c.velocity_probes.size(), c.packing_probes.size());
  for (std::size_t k = 0; k < built.body_surfaces.size(); ++k) {
    std::size_t n = 0;
    for (auto s : sim.walls()->particles().surface) n += s == built.body_surfaces[k] ? 1 : 0;
    std::printf("  %s; %zu boundary particles on its surface\n", body_lines[k].c_str(), n);
  }
  for (std::size_t k = built.body_surfaces.size(); k < body_lines.size(); ++k) std::printf("  %s\n", body_lines[k].c_str());
  if (c.piston.present && c.piston.signal == "regular") {
    // What resolution the waves get: particles per wavelength and per wave height.
    const auto& p = c.piston;
    const double g = c.gravityMagnitude();
    const fluid::waves::AiryWave wave(0.5 * p.wave_height, p.period, p.depth, g);
    std::printf("  piston: H = %g m, T = %g s, d = %g m: stroke %.4g m, wavelength %.4g m (%.0f dx), H = %.1f dx, kd = %.3g\n",
                p.wave_height, p.period, p.depth, fluid::waves::pistonStroke(p.wave_height, p.period, p.depth, g),
                wave.wavelength(), wave.wavelength() / c.dx, p.wave_height / c.dx, wave.waveNumber() * p.depth);
  }
  // Timed sample: a few steps, at most ~2 s of wall time; the first step (list
  // building, first touches) is not counted.
  sim.step();
  const auto start = std::chrono::steady_clock::now();
  int sampled = 0;
  double wall = 0.0;
  while (sampled < 50 && wall < 2.0) {
    sim.step();
    ++sampled;
    wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  const double per_step = wall / sampled;
  const double estimate = per_step * steps;
  std::printf("  timed sample: %d steps, %.3g ms/step on %d threads -> estimated wall time %.3g s (%.3g h)\n", sampled,
              1e3 * per_step, omp_get_max_threads(), estimate, estimate / 3600.0);
  const double rss = residentBytes() - rss0;
  std::printf("  memory: about %.1f MiB for the particles, lists and work arrays (measured)\n", rss / 1048576.0);
  const double snapshots = c.output.particles_interval > 0.0 ? std::floor(c.end_time / c.output.particles_interval) + 1 : 0.0;
  const double snapshot_bytes = snapshots * static_cast<double>(sim.fluid().size() + nb) * (8.0 * 8.0 + 4.0 + 8.0);
  std::printf("  output: %.0f time-series rows, %.0f particle snapshots (~%.1f MiB)\n",
              std::floor(c.end_time / c.output.interval) + 1, snapshots, snapshot_bytes / 1048576.0);
  return kSuccess;
}

}  // namespace

int checkScene(const std::string& scene, const std::vector<std::string>& sets, int threads) {
  if (threads > 0) omp_set_num_threads(threads);
  try {
    const io::SceneConfig c = io::loadSceneFile(scene, sets);
    return c.dim == 2 ? checkDim<2>(c) : checkDim<3>(c);
  } catch (const io::SceneError& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return kBadInput;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s: %s\n", scene.c_str(), e.what());
    return kBadInput;
  }
}

}  // namespace moorsph::app
