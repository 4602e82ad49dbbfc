// moorsph_spheric_test2: runs SPHERIC Test 2 (3-D dam break with a box obstacle,
// Kleefsman et al. 2005) and records series.h5 with
//   /gauges    H1..H4 free-surface heights [m] (data-file column meaning, see spheric_test2.hpp)
//   /pressure  P1..P4 from the box's boundary reactions and P1i..P4i SPH-interpolated [Pa]
//   /energy    the fluid's energy terms, dt, steps and wall time (RunRecorder)
// and run.txt with particles, steps, wall time and threads.
//
//   moorsph_spheric_test2 [--dx M] [--end S] [--out DIR] [--output-interval S]
//                         [--density-diffusion] [--xsph-monaghan] [--threads N]
#include <omp.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <moorsph/cases/run_recorder.hpp>

#include "spheric_test2.hpp"

namespace {

struct Options {
  double dx = 0.04;
  double end = 6.0;
  double output_interval = 0.002;
  std::string out = "spheric_test2_out";
  bool density_diffusion = false;
  bool xsph_monaghan = false;
  int threads = 0;  // 0: OpenMP's default
};

[[noreturn]] void usage(const char* program, int code) {
  std::fprintf(code ? stderr : stdout,
               "usage: %s [--dx M (0.04)] [--end S (6.0)] [--out DIR] [--output-interval S (0.002)]\n"
               "          [--density-diffusion] [--xsph-monaghan] [--threads N]\n",
               program);
  std::exit(code);
}

Options parse(int argc, char** argv) {
  Options o;
  for (int a = 1; a < argc; ++a) {
    const std::string arg = argv[a];
    const auto value = [&]() -> std::string {
      if (a + 1 >= argc) {
        std::fprintf(stderr, "%s needs a value\n", arg.c_str());
        usage(argv[0], 2);
      }
      return argv[++a];
    };
    try {
      if (arg == "--dx") o.dx = std::stod(value());
      else if (arg == "--end") o.end = std::stod(value());
      else if (arg == "--out") o.out = value();
      else if (arg == "--output-interval") o.output_interval = std::stod(value());
      else if (arg == "--density-diffusion") o.density_diffusion = true;
      else if (arg == "--xsph-monaghan") o.xsph_monaghan = true;
      else if (arg == "--threads") o.threads = std::stoi(value());
      else if (arg == "-h" || arg == "--help") usage(argv[0], 0);
      else {
        std::fprintf(stderr, "unknown option %s\n", arg.c_str());
        usage(argv[0], 2);
      }
    } catch (const std::logic_error&) {
      std::fprintf(stderr, "bad value for %s\n", arg.c_str());
      usage(argv[0], 2);
    }
  }
  if (!(o.dx > 0.0) || !(o.end > 0.0) || !(o.output_interval > 0.0) || o.threads < 0) usage(argv[0], 2);
  return o;
}

}  // namespace

int main(int argc, char** argv) {
  namespace st2 = moorsph::cases::spheric_test2;
  using moorsph::fluid::FluidSimulation;
  const Options opt = parse(argc, argv);
  if (opt.threads > 0) omp_set_num_threads(opt.threads);
  const int threads = omp_get_max_threads();

  try {
    st2::Spec spec;
    spec.dx = opt.dx;
    spec.density_diffusion = opt.density_diffusion;
    spec.xsph_monaghan = opt.xsph_monaghan;
    st2::Built built = st2::build(spec);
    FluidSimulation<3> sim(built.scene.setup, built.scene.fluid, built.scene.boundary);
    const auto gauges = st2::makeGauges(0.8);
    const auto level_gauges = st2::makeGauges(0.5);
    const auto probes = st2::makeProbes(sim, built);

    std::filesystem::create_directories(opt.out);
    const std::string path = (std::filesystem::path(opt.out) / "series.h5").string();
    moorsph::io::SeriesFile file(path);
    moorsph::cases::RunRecorder<3> recorder(sim, file, opt.output_interval);

    std::vector<moorsph::io::SeriesColumn> gauge_columns, pressure_columns;
    for (const auto& g : st2::kGauges) gauge_columns.push_back({g.name, "m"});
    for (const auto& p : st2::kPressureSensors) pressure_columns.push_back({p.name, "Pa"});
    for (const auto& p : st2::kPressureSensors) pressure_columns.push_back({std::string(p.name) + "i", "Pa"});
    recorder.addSeries(
        "gauges", gauge_columns,
        [&gauges](const FluidSimulation<3>& s) {
          std::vector<double> h;
          for (const auto& g : gauges) h.push_back(g.read(s));
          return h;
        },
        "free-surface height above the floor at x = 1.488, 0.992, 0.496, 2.638 m (z = 0.5 m), "
        "the data file's H1..H4 columns; particle-density threshold xi_t = 0.8 (METHOD.md section 3)");
    recorder.addSeries(
        "gauges_half", gauge_columns,
        [&level_gauges](const FluidSimulation<3>& s) {
          std::vector<double> h;
          for (const auto& g : level_gauges) h.push_back(g.read(s));
          return h;
        },
        "as /gauges with xi_t = 0.5: the level where the particles' volumes end (xi_t = 0.8 reads about "
        "half a spacing lower, at the top particle row)");
    recorder.addSeries(
        "pressure", pressure_columns,
        [&probes](const FluidSimulation<3>& s) {
          std::vector<double> p;
          for (const auto& probe : probes) p.push_back(probe.readReaction(s));
          for (const auto& probe : probes) p.push_back(probe.readInterpolated(s));
          return p;
        },
        "P1..P4 on the box face x = 0.8245 m at z = 0.471 m, heights 0.021..0.141 m: from the boundary "
        "reactions (Pn) and SPH-interpolated 1.5 dx in front of the face (Pni)");

    // run.txt: what compare.py needs, written now (status running, so a run stopped by
    // hand can still be compared using the /energy series) and again at the end.
    const auto writeRunInfo = [&](const moorsph::cases::RunSummary& summary, const char* status) {
      std::ofstream txt(std::filesystem::path(opt.out) / "run.txt");
      txt << "status " << status << "\ndx " << sim.setup().dx << "\ndx_requested " << opt.dx << "\nend " << opt.end
          << "\nsimulated " << summary.simulated_time << "\nparticles " << sim.fluid().size()
          << "\nboundary_particles " << sim.walls()->particles().size() << "\nsteps " << summary.steps
          << "\nwall_seconds " << summary.wall_seconds << "\nthreads " << threads << "\ndensity_diffusion "
          << (opt.density_diffusion ? 1 : 0) << "\nxsph_monaghan " << (opt.xsph_monaghan ? 1 : 0) << "\nmethod "
          << sim.setup().method.name << "\nsound_speed " << sim.setup().sound_speed << "\nerror "
          << (summary.error.empty() ? "none" : summary.error) << "\n";
    };
    writeRunInfo({}, "running");

    std::printf("SPHERIC test 2: dx = %.5g m, c_s = %.2f m/s, %zu fluid + %zu boundary particles, %d threads, "
                "effects:",
                sim.setup().dx, sim.setup().sound_speed, sim.fluid().size(), sim.walls()->particles().size(), threads);
    for (const auto& e : sim.effectNames()) std::printf(" %s", e.c_str());
    std::printf("\n");
    const auto summary = recorder.runTo(opt.end, [](const std::string& line) {
      static int count = 0;
      if (++count % 50 == 0) std::printf("%s\n", line.c_str());
      std::fflush(stdout);
    });

    writeRunInfo(summary, "finished");
    std::printf("particles %zu  steps %zu  wall time %.1f s  threads %d  simulated %.3f s%s\n", summary.particles,
                summary.steps, summary.wall_seconds, threads, summary.simulated_time,
                summary.error.empty() ? "" : "  (stopped early)");
    std::printf("output: %s\n", path.c_str());
    return summary.error.empty() ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
}
