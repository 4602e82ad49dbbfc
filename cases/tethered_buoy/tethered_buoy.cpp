// Tethered laboratory buoy, METHOD.md section 6.2 a/b: the buoy is pulled fully under
// (vertical, centroid 0.12 m below rest) or 0.508 m along the surface (horizontal),
// held while the fluid settles, released, and left to oscillate about its rest pose.
// Writes the time series (heave, surge, pitch, tether tension, fluid force) as CSV and
// prints one summary: the extrema of the released motion, the period between peaks,
// the decay per cycle, the tension range, particles, steps and wall time.
// The builder is cases/include/moorsph/cases/tethered_buoy.hpp; run_study.sh sweeps
// resolutions and tank sizes.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>
#include <moorsph/cases/command_line.hpp>
#include <moorsph/cases/tethered_buoy.hpp>

namespace {

using namespace moorsph;

struct Options {
  cases::TetheredBuoyTank tank;
  double end = 5.0;  ///< simulated time after release [s]
  std::string csv;
};

[[noreturn]] void usage(const std::string& why) {
  std::fprintf(stderr,
               "%s\nusage: moorsph_tethered_buoy [--release vertical|horizontal|rest] [--dx M] [--length M] "
               "[--width M] [--depth M] [--settle S] [--end S] [--mu PA_S] [--model WORD] [--sound-speed-factor F] "
               "[--outflow 0|1] [--csv FILE]\n",
               why.c_str());
  std::exit(2);
}

Options parse(int argc, char** argv) {
  Options o;
  for (int a = 1; a < argc; a += 2) {
    const std::string key = argv[a];
    if (a + 1 >= argc) usage("missing value after " + key);
    const std::string value = argv[a + 1];
    const bool text_value = key == "--release" || key == "--model" || key == "--csv";
    const double v = text_value ? 0.0 : cases::numberArgument(value, key, "moorsph_tethered_buoy");
    if (key == "--release") {
      if (value == "vertical") o.tank.release = cases::BuoyRelease::Vertical;
      else if (value == "horizontal") o.tank.release = cases::BuoyRelease::Horizontal;
      else if (value == "rest") o.tank.release = cases::BuoyRelease::Rest;
      else usage("--release expects vertical, horizontal or rest, got " + value);
    } else if (key == "--dx") o.tank.dx = v;
    else if (key == "--length") o.tank.length = v;
    else if (key == "--width") o.tank.width = v;
    else if (key == "--depth") o.tank.depth = v;
    else if (key == "--settle") o.tank.release_time = v;
    else if (key == "--end") o.end = v;
    else if (key == "--mu") o.tank.mu = v;
    else if (key == "--model") o.tank.mooring_model = value;
    else if (key == "--sound-speed-factor") o.tank.sound_speed_factor = v;  // c_s = F sqrt(2 g depth)
    else if (key == "--outflow") o.tank.outflow = v != 0.0;
    else if (key == "--csv") o.csv = value;
    else usage("unknown option " + key);
  }
  return o;
}

/// Turning points of a sampled signal; a turn counts once the signal has come back
/// by more than `hysteresis` from its running extremum (ignores particle noise).
struct Extremum {
  double t, value;
};
std::vector<Extremum> turningPoints(const std::vector<double>& t, const std::vector<double>& s, double hysteresis) {
  std::vector<Extremum> out;
  if (s.empty()) return out;
  int direction = 0;  // +1 rising, -1 falling
  Extremum best{t[0], s[0]};
  for (std::size_t i = 1; i < s.size(); ++i) {
    if (direction >= 0 && s[i] > best.value) best = {t[i], s[i]};
    if (direction <= 0 && s[i] < best.value) best = {t[i], s[i]};
    if (direction == 0) {
      if (std::abs(s[i] - s[0]) > hysteresis) direction = s[i] > s[0] ? 1 : -1, best = {t[i], s[i]};
      continue;
    }
    if (direction * (best.value - s[i]) > hysteresis) {
      out.push_back(best);
      direction = -direction;
      best = {t[i], s[i]};
    }
  }
  return out;
}

double angleAboutZ(const Eigen::Quaterniond& q) {
  const Eigen::Matrix3d r = q.toRotationMatrix();
  return std::atan2(r(1, 0), r(0, 0));
}

}  // namespace

int main(int argc, char** argv) {
  const Options o = parse(argc, argv);
  auto scene = cases::buildTetheredBuoy(o.tank);
  auto& co = *scene.co;
  const double release = o.tank.release_time, sample = 0.005;
  std::FILE* csv = o.csv.empty() ? nullptr : std::fopen(o.csv.c_str(), "w");
  if (!o.csv.empty() && !csv) usage("cannot write " + o.csv);
  if (csv)
    std::fprintf(csv, "t_s,surge_m,heave_m,sway_m,pitch_deg,tension_N,fluid_fx_N,fluid_fy_N\n");
  std::vector<double> ts, heave, surge;
  double tension_min = 1e300, tension_max = -1e300;
  const auto start = std::chrono::steady_clock::now();
  std::string failure;
  try {
    for (double next = 0.0; co.time() < release + o.end;) {
      co.step();
      if (co.time() < next) continue;
      next += sample;
      const auto k = co.bodies().kinematics(0);
      const double t = co.time() - release, tension = co.bodies().lineDiagnostics(0).fairleadTension;
      const auto f = co.coupling().appliedWrench(0).force;
      if (csv)
        std::fprintf(csv, "%.5f,%.6f,%.6f,%.6f,%.4f,%.5f,%.5f,%.5f\n", t, k.position[0] - scene.rest[0],
                     k.position[1] - scene.rest[1], k.position[2] - scene.rest[2],
                     angleAboutZ(k.orientation) * 180.0 / std::acos(-1.0), tension, f[0], f[1]);
      if (t < 0.0) continue;
      ts.push_back(t);
      heave.push_back(k.position[1] - scene.rest[1]);
      surge.push_back(k.position[0] - scene.rest[0]);
      tension_min = std::min(tension_min, tension);
      tension_max = std::max(tension_max, tension);
    }
  } catch (const std::exception& e) {
    failure = e.what();
  }
  if (csv) std::fclose(csv);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  const bool horizontal = o.tank.release == cases::BuoyRelease::Horizontal;
  const auto& signal = horizontal ? surge : heave;
  const double pull = horizontal ? o.tank.horizontal_pull : o.tank.vertical_pull;
  const auto turns = turningPoints(ts, signal, 0.02 * pull);
  std::printf("# release=%s dx=%.4f (D/%.0f) tank=%.2fx%.2f depth=%.2f c_s=%.3g mu=%.4g model=%s\n",
              horizontal ? "horizontal" : (o.tank.release == cases::BuoyRelease::Vertical ? "vertical" : "rest"),
              o.tank.dx, 2 * o.tank.buoy.radius / o.tank.dx, o.tank.length, o.tank.width, o.tank.depth,
              co.fluid().setup().sound_speed, o.tank.mu,
              o.tank.mooring_model.c_str());
  std::printf("# turning points (t_s, %s_m):", horizontal ? "surge" : "heave");
  for (const auto& e : turns) std::printf(" (%.3f, %+.4f)", e.t, e.value);
  std::printf("\n");
  // Period: mean spacing of successive maxima (and minima); decay: ratio of successive
  // peak-to-trough heights, cycle n+1 over cycle n.
  double period_sum = 0.0, decay_sum = 0.0;
  int periods = 0, decays = 0;
  for (std::size_t i = 2; i < turns.size(); ++i) {
    period_sum += turns[i].t - turns[i - 2].t;
    ++periods;
    if (i < 3) continue;
    decay_sum += std::abs(turns[i].value - turns[i - 1].value) / std::abs(turns[i - 2].value - turns[i - 3].value);
    ++decays;
  }
  if (const auto* out = co.fluid().outflow(); out && out->tally().particles > 0)
    std::printf("# outflow: %zu particles (%.4g kg) thrown over the walls, the first at t = %.3f s after release\n",
                out->tally().particles, out->tally().mass, out->tally().first_time - release);
  std::printf("period_s=%.4f decay_per_cycle=%.4f first_extremum=%+.4f tension_N=[%.3f, %.3f] particles=%zu "
              "steps=%zu wall_s=%.1f fluid_s=%.1f bodies_s=%.1f exchange_s=%.1f%s%s\n",
              periods ? period_sum / periods : NAN, decays ? decay_sum / decays : NAN,
              turns.empty() ? NAN : turns.front().value, tension_min, tension_max, scene.particles,
              co.fluid().stepCount(), wall, co.fluidSeconds(), co.bodySeconds(), co.exchangeSeconds(),
              failure.empty() ? "" : " FAILED: ", failure.c_str());
  return failure.empty() ? 0 : 3;
}
