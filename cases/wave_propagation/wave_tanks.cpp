#include "wave_tanks.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <Eigen/Dense>
#include <stdexcept>
#include <moorsph/fluid/box_geometry.hpp>
#include <moorsph/fluid/damping_zone.hpp>
#include <moorsph/fluid/waves/dispersion.hpp>
#include <moorsph/fluid/waves/piston_signal.hpp>
#include <moorsph/fluid/waves/stokes2_wave.hpp>

namespace moorsph::cases {
namespace {

constexpr double kG = 9.81;
using Vec2 = fluid::Vec<2>;

fluid::FluidSetup<2> makeSetup(const WaveTankFluid& f, double dx, double depth) {
  fluid::FluidSetup<2> s;
  s.dx = dx;
  s.mu = f.mu;
  // 10 x the speed of water falling the depth: density changes stay below ~1%.
  s.sound_speed = f.sound_speed > 0.0 ? f.sound_speed : 10.0 * std::sqrt(2.0 * kG * depth);
  s.method = f.method;
  s.effects = f.effects;
  return s;
}

void addGauges(WaveTank& tank, const std::vector<double>& xs, double x_origin) {
  for (double x : xs) {
    fluid::WaveGaugeSpec<2> g;
    g.position = Vec2(x_origin + x, 0.0);
    g.bottom = 0.0;
    g.top = 2.0 * tank.depth;
    tank.gauges.emplace_back(g);
  }
}

// The controller of `control` for a maker of height H and period T ramped up over
// `ramp` seconds; its gauges are added to tank.control_gauges.
void addController(WaveTank& tank, const WaveTankControl& control, double height, double ramp, double gain) {
  if (control.gauges.empty()) return;
  fluid::WaveHeightControllerSpec c;
  c.target_height = height;
  c.period = tank.period;
  c.start_time = control.start_time;
  c.update_periods = control.update_periods;
  c.beta = control.beta;
  c.initial_gain = gain;
  c.stop_time = control.stop_time;
  // Each window waits until the wave made with the new gain has reached the farthest
  // watched gauge (distance over the group speed), plus a period.
  const double k = 2.0 * M_PI / tank.wavelength;
  const double farthest = *std::max_element(control.gauges.begin(), control.gauges.end());
  c.delay = std::max(0.0, farthest) / fluid::waves::groupSpeed(k, tank.depth, kG) + tank.period;
  if (c.start_time < ramp + c.delay) c.start_time = ramp + c.delay;
  tank.controller = std::make_shared<fluid::WaveHeightController>(c);
  for (double x : control.gauges) {
    fluid::WaveGaugeSpec<2> g;
    g.position = Vec2(tank.x_origin + x, 0.0);
    g.top = 2.0 * tank.depth;
    tank.control_gauges.emplace_back(g);
  }
}

// The velocity field of the wave a periodic tank makes or starts with, (x, height above
// the floor, t) -> velocity.
fluid::ForcingRegion<2>::TargetField makeWaveVelocity(const std::string& theory, double amplitude, double period,
                                                      double depth) {
  if (theory == "stokes2") {
    const auto w = std::make_shared<fluid::waves::Stokes2Wave>(amplitude, period, depth, kG);
    return [w](double x, double y, double t) { return w->velocity(x, y, t); };
  }
  if (theory == "airy") {
    const auto w = std::make_shared<fluid::waves::AiryWave>(amplitude, period, depth, kG);
    return [w](double x, double y, double t) { return w->velocity(x, y, t); };
  }
  throw std::invalid_argument("periodic wave tank: theory must be 'airy' or 'stokes2', not '" + theory + "'");
}

// The water already carrying the wave eta = a cos(k x) at t = 0 (no maker, so nothing but
// the scheme acts on it afterwards). Each particle of the square lattice at (x0, y0) is
// moved by the linear wave's orbital displacement (e.g. Dean & Dalrymple 1991, sec. 4.4)
//   xi = -a cosh(k y0)/sinh(k d) sin(k x0),   zeta = a sinh(k y0)/sinh(k d) cos(k x0),
// plus the second-order rise of the mean positions, Delta = A^2 k sinh(2 k y0)/4 with
// A = a/sinh(k d), that keeps each row's area (the first-order map shrinks a cell by
// (A k)^2 cosh(2 k y0)/2 on average; without Delta the still level would sit k a^2 coth(kd)/2
// = 0.09 a low). Each particle gets the wave's velocity at (x0, y0) and the linear wave's
// pressure rho0 g ((d - y0) - zeta + a cosh(k y0)/cosh(k d) cos(k x0)), zero on the
// surface; mass = rho x its mapped cell's area (the map's Jacobian), which varies along x
// by (ka)^2/(2 sinh^2 kd) only (0.1 (ka)^2 at kd = 1.57). (Columns stretched to the surface, tried first, made the masses under crests
// and troughs 2 a/d = 20% apart, and that wave went unstable after 5 wavelengths.)
// Positions are second order in the mean only: a Stokes wave starts with the Airy surface
// and the Stokes velocity.
void fillWithWave(fluid::FluidParticles<2>& water, const fluid::ForcingRegion<2>::TargetField& velocity,
                  double amplitude, double k, double length, double depth, double dx, const fluid::TaitEos& eos) {
  const int columns = static_cast<int>(std::lround(length / dx));
  const int rows = static_cast<int>(std::lround(depth / dx));
  const double A = amplitude / std::sinh(k * depth), Ak = A * k;
  for (int i = 0; i < columns; ++i) {
    const double x0 = (i + 0.5) * dx, c = std::cos(k * x0), s = std::sin(k * x0);
    for (int j = 0; j < rows; ++j) {
      const double y0 = (j + 0.5) * dx, ch = std::cosh(k * y0), sh = std::sinh(k * y0);
      const double zeta = A * sh * c;
      const double x = x0 - A * ch * s, y = y0 + zeta + 0.25 * A * Ak * std::sinh(2.0 * k * y0);
      // Jacobian of (x0, y0) -> (x, y).
      const double area = (1.0 - Ak * ch * c) * (1.0 + Ak * ch * c + 0.5 * Ak * Ak * std::cosh(2.0 * k * y0)) -
                          (Ak * sh * s) * (Ak * sh * s);
      const double p = eos.rho0() * kG * ((depth - y0) - zeta + amplitude * ch / std::cosh(k * depth) * c);
      const double rho = eos.density(p);
      const Eigen::Vector2d v = velocity(x0, y0, 0.0);
      water.add(Vec2(std::fmod(x + length, length), y), Vec2(v[0], v[1]), rho, rho * dx * dx * area);
    }
  }
}

}  // namespace

WaveTankFluid lowDissipationWaveFluid(double dx) {
  WaveTankFluid f;
  f.dx = dx;
  f.method.h_factor = 2.0;
  // The midpoint predictor lets particle noise grow, 0.55 damps the waves too, 0.52 lets
  // the run-up on a piston grow; the symplectic step does neither (docs/stability.md 3h).
  f.method.integrator = fluid::Integrator::Symplectic;
  f.method.predictor_fraction = 0.5;  // what the symplectic step's predictor does
  f.method.density_diffusion_form = fluid::DensityDiffusionForm::Renormalised;
  f.effects = {"pressure", "viscosity", "gravity", "walls", "density_diffusion"};
  return f;
}

WaveTank buildPeriodicWaveTank(const PeriodicWaveTankSpec& spec) {
  if (spec.wavelengths < 1) throw std::invalid_argument("periodic wave tank: at least one wavelength");
  const double hf = spec.fluid.method.h_factor;
  // METHOD.md 4a: L = n lambda, dx adjusted so L holds whole cells and particles; the
  // depth is then rounded to whole rows, which changes lambda a little: iterate, and
  // finally take k = 2 pi n / L exactly and the period that goes with it.
  double depth = spec.depth, length = 0.0, dx = spec.fluid.dx;
  for (int it = 0; it < 4; ++it) {
    length = spec.wavelengths * fluid::waves::wavelengthFromPeriod(spec.period, depth, kG);
    dx = fluid::periodicSpacing(length, spec.fluid.dx, hf);
    depth = std::max(2.0, std::round(spec.depth / dx)) * dx;
  }
  const double k = 2.0 * M_PI * spec.wavelengths / length;
  const double period = 2.0 * M_PI / fluid::waves::angularFrequencyFromWaveNumber(k, depth, kG);

  fluid::FluidSetup<2> setup = makeSetup(spec.fluid, dx, depth);
  if (spec.floor == "mirror") {  // the images replace the floor's boundary particles
    std::replace(setup.effects.begin(), setup.effects.end(), std::string("walls"), std::string("mirror_floor"));
    setup.mirror_floor_height = 0.0;
  } else if (spec.floor != "walls") {
    throw std::invalid_argument("periodic wave tank: floor must be 'walls' or 'mirror', not '" + spec.floor + "'");
  }
  const double h = setup.h();
  setup.domain.lower = Vec2(0.0, -4.0 * h);
  setup.domain.upper = Vec2(length, 3.0 * depth + 0.5);
  setup.domain.periodic = {true, false};
  const fluid::TaitEos eos(setup.rho0, setup.sound_speed, setup.method.gamma);
  fluid::FluidParticles<2> water;
  const auto wave_velocity = makeWaveVelocity(spec.theory, spec.amplitude, period, depth);
  if (spec.initial_wave)
    fillWithWave(water, wave_velocity, spec.amplitude, k, length, depth, dx, eos);
  else
    fluid::fillBox<2>(water, Vec2(0.0, 0.0), Vec2(length, depth), dx, eos, kG, depth);
  // The floor: one row of boundary particles at y = 0, normals up, spacing dx,
  // periodic like the water.
  fluid::BoundaryGeometry<2> boundary;
  if (spec.floor == "walls") {
    fluid::BoundaryParticles<2> floor;
    const int columns = static_cast<int>(std::lround(length / dx));
    for (int i = 0; i < columns; ++i) floor.add(Vec2((i + 0.5) * dx, 0.0), {Vec2(0.0, 1.0)}, 0);
    boundary.addSurface(floor, fluid::SurfaceInfo{"floor", false});
  }

  WaveTank tank;
  tank.sim = std::make_unique<fluid::FluidSimulation<2>>(setup, water, boundary);
  tank.depth = depth;
  tank.period = period;
  tank.wavelength = length / spec.wavelengths;
  tank.amplitude = spec.amplitude;

  if (!spec.initial_wave) {  // a free wave needs no maker
    fluid::ForcingRegionSpec f;
    f.x_start = spec.maker_start;
    f.length = spec.maker_length > 0.0 ? spec.maker_length : length;
    f.floor = 0.0;
    f.bottom_gap = spec.bottom_gap;
    f.still_level = depth;
    f.kappa = spec.kappa;
    f.mu = spec.fluid.mu;
    f.ramp_up = spec.ramp_up;
    f.end_time = spec.forcing_end;
    f.gain = spec.gain;
    // The forcing region is [x_start, x_start + length] without wrapping: a region that
    // covers the tank starts at 0.
    auto forcing = std::make_unique<fluid::ForcingRegion<2>>(f, wave_velocity, tank.sim->cflDt());
    tank.forcing = forcing.get();
    tank.sim->addEffect(std::move(forcing));
  }

  std::vector<double> xs = spec.gauges;
  if (xs.empty())
    for (int i = 0; i < 10 * spec.wavelengths; ++i) xs.push_back((i + 0.25) * 0.1 * tank.wavelength);
  addGauges(tank, xs, 0.0);
  addController(tank, spec.control, 2.0 * spec.amplitude, spec.ramp_up, spec.gain);
  return tank;
}

WaveTank buildPistonFlume(const PistonFlumeSpec& spec) {
  const double dx = spec.fluid.dx;
  const double depth = std::max(2.0, std::round(spec.depth / dx)) * dx;
  const double stroke = fluid::waves::pistonStroke(spec.height, spec.period, depth, kG);
  const double x_p = 0.5 * stroke * std::max(spec.gain, 2.5) + 4.0 * dx;  // room behind the plate for its stroke
  const double x_end = x_p + spec.length;
  if (!(spec.damping_start > 0.0 && spec.damping_start < spec.length))
    throw std::invalid_argument("piston flume: the damping zone must start inside the flume");

  if (spec.floor != "walls" && spec.floor != "mirror")
    throw std::invalid_argument("piston flume: floor must be 'walls' or 'mirror', not '" + spec.floor + "'");
  const bool mirror_floor = spec.floor == "mirror";

  fluid::FluidSetup<2> setup = makeSetup(spec.fluid, dx, depth);
  if (mirror_floor) {  // the images replace the floor's row; the walls law keeps the piston and end wall
    setup.effects.push_back("mirror_floor");
    setup.mirror_floor_height = 0.0;
  }
  const double h = setup.h();
  const double top = 2.0 * depth;
  setup.domain.lower = Vec2(-4.0 * h, -4.0 * h);
  setup.domain.upper = Vec2(x_end + 4.0 * h, 3.0 * depth + 0.5);
  const fluid::TaitEos eos(setup.rho0, setup.sound_speed, setup.method.gamma);
  fluid::FluidParticles<2> water;
  fluid::fillBox<2>(water, Vec2(x_p, 0.0), Vec2(x_end, depth), dx, eos, kG, depth);
  fluid::BoundaryGeometry<2> boundary;
  boundary.addSurface(
      fluid::sampleBoxSurface<2>(Vec2(0.0, 0.0), Vec2(x_end, top), dx, fluid::tankFaces<2>(false, mirror_floor),
                                 fluid::NormalSide::Inward),
      fluid::SurfaceInfo{"flume", false});
  // The plate: the +x face of a thin box, moved rigidly along x.
  const auto plate = fluid::sampleBoxSurface<2>(Vec2(x_p - 2.0 * dx, 0.0), Vec2(x_p, top), dx,
                                                {false, true, false, false}, fluid::NormalSide::Outward);
  const auto surface = boundary.addSurface(plate, fluid::SurfaceInfo{"piston", false, true, Eigen::Vector3d(x_p, 0, 0)});

  WaveTank tank;
  tank.sim = std::make_unique<fluid::FluidSimulation<2>>(setup, water, boundary);
  tank.depth = depth;
  tank.period = spec.period;
  tank.wavelength = fluid::waves::wavelengthFromPeriod(spec.period, depth, kG);
  tank.amplitude = 0.5 * spec.height;
  tank.x_origin = x_p;

  // X(t) = G(t) r(t) (S/2) sin(omega t), r the half-cosine ramp (as the scene files'
  // piston), G the gain: fixed, or the controller's (continuous, piecewise linear).
  const double omega = 2.0 * M_PI / spec.period;
  const double ramp = spec.ramp_up > 0.0 ? spec.ramp_up : 2.0 * spec.period;
  addController(tank, spec.control, spec.height, ramp, spec.gain);
  const auto control = tank.controller;
  const double half = 0.5 * stroke, fixed_gain = spec.gain;
  auto G = [control, fixed_gain](double t) { return control ? control->gainAt(t) : fixed_gain; };
  auto dG = [control](double t) { return control ? control->gainRate(t) : 0.0; };
  // Ramped unit signal and its rate.
  auto s = [=](double t) {
    const double r = t >= ramp ? 1.0 : 0.5 * (1.0 - std::cos(M_PI * t / ramp));
    return r * half * std::sin(omega * t);
  };
  auto ds = [=](double t) {
    const double r = t >= ramp ? 1.0 : 0.5 * (1.0 - std::cos(M_PI * t / ramp));
    const double dr = t >= ramp ? 0.0 : 0.5 * M_PI / ramp * std::sin(M_PI * t / ramp);
    return half * (dr * std::sin(omega * t) + r * omega * std::cos(omega * t));
  };
  auto X = [=](double t) { return t <= 0.0 ? 0.0 : G(t) * s(t); };
  auto V = [=](double t) { return t <= 0.0 ? 0.0 : G(t) * ds(t) + dG(t) * s(t); };
  tank.sim->addEffect(std::make_unique<fluid::Piston<2>>(tank.sim->updWalls(), surface, X, V));
  tank.sim->addEffect(std::make_unique<fluid::DampingZone<2>>(x_p + spec.damping_start, x_end, spec.damping_k_max,
                                                              tank.sim->cflDt()));
  addGauges(tank, spec.gauges, x_p);
  return tank;
}

GaugeRecord runAndRecord(WaveTank& tank, double end, double interval,
                         const std::function<void(const GaugeRecord&)>& on_sample) {
  GaugeRecord rec;
  rec.eta.resize(tank.gauges.size());
  const auto sample = [&]() {
    rec.t.push_back(tank.sim->time());
    for (std::size_t g = 0; g < tank.gauges.size(); ++g)
      rec.eta[g].push_back(tank.gauges[g].read(*tank.sim) - tank.depth);
    if (on_sample) on_sample(rec);
  };
  std::vector<double> watched(tank.control_gauges.size());
  const auto control = [&]() {
    if (!tank.controller) return;
    for (std::size_t g = 0; g < watched.size(); ++g) watched[g] = tank.control_gauges[g].read(*tank.sim) - tank.depth;
    tank.controller->addSample(tank.sim->time(), watched);
  };
  sample();
  double next = interval;
  while (tank.sim->time() < end) {
    if (tank.controller && tank.forcing) tank.forcing->setGain(tank.controller->gainAt(tank.sim->time()));
    tank.sim->step();
    if (tank.sim->time() >= next) {
      sample();
      control();
      next += interval;
    }
  }
  return rec;
}

double meanWaveHeight(const std::vector<double>& t, const std::vector<double>& eta, double period, double t0,
                      double t1) {
  double sum = 0.0;
  int count = 0;
  for (double a = t0; a + period <= t1 + 1e-12; a += period) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (std::size_t k = 0; k < t.size(); ++k) {
      if (t[k] < a || t[k] >= a + period) continue;
      lo = std::min(lo, eta[k]);
      hi = std::max(hi, eta[k]);
    }
    if (hi >= lo) {
      sum += hi - lo;
      ++count;
    }
  }
  return count ? sum / count : 0.0;
}

double meanLevel(const std::vector<double>& t, const std::vector<double>& eta, double t0, double t1) {
  double sum = 0.0;
  int count = 0;
  for (std::size_t k = 0; k < t.size(); ++k)
    if (t[k] >= t0 && t[k] <= t1) {
      sum += eta[k];
      ++count;
    }
  return count ? sum / count : 0.0;
}

WaveSeparation separateIncidentReflected(const GaugeRecord& rec, const std::vector<double>& x, double omega, double k,
                                         double t0, double t1, double x_ref) {
  using C = std::complex<double>;
  const int n = static_cast<int>(x.size());
  if (n < 3 || rec.eta.size() != x.size()) throw std::invalid_argument("wave separation: one x per gauge, at least 3");
  const double period = 2.0 * M_PI / omega;
  t1 = t0 + std::floor((t1 - t0) / period + 1e-9) * period;  // whole periods only
  Eigen::VectorXcd z(n);
  for (int g = 0; g < n; ++g) {
    C sum = 0.0;
    int count = 0;
    for (std::size_t j = 0; j < rec.t.size(); ++j)
      if (rec.t[j] >= t0 && rec.t[j] < t1) {
        sum += rec.eta[g][j] * std::exp(C(0.0, omega * rec.t[j]));
        ++count;
      }
    if (count == 0) throw std::invalid_argument("wave separation: no samples in the window");
    z[g] = 2.0 * sum / static_cast<double>(count);
  }
  WaveSeparation best;
  best.residual = std::numeric_limits<double>::infinity();
  for (double alpha = 0.0; alpha <= 3.0; alpha += 0.005) {
    Eigen::MatrixXcd m(n, 2);
    for (int g = 0; g < n; ++g) {
      m(g, 0) = std::exp(C(-alpha, k) * x[g]);
      m(g, 1) = std::exp(C(alpha, -k) * x[g]);
    }
    const Eigen::Vector2cd c = m.colPivHouseholderQr().solve(z);
    const double r = (m * c - z).norm() / z.norm();
    if (r < best.residual) {
      best.residual = r;
      best.alpha = alpha;
      best.incident = std::abs(c[0]) * std::exp(-alpha * x_ref);
      best.reflected = std::abs(c[1]) * std::exp(alpha * x_ref);
    }
  }
  return best;
}

}  // namespace moorsph::cases
