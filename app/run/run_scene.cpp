#include "run_scene.hpp"

#include <omp.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstdio>
#include <filesystem>
#include <unistd.h>
#include <yaml-cpp/yaml.h>
#include <fstream>
#include <moorsph/cases/run_recorder.hpp>
#include <moorsph/io/checkpoint.hpp>
#include <moorsph/io/csv_export.hpp>
#include <moorsph/io/particle_file.hpp>
#include <moorsph/io/scene_builder.hpp>
#include <moorsph/io/scene_loader.hpp>
#include <moorsph/io/series_history.hpp>
#include "progress.hpp"
#include "scene_series.hpp"
#if MOORSPH_HAS_BODIES
#include "scene_bodies.hpp"
#endif

namespace moorsph::app {
namespace {

namespace fs = std::filesystem;

std::atomic<bool> g_stop{false};
/// True once the scene is built and stepping. Before that a signal has nothing to save,
/// and the set-up (packing the water, sampling hulls) can take minutes at fine spacings:
/// the run stops at once instead of building the scene only to checkpoint its start.
std::atomic<bool> g_stepping{false};

extern "C" void onSignal(int) {
  if (!g_stepping.load()) {
    static const char message[] = "\ninterrupted while setting up the scene: nothing to save yet, stopped\n";
    (void)!write(STDERR_FILENO, message, sizeof message - 1);  // async-signal-safe, unlike stdio
    std::_Exit(kInterrupted);
  }
  g_stop.store(true);
}

std::string format(const char* fmt, double a, double b = 0.0, double c = 0.0) {
  char text[256];
  std::snprintf(text, sizeof text, fmt, a, b, c);
  return text;
}

/// The first top-level key that defines the particle set (dimension, resolution,
/// geometry, piston plate) and differs between two resolved scenes, or "".
std::string changedParticleSetKey(const std::string& saved, const std::string& current) {
  const YAML::Node a = YAML::Load(saved), b = YAML::Load(current);
  for (const char* key : {"dim", "resolution", "geometry"}) {
    YAML::Emitter ea, eb;
    ea << a[key];
    eb << b[key];
    if (std::string(ea.c_str()) != eb.c_str()) return key;
  }
  const YAML::Node pa = a["piston"], pb = b["piston"];
  if (pa.IsDefined() != pb.IsDefined()) return "piston";
  if (pa.IsDefined())
    for (const char* key : {"x", "bottom", "top", "z"}) {
      YAML::Emitter ea, eb;
      ea << pa[key];
      eb << pb[key];
      if (std::string(ea.c_str()) != eb.c_str()) return std::string("piston.") + key;
    }
  // A body's surface and start pose define boundary particles and where water starts.
  const YAML::Node ba = a["bodies"], bb = b["bodies"];
  const std::size_t na = ba.IsDefined() ? ba.size() : 0, nb = bb.IsDefined() ? bb.size() : 0;
  if (na != nb) return "bodies";
  for (std::size_t k = 0; k < na; ++k)
    for (const char* key : {"shape", "position", "offset", "orientation_deg"}) {
      YAML::Emitter ea, eb;
      ea << ba[k][key];
      eb << bb[k][key];
      if (std::string(ea.c_str()) != eb.c_str()) return "bodies." + std::to_string(k) + "." + key;
    }
  return "";
}

/// Log notes for the mooring lines (matched by name) whose model differs from the one in
/// the scene a checkpoint was written for: what the restarted line starts from.
std::vector<std::string> changedLineModels(const std::string& saved, const std::string& current) {
  const YAML::Node a = YAML::Load(saved)["moorings"], b = YAML::Load(current)["moorings"];
  std::vector<std::string> notes;
  if (!a.IsSequence() || !b.IsSequence()) return notes;
  for (const YAML::Node& now : b)
    for (const YAML::Node& before : a) {
      if (before["name"].as<std::string>("") != now["name"].as<std::string>("-")) continue;
      const std::string from = before["model"].as<std::string>(""), to = now["model"].as<std::string>("");
      if (from == to) continue;
      const char* start = to == "lumped_mass" ? "it starts at rest in its static shape between the restored ends"
                          : from == "lumped_mass" ? "the saved nodes are dropped"
                                                  : "neither model keeps a state of its own";
      notes.push_back("line '" + now["name"].as<std::string>() + "': " + from + " in the checkpoint's run, " + to +
                      " now (" + start + ")");
    }
  return notes;
}

/// Whether the scene a checkpoint was written for builds the same boundary particles
/// (surfaces by name, positions to 1e-9 m) as `built`: then a geometry written differently
/// (e.g. a face given the full period instead of stopping one spacing short of it, which
/// the builder makes the same particles) does not block the restart.
template <int D>
bool sameBoundary(const std::string& saved_yaml, const io::BuiltScene<D>& built) {
  try {
    const io::BuiltScene<D> saved =
        io::buildScene<D>(io::loadSceneText(saved_yaml, "checkpoint scene"), io::WaterBuild::Skip);
    const auto &a = saved.scene.boundary, &b = built.scene.boundary;
    if (a.surfaces.size() != b.surfaces.size() || a.particles.size() != b.particles.size()) return false;
    for (std::size_t s = 0; s < a.surfaces.size(); ++s)
      if (a.surfaces[s].name != b.surfaces[s].name) return false;
    for (std::size_t k = 0; k < a.particles.size(); ++k)
      if ((a.particles.r[k] - b.particles.r[k]).norm() > 1e-9 * (1.0 + b.particles.r[k].norm())) return false;
    return true;
  } catch (const std::exception&) {
    return false;  // the saved scene no longer loads or builds: keep the textual verdict
  }
}

/// A restart's series.h5 starts with the rows the interrupted run wrote up to the
/// checkpoint (read from the series.h5 beside it), so its series run from t = 0.
void carryRestartHistory(RunLog& log, const std::string& checkpoint, io::SeriesFile& series, double restart_time) {
  const std::string previous = (fs::path(checkpoint).parent_path() / "series.h5").string();
  if (!fs::exists(previous)) {
    log.line(format("  note: no series.h5 beside the checkpoint; the series start at t = %.6g s", restart_time));
    return;
  }
  try {
    const io::CarriedHistory h = io::carrySeriesHistory(previous, series, restart_time);
    std::string names;
    for (const auto& n : h.carried) names += " " + n;
    log.line(format("  series: %.0f rows up to t = %.6g s carried from ", static_cast<double>(h.rows), restart_time) +
             previous + " (" + std::to_string(h.carried.size()) + " series:" + names + ")");
    for (const auto& n : h.skipped) log.line("  note: series '" + n + "' not in " + previous + " with these columns; it starts at the restart");
  } catch (const std::exception& e) {
    log.line(std::string("  note: the earlier series could not be carried (") + e.what() + "); the series start at the restart");
  }
}

template <int D>
int runDim(const io::SceneConfig& config, const RunOptions& o, const std::string& out) {
  using Clock = std::chrono::steady_clock;
  // Files of an earlier run in the same directory would mix with this one's.
  for (const char* stale : {"particles.h5", "particles.xmf", "error.txt", "failure.checkpoint.h5"}) {
    std::error_code ignored;
    fs::remove(fs::path(out) / stale, ignored);
  }
  RunLog log(out + "/log.txt");
  if (!log.ok()) {
    std::fprintf(stderr, "error: cannot write %s/log.txt\n", out.c_str());
    return kOutputError;
  }
  const std::string resolved = io::resolvedSceneYaml(config);
  {
    std::ofstream(out + "/scene.resolved.yaml") << resolved;
  }
  io::Checkpoint restored;
  const bool restarting = !o.restart.empty();
  if (restarting) restored = io::readCheckpoint(o.restart);
  // A restart takes its particles from the checkpoint. When the scene is the checkpoint's
  // as far as the particle set goes, and the checkpoint says how many particles that scene
  // built, the water blocks are not built again.
  const std::string changed = restarting ? changedParticleSetKey(restored.scene_yaml, resolved) : std::string();
  const bool same_water = restarting && changed.empty() && restored.scene_fluid_count > 0;
  auto built = io::buildScene<D>(config, same_water ? io::WaterBuild::Skip : io::WaterBuild::Particles);
  const std::size_t scene_fluid_count =
      same_water ? static_cast<std::size_t>(restored.scene_fluid_count) : built.scene.fluid.size();
  fluid::FluidParticles<D> particles = built.scene.fluid;
  if (restarting) {
    particles = io::restoreParticles<D>(restored);
    // A run with 'outflow' may have removed spray: its checkpoint holds fewer particles,
    // and exactly as many fewer as its outflow tally says.
    const std::size_t removed = restored.outflow.empty() ? 0 : static_cast<std::size_t>(restored.outflow[0]);
    if (removed > 0 && !config.hasEffect("outflow"))
      throw io::SceneError(o.restart, "effects",
                           "the checkpoint's run removed " + std::to_string(removed) +
                               " particles through 'outflow'; list 'outflow' in the effects to continue it");
    if (particles.size() + removed != scene_fluid_count)
      throw io::SceneError(o.restart, "", "the checkpoint holds " + std::to_string(particles.size()) +
                                              " fluid particles" +
                                              (removed ? " (" + std::to_string(removed) + " removed by outflow)" : "") +
                                              ", the scene " + std::to_string(scene_fluid_count) +
                                              ": it belongs to another scene");
    if (!changed.empty() && !sameBoundary<D>(restored.scene_yaml, built))
      throw io::SceneError(o.restart, changed,
                           "differs from the scene the checkpoint was written for; a restart may change only what "
                           "does not alter the particle set (end time, output, method options, sensors)");
  }
  // With bodies the fluid runs inside a co-simulation (coupling/), without as is.
  std::unique_ptr<fluid::FluidSimulation<D>> plain;
#if MOORSPH_HAS_BODIES
  std::unique_ptr<coupling::CoSimulation<D>> co;
  if (!config.bodies.empty()) {
    if (restarting && restored.bodies.empty())
      throw io::SceneError(o.restart, "bodies", "the checkpoint holds no bodies' state: it belongs to a scene without bodies");
    co = makeCoSimulation<D>(config, built, particles, restarting ? restored.bodies : std::vector<double>{});
  }
  fluid::FluidSimulation<D>* coupled = co ? &co->updFluid() : nullptr;
#else
  if (!config.bodies.empty())
    throw io::SceneError(config.file, "bodies", "this moorsph was built without bodies (MOORSPH_WITH_BODIES=OFF)");
  fluid::FluidSimulation<D>* coupled = nullptr;
#endif
  if (!coupled) {
    plain = std::make_unique<fluid::FluidSimulation<D>>(built.scene.setup, particles, built.scene.boundary);
    io::addSceneEffects(*plain, config, built);
  }
  fluid::FluidSimulation<D>& sim = coupled ? *coupled : *plain;
  bool lists_restored = false;
  if (restarting) {
    sim.restoreClock(restored.time, static_cast<std::size_t>(restored.steps), restored.last_dt);
    io::restoreEffectTotals(restored, sim);
    lists_restored = io::restoreNeighbourLists(restored, sim);
  }

  log.line("moorsph run " + config.file + " -> " + fs::absolute(out).string());
  log.line("  " + std::to_string(D) + "D scene '" + config.name + "': " + std::to_string(sim.fluid().size()) +
           " fluid, " + std::to_string(sim.walls() ? sim.walls()->particles().size() : 0) + " boundary particles, " +
           std::to_string(omp_get_max_threads()) + " threads");
  log.line(format("  dx = %g m, h = %g m, c_s = %g m/s", config.dx, sim.setup().h(), config.sound_speed) +
           format(", dt <= %.3e s, end %g s", sim.cflDt(), config.end_time));
  std::string effects;
  for (const auto& e : sim.effectNames()) effects += " " + e;
  log.line("  effects:" + effects + "  (method " + config.method.name + ")");
  for (const auto& note : built.notes) log.line("  note: " + note);
#if MOORSPH_HAS_BODIES
  if (co)
    for (const auto& line : describeBodies(config, co->bodies())) log.line("  " + line);
#endif
  if (restarting) {
    log.line(format("  restarted from t = %.6g s, step %.0f", restored.time, static_cast<double>(restored.steps)) + " (" +
             o.restart + ")");
    if (same_water) log.line("  water blocks not built again: the scene's particle set is the checkpoint's");
    for (const std::string& note : changedLineModels(restored.scene_yaml, resolved)) log.line("  note: " + note);
    if (!lists_restored)
      log.line("  note: the checkpoint has no neighbour-list positions that fit this run (written before they were "
               "saved, or h, the skin or the number of boundary particles changed, e.g. a body surface sampled by "
               "another version): the lists are built afresh, so the run does not continue bit-identically");
  }

  io::SeriesFile series(out + "/series.h5");
  cases::RunRecorder<D> recorder(sim, series, config.output.interval);
  SceneSeries<D> sensors(sim, built, [&log](const std::string& text) { log.line("  " + text, true); });
  sensors.attach(recorder);
#if MOORSPH_HAS_BODIES
  if (co) attachBodySeries(recorder, *co, config);
#endif
  if (restarting) carryRestartHistory(log, o.restart, series, restored.time);

  std::unique_ptr<io::ParticleFile> particle_file;
  long long next_snapshot = restarting ? restored.next_snapshot : 0;
  if (config.output.particles_interval > 0.0) particle_file = std::make_unique<io::ParticleFile>(out);

  Progress progress(log, sim.time(), config.end_time, o.log_interval);
  auto last_checkpoint = Clock::now();
  auto writeCheckpointNow = [&](const std::string& path, const std::string& reason) {
    io::Checkpoint c = io::captureCheckpoint(sim);
    c.scene_yaml = resolved;
    c.scene_fluid_count = static_cast<std::int64_t>(scene_fluid_count);
    c.reason = reason;
    c.next_output = recorder.nextOutputIndex();
    c.next_snapshot = next_snapshot;
#if MOORSPH_HAS_BODIES
    if (co) c.bodies = packSnapshot(co->bodies().snapshot());
#endif
    io::writeCheckpoint(path, c);
    last_checkpoint = Clock::now();
    progress.clear();
    log.line(format("checkpoint at t = %.6g s (", sim.time()) + reason + "): " + path);
  };

  cases::RunControl control;
  control.next_output = restarting ? restored.next_output : 0;
  control.on_step = [&] {
    progress.update(sim.time(), sim.stepCount(), sim.lastDt());
    if (o.after_step) o.after_step(sim.stepCount());
  };
  control.on_output = [&] {
    if (!particle_file) return;
    const double every = config.output.particles_interval;
    if (sim.time() < static_cast<double>(next_snapshot) * every - 1e-12) return;
    particle_file->write(io::takeSnapshot(sim));
    while (static_cast<double>(next_snapshot) * every <= sim.time() + 1e-12) ++next_snapshot;
  };
  const double checkpoint_seconds = 60.0 * config.output.checkpoint_minutes;
  control.checkpoint_due = [&] {
    return checkpoint_seconds > 0.0 &&
           std::chrono::duration<double>(Clock::now() - last_checkpoint).count() >= checkpoint_seconds;
  };
  control.stop_requested = [] { return g_stop.load(); };
  bool interrupted_checkpoint = false;
  control.on_checkpoint = [&] {
    const bool stopping = g_stop.load();
    writeCheckpointNow(out + "/checkpoint.h5", stopping ? "interrupt" : "interval");
    interrupted_checkpoint = stopping;
  };

  g_stepping.store(true);
  const auto summary = recorder.runTo(config.end_time, {}, control);
  progress.clear();
  series.flush();
  if (const auto* outflow = sim.outflow(); outflow && outflow->tally().particles > 0) {
    const fluid::OutflowTally& t = outflow->tally();
    log.line(format("outflow: %.0f particles (%.4g kg, carrying %.4g J)", static_cast<double>(t.particles), t.mass, t.energy) +
             format(" left over the walls (above y = %g m), the first at t = %.6g s", outflow->wallTop(), t.first_time));
  }
  if (!summary.error.empty()) {
    log.line("error: the run failed: " + summary.error);
    std::ofstream(out + "/error.txt") << summary.error << "\n";
    writeCheckpointNow(out + "/failure.checkpoint.h5", "failure");
    log.line("output written so far is kept in " + fs::absolute(out).string() +
             "; failure.checkpoint.h5 holds the state at the failure (for inspection, not for restarting)");
    return kRunFailed;
  }
  const auto logPhases = [&] {
    std::vector<std::string> names = sim.phaseTimers().names();
    std::vector<double> seconds = sim.phaseTimers().seconds();
#if MOORSPH_HAS_BODIES
    if (co) {
      names.insert(names.end(), {"body dynamics", "fluid-body exchange"});
      seconds.insert(seconds.end(), {co->bodySeconds(), co->exchangeSeconds()});
    }
#endif
    log.line("  " + describePhases(names, seconds, summary.wall_seconds));
  };
  if (recorder.stoppedEarly()) {
    (void)interrupted_checkpoint;
    logPhases();
    log.line(format("interrupted at t = %.6g s; continue with --restart ", sim.time()) + out + "/checkpoint.h5");
    return kInterrupted;
  }
  writeCheckpointNow(out + "/checkpoint.h5", "end");
  const double steps = static_cast<double>(summary.steps - (restarting ? restored.steps : 0));
  log.line(format("simulated %.4g s in %.0f steps, %.1f s wall", summary.simulated_time, steps, summary.wall_seconds) +
           format(" (real-time factor %.3g, %.3g particle-steps/s)", (summary.simulated_time - (restarting ? restored.time : 0.0)) / summary.wall_seconds,
                  steps * static_cast<double>(summary.particles) / summary.wall_seconds));
  logPhases();
  log.line("output: " + fs::absolute(out).string() + " (series.h5" + (particle_file ? ", particles.xmf" : "") +
           ", scene.resolved.yaml, log.txt, checkpoint.h5)");
  return kSuccess;
}

}  // namespace

void requestStop() { g_stop.store(true); }

int runScene(const RunOptions& o) {
  std::vector<std::string> sets = o.sets;
  if (o.end > 0.0) sets.push_back(format("end_time=%.17g", o.end));
  io::SceneConfig config;
  try {
    config = io::loadSceneFile(o.scene, sets);
  } catch (const io::SceneError& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return kBadInput;
  }
  std::string out = o.out;
  if (out.empty()) {
    const fs::path restart_dir = fs::absolute(o.restart).parent_path();
    out = !o.restart.empty() ? restart_dir.string() + ".restart" : "moorsph-output/" + config.name;
  }
  std::error_code ec;
  if (!o.restart.empty() && fs::exists(out) &&
      fs::equivalent(fs::absolute(out), fs::absolute(o.restart).parent_path(), ec)) {
    std::fprintf(stderr, "error: --out %s is the directory of the checkpoint: the restart would overwrite the series of "
                 "the run that wrote it; choose another directory (the default is <checkpoint dir>.restart)\n",
                 out.c_str());
    return kBadArguments;
  }
  fs::create_directories(out, ec);
  if (ec) {
    std::fprintf(stderr, "error: cannot create %s: %s\n", out.c_str(), ec.message().c_str());
    return kOutputError;
  }
  if (o.threads > 0) omp_set_num_threads(o.threads);
  g_stop.store(false);
  g_stepping.store(false);
  auto previous_int = std::signal(SIGINT, onSignal);
  auto previous_term = std::signal(SIGTERM, onSignal);
  int code = kSuccess;
  try {
    code = config.dim == 2 ? runDim<2>(config, o, out) : runDim<3>(config, o, out);
  } catch (const io::SceneError& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    code = kBadInput;
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "error: %s: %s\n", o.scene.c_str(), e.what());
    code = kBadInput;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    code = !o.restart.empty() && std::string(e.what()).find(o.restart) != std::string::npos ? kBadInput : kOutputError;
  }
  std::signal(SIGINT, previous_int);
  std::signal(SIGTERM, previous_term);
  return code;
}

int exportRun(const std::string& directory) {
  try {
    const auto files = io::exportSeriesCsv(directory);
    std::printf("wrote %zu files to %s/csv\n", files.size(), directory.c_str());
    return kSuccess;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return kBadInput;
  }
}

}  // namespace moorsph::app
