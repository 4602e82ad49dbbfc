// Runner for the 2D wave tanks of wave_tanks.hpp (issue 6): writes the gauge series
// as CSV and prints the wave height and mean level at each gauge.
//
//   moorsph_wave_tank periodic|flume [key=value ...] --out FILE.csv
//
// Keys (SI units): dx, mu, cfl, h_factor, b_off, boundary_strength, boundary_h_factor, dd_delta, dd_form, no_viscosity (1: drop the term), sound_speed, xsph_form (reference|monaghan), xsph_eps,
// density_diffusion (0|1), shifting (0|1: particle_shifting), shifting_coefficient,
// shifting_cap, shifting_r, predictor_fraction, integrator (predictor_corrector|symplectic), period, depth, amplitude (periodic) or
// height (flume), wavelengths, theory, kappa, maker_start, maker_length, bottom_gap,
// ramp_up, forcing_end, gain, floor (walls|mirror), initial_wave (periodic: 0|1), length, damping_start, damping_k_max, gauges (comma
// list of x), end, interval, window (periods averaged at the end), threads;
// active correction: control_gauges (comma list of x), control_start, control_periods,
// control_beta, control_stop.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <omp.h>
#include "wave_tanks.hpp"

using namespace moorsph;

namespace {

std::vector<double> numberList(const std::string& s) {
  std::vector<double> out;
  std::stringstream in(s);
  std::string item;
  while (std::getline(in, item, ',')) out.push_back(std::stod(item));
  return out;
}

struct Args {
  std::map<std::string, std::string> kv;
  std::map<std::string, bool> used;
  double get(const std::string& k, double fallback) {
    used[k] = true;
    return kv.count(k) ? std::stod(kv[k]) : fallback;
  }
  std::string str(const std::string& k, const std::string& fallback) {
    used[k] = true;
    return kv.count(k) ? kv[k] : fallback;
  }
  void rejectUnknown() const {
    for (const auto& [k, v] : kv)
      if (!used.count(k)) throw std::invalid_argument("unknown key '" + k + "'");
  }
};

cases::WaveTankControl controlOf(Args& a) {
  cases::WaveTankControl c;
  if (a.kv.count("control_gauges")) c.gauges = numberList(a.str("control_gauges", ""));
  c.start_time = a.get("control_start", c.start_time);
  c.update_periods = static_cast<int>(a.get("control_periods", c.update_periods));
  c.beta = a.get("control_beta", c.beta);
  c.stop_time = a.get("control_stop", c.stop_time);
  return c;
}

cases::WaveTankFluid fluidOf(Args& a) {
  cases::WaveTankFluid f;
  f.dx = a.get("dx", f.dx);
  f.mu = a.get("mu", f.mu);
  f.sound_speed = a.get("sound_speed", 0.0);
  if (!fluid::optionFromName(fluid::kXsphFormNames, a.str("xsph_form", fluid::optionName(fluid::kXsphFormNames, f.method.xsph_form)), f.method.xsph_form))
    throw std::invalid_argument("xsph_form: " + fluid::optionNames(fluid::kXsphFormNames));
  f.method.xsph_eps = a.get("xsph_eps", f.method.xsph_eps);
  f.method.predictor_fraction = a.get("predictor_fraction", f.method.predictor_fraction);
  if (!fluid::optionFromName(fluid::kIntegratorNames, a.str("integrator", fluid::optionName(fluid::kIntegratorNames, f.method.integrator)), f.method.integrator))
    throw std::invalid_argument("integrator: " + fluid::optionNames(fluid::kIntegratorNames));
  f.method.cfl = a.get("cfl", f.method.cfl);
  f.method.h_factor = a.get("h_factor", f.method.h_factor);
  f.method.boundary_offset = a.get("b_off", f.method.boundary_offset);
  f.method.boundary_strength = a.get("boundary_strength", f.method.boundary_strength);
  f.method.boundary_h_factor = a.get("boundary_h_factor", f.method.boundary_h_factor);
  f.method.density_diffusion_delta = a.get("dd_delta", f.method.density_diffusion_delta);
  const std::string dd_form = a.str("dd_form", fluid::optionName(fluid::kDensityDiffusionFormNames, f.method.density_diffusion_form));
  if (!fluid::optionFromName(fluid::kDensityDiffusionFormNames, dd_form, f.method.density_diffusion_form)) throw std::invalid_argument("dd_form: " + fluid::optionNames(fluid::kDensityDiffusionFormNames));
  if (a.get("density_diffusion", 0.0) != 0.0) f.effects.push_back("density_diffusion");
  if (a.get("shifting", 0.0) != 0.0) f.effects.push_back("particle_shifting");
  f.method.shifting.coefficient = a.get("shifting_coefficient", f.method.shifting.coefficient);
  f.method.shifting.cap = a.get("shifting_cap", f.method.shifting.cap);
  f.method.shifting.anti_clustering = a.get("shifting_r", f.method.shifting.anti_clustering);
  if (a.get("no_viscosity", 0.0) != 0.0) f.effects.erase(f.effects.begin() + 1);
  if (f.method.xsph_eps == 0.0) f.effects.erase(std::find(f.effects.begin(), f.effects.end(), "xsph"));
  if (f.method.xsph_form != fluid::XsphForm::Reference || f.method.predictor_fraction != 1.0 ||
      f.method.integrator != fluid::Integrator::PredictorCorrector ||
      f.method.cfl != 0.5 || f.method.h_factor != 1.2 ||
      f.effects.size() != 5)
    f.method.name = "reference+options";
  return f;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    if (argc < 2) throw std::invalid_argument("usage: moorsph_wave_tank periodic|flume [key=value ...] --out FILE.csv");
    const std::string kind = argv[1];
    Args a;
    std::string out;
    for (int i = 2; i < argc; ++i) {
      const std::string s = argv[i];
      if (s == "--out" && i + 1 < argc) { out = argv[++i]; continue; }
      const auto eq = s.find('=');
      if (eq == std::string::npos) throw std::invalid_argument("expected key=value, got '" + s + "'");
      a.kv[s.substr(0, eq)] = s.substr(eq + 1);
    }
    const int threads = static_cast<int>(a.get("threads", 1));
    omp_set_num_threads(threads);
    cases::WaveTank tank;
    if (kind == "periodic") {
      cases::PeriodicWaveTankSpec s;
      s.fluid = fluidOf(a);
      s.period = a.get("period", s.period);
      s.depth = a.get("depth", s.depth);
      s.amplitude = a.get("amplitude", s.amplitude);
      s.wavelengths = static_cast<int>(a.get("wavelengths", s.wavelengths));
      s.theory = a.str("theory", s.theory);
      s.kappa = a.get("kappa", s.kappa);
      s.maker_start = a.get("maker_start", s.maker_start);
      s.maker_length = a.get("maker_length", s.maker_length);
      s.bottom_gap = a.get("bottom_gap", s.bottom_gap);
      s.ramp_up = a.get("ramp_up", s.ramp_up);
      s.forcing_end = a.get("forcing_end", s.forcing_end);
      s.gain = a.get("gain", s.gain);
      s.floor = a.str("floor", s.floor);
      s.initial_wave = a.get("initial_wave", 0.0) != 0.0;
      if (a.kv.count("gauges")) s.gauges = numberList(a.str("gauges", ""));
      s.control = controlOf(a);
      tank = cases::buildPeriodicWaveTank(s);
    } else if (kind == "flume") {
      cases::PistonFlumeSpec s;
      s.fluid = fluidOf(a);
      s.period = a.get("period", s.period);
      s.depth = a.get("depth", s.depth);
      s.height = a.get("height", s.height);
      s.length = a.get("length", s.length);
      s.ramp_up = a.get("ramp_up", s.ramp_up);
      s.gain = a.get("gain", s.gain);
      s.damping_start = a.get("damping_start", s.damping_start);
      s.damping_k_max = a.get("damping_k_max", s.damping_k_max);
      s.floor = a.str("floor", s.floor);
      s.gauges = numberList(a.str("gauges", "0.5,1.0,1.5"));
      s.control = controlOf(a);
      tank = cases::buildPistonFlume(s);
    } else {
      throw std::invalid_argument("first argument: periodic or flume");
    }
    const double end = a.get("end", 10.0 * tank.period);
    const double interval = a.get("interval", tank.period / 50.0);
    const double window = a.get("window", 3.0);
    a.rejectUnknown();

    const auto& f = tank.sim->fluid();
    std::printf("%s: %zu fluid particles, dx = %.5g m, depth = %.5g m, T = %.5g s, lambda = %.5g m, a = %.5g m "
                "(%.2f particles per height), dt = %.3g s, c_s = %.3g m/s\n",
                kind.c_str(), f.size(), tank.sim->setup().dx, tank.depth, tank.period, tank.wavelength, tank.amplitude,
                2.0 * tank.amplitude / tank.sim->setup().dx, tank.sim->cflDt(), tank.sim->setup().sound_speed);
    // The CSV is written as the run goes (a long run can be read before it ends); its
    // first line describes the tank, the last one the cost.
    std::ofstream csv, energy;
    if (!out.empty()) {
      csv.open(out);
      energy.open(out + ".energy");
      energy << "t,kinetic_J_per_m,potential_J_per_m,elastic_J_per_m,momentum_x_kg_per_s,max_speed_m_per_s,x_of_max_speed_m,y_of_max_speed_m\n";
      energy.precision(10);
      csv << "# " << kind << " T=" << tank.period << " depth=" << tank.depth << " lambda=" << tank.wavelength
          << " a=" << tank.amplitude << " dx=" << tank.sim->setup().dx << " particles=" << f.size()
          << " method=" << tank.sim->setup().method.name << "\n";
      csv << "t";
      for (const auto& g : tank.gauges) csv << ",x=" << g.spec().position[0] - tank.x_origin;
      csv << "\n";
      csv.precision(9);
    }
    int updates_seen = 0;
    const auto write_row = [&](const cases::GaugeRecord& r) {
      if (tank.controller && tank.controller->updates() != updates_seen) {
        updates_seen = tank.controller->updates();
        std::printf("control update %d at t = %.3f s: window height %.5g m -> gain %.4f\n", updates_seen, r.t.back(),
                    tank.controller->lastHeight(), tank.controller->gainAt(r.t.back() + tank.period));
        if (csv.is_open())
          csv << "# control t=" << r.t.back() << " height=" << tank.controller->lastHeight()
              << " gain=" << tank.controller->gainAt(r.t.back() + tank.period) << "\n";
      }
      if (!csv.is_open()) return;
      // Kinetic energy per metre of width: a progressive linear wave holds rho g H^2 L / 16,
      // so sqrt(KE) falls like the height if the height's loss is a real energy loss.
      const auto e = tank.sim->calcEnergy();
      // Horizontal momentum per metre (nothing changes it in a periodic tank once the
      // forcing stops) and the fastest particle (where a splash or a blow-up starts).
      double px = 0.0, v2max = 0.0;
      std::size_t fastest = 0;
      for (std::size_t i = 0; i < f.size(); ++i) {
        px += f.m[i] * f.v[i][0];
        if (f.v[i].squaredNorm() > v2max) { v2max = f.v[i].squaredNorm(); fastest = i; }
      }
      energy << r.t.back() << "," << e.kinetic << "," << e.potential << "," << e.elastic << "," << px << ","
             << std::sqrt(v2max) << "," << f.r[fastest][0] << "," << f.r[fastest][1] << "\n";
      csv << r.t.back();
      for (const auto& e : r.eta) csv << "," << e.back();
      csv << "\n";
      if (r.t.size() % 50 == 0) csv.flush();
    };
    const auto start = std::chrono::steady_clock::now();
    const auto rec = cases::runAndRecord(tank, end, interval, write_row);
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("steps %zu, wall %.1f s (%.3g particle-steps/s, %d threads)\n", tank.sim->stepCount(), wall,
                static_cast<double>(f.size()) * tank.sim->stepCount() / wall, threads);
    if (csv.is_open()) csv << "# end steps=" << tank.sim->stepCount() << " wall_s=" << wall << " threads=" << threads << "\n";
    const double t1 = rec.t.back(), t0 = t1 - window * tank.period;
    if (tank.controller)
      std::printf("controller: %d updates, final gain %.4f, last window height %.5g m (target %.5g m)\n",
                  tank.controller->updates(), tank.controller->gainAt(rec.t.back()), tank.controller->lastHeight(),
                  2.0 * tank.amplitude);
    for (std::size_t g = 0; g < tank.gauges.size(); ++g) {
      const double H = cases::meanWaveHeight(rec.t, rec.eta[g], tank.period, t0, t1);
      std::printf("gauge x = %.4g m: H = %.5g m (%.3f of requested), mean level %+.3g dx\n",
                  tank.gauges[g].spec().position[0] - tank.x_origin, H, H / (2.0 * tank.amplitude),
                  cases::meanLevel(rec.t, rec.eta[g], t0, t1) / tank.sim->setup().dx);
    }
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "moorsph_wave_tank: %s\n", e.what());
    return 1;
  }
}
