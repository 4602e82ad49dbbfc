// moorsph_breather_signal: writes the piston displacement table (CSV t [s], X [m]) that makes a
// Peregrine breather (METHOD.md section 4c) focused a given distance from the piston at a given
// time, for a scene's `piston: {signal: {type: table, file: ...}}` (the same motion as a scene's
// `signal: {type: breather}`: both come from fluid::waves::breatherMakerSignal). With
// --theory-at it also writes the breather's theoretical elevation at those distances from the
// piston (one CSV time,value each, beside --out), the reference for a run's gauges.
//
//   moorsph_breather_signal --order 1 --a0 4.5 --k0 0.013333 --focus-distance 200
//        --focus-time 300 --depth 132 --still 30 --ramp 60 --duration 420 [--dt 0.1]
//        --out signal.csv [--theory-at 0.5,2,2.86 --theory-level 0.35]
//
// The piston stays at X = 0 for the first `still` seconds (the water and the moored body settle,
// and a CI test can stop there), then the target elevation eta(-x_f, t - t_f) at the piston is
// ramped up over `ramp` seconds (half cosine; the breather's background sea has its full
// amplitude a0 everywhere, so an unramped start would jerk the piston) and converted to X(t) by
// the linear piston transfer function, frequency by frequency
// (fluid::waves::breatherPistonSignal). Components below half the carrier frequency are removed
// (a piston cannot make a mean level; see piston_transfer.hpp, LOW-FREQUENCY LIMIT). The ramp
// front travels at the group speed, so it must have left the tank before the focus time.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <stdexcept>
#include <string>

#include <moorsph/fluid/waves/dispersion.hpp>
#include <moorsph/fluid/waves/peregrine_breather.hpp>
#include <moorsph/fluid/waves/piston_signal.hpp>

using namespace moorsph::fluid::waves;

namespace {

std::map<std::string, std::string> parseArgs(int argc, char** argv) {
  std::map<std::string, std::string> a;
  for (int i = 1; i < argc; ++i) {
    const std::string key = argv[i];
    if (key.rfind("--", 0) != 0 || i + 1 >= argc) throw std::invalid_argument("expected --key value, got '" + key + "'");
    a[key.substr(2)] = argv[++i];
  }
  return a;
}

double number(const std::map<std::string, std::string>& a, const std::string& key, double fallback = NAN) {
  const auto it = a.find(key);
  if (it == a.end()) {
    if (std::isnan(fallback)) throw std::invalid_argument("missing --" + key);
    return fallback;
  }
  return std::stod(it->second);
}

/// The breather's own surface, level + eta(x - x_f, t - t_f), at each distance x [m] from
/// the piston in `list` (comma separated), 0 <= t <= duration, one CSV "time,value" each,
/// named after `out` with "_theory_x<x>" before the extension: the theory a run's gauges
/// (which read the surface's height) are measured against (moorsph study --reference FILE).
void writeTheory(const PeregrineBreather& breather, double xf, double tf, double duration, double dt, double level,
                 const std::string& list, const std::string& out) {
  const std::string stem = out.size() > 4 && out.substr(out.size() - 4) == ".csv" ? out.substr(0, out.size() - 4) : out;
  std::size_t from = 0;
  while (from <= list.size()) {
    const std::size_t comma = std::min(list.find(',', from), list.size());
    const std::string item = list.substr(from, comma - from);
    from = comma + 1;
    if (item.empty()) continue;
    const double x = std::stod(item);
    const std::string name = stem + "_theory_x" + item + ".csv";
    std::ofstream f(name);
    if (!f) throw std::runtime_error("cannot write " + name);
    f << "time,value\n";
    char line[64];
    const long n = std::lround(duration / dt);
    for (long i = 0; i <= n; ++i) {
      const double t = i * dt;
      std::snprintf(line, sizeof line, "%.4f,%.7e\n", t, level + breather.elevation(x - xf, t - tf));
      f << line;
    }
    std::printf("wrote %s (theory at %g m from the piston)\n", name.c_str(), x);
  }
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const auto a = parseArgs(argc, argv);
    const int order = static_cast<int>(number(a, "order", 1));
    const double a0 = number(a, "a0"), k0 = number(a, "k0"), xf = number(a, "focus-distance");
    const double tf = number(a, "focus-time"), depth = number(a, "depth"), still = number(a, "still", 0.0);
    const double ramp = number(a, "ramp"), duration = number(a, "duration"), dt = number(a, "dt", 0.1);
    const auto out = a.count("out") ? a.at("out") : std::string("signal.csv");
    BreatherMakerSpec spec;
    spec.order = order;
    spec.a0 = a0;
    spec.k0 = k0;
    spec.focusDistance = xf;
    spec.focusTime = tf;
    spec.depth = depth;
    spec.still = still;
    spec.ramp = ramp;
    spec.duration = duration;
    spec.dt = dt;
    const UniformSeries x = breatherMakerSignal(spec);
    const PeregrineBreather breather(order, a0, k0);

    std::ofstream f(out);
    if (!f) throw std::runtime_error("cannot write " + out);
    f << "t [s],X [m]\n";
    char line[64];
    double xmax = 0.0;
    for (std::size_t i = 0; i < x.values.size(); ++i) {
      std::snprintf(line, sizeof line, "%.3f,%.6f\n", x.time(i), x.values[i]);
      f << line;
      xmax = std::max(xmax, std::abs(x.values[i]));
    }
    const double cg = 0.5 * breather.carrierAngularFrequency() / k0;  // deep-water group speed
    std::printf("breather order %d: a0 %.3f m, k0 %.6f 1/m (wavelength %.1f m), a0 k0 %.4f, omega0 %.4f rad/s (period %.2f s)\n",
                order, a0, k0, 2.0 * M_PI / k0, a0 * k0, breather.carrierAngularFrequency(),
                2.0 * M_PI / breather.carrierAngularFrequency());
    std::printf("depth %.2f m: k0 d = %.3f (deep-water NLS wants >= 1.75), H/S at the carrier %.4f\n", depth, k0 * depth,
                pistonHeightToStroke(waveNumberFromAngularFrequency(breather.carrierAngularFrequency(), depth), depth));
    std::printf("focus %.1f m from the piston at t = %.1f s (peak crest about %.1f m); still until %.1f s, ramp %.1f s\n", xf,
                tf, breather.peakAmplification() * a0, still, ramp);
    std::printf("largest |X| %.3f m; ramp front at the group speed %.2f m/s is %.0f m from the piston at the focus time\n",
                xmax, cg, cg * (tf - still));
    std::printf("wrote %s (%zu rows)\n", out.c_str(), x.values.size());
    if (a.count("theory-at"))
      writeTheory(breather, xf, tf, duration, dt, number(a, "theory-level", 0.0), a.at("theory-at"), out);
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "moorsph_breather_signal: " << e.what() << "\n";
    return 1;
  }
}
