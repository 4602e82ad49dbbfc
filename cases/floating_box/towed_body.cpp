// The released light cylinder's missing speed (docs/accuracy-cost.md, "Light cylinder
// released under water") asked the other way round: move the cylinder along a prescribed
// path and measure the force the water puts on it. Same tank, body and fluid set-up as
// cases/include/moorsph/cases/submerged_body.hpp (2D, R = 0.05 m centred 0.2 m above the
// floor of a 0.6 m tank with 0.5 m of water), but no body dynamics: the surface is held
// for 0.3 s while the water settles and then moved straight up by one of
//   accel A          y - y0 = A s^2 / 2 (s = t - 0.3 s): with A = a0 = 6.2547 m/s^2 the
//                    path potential flow gives the free cylinder of density ratio 0.2;
//   speed U RAMP     speed ramped linearly from 0 to U over RAMP seconds, then held.
// Potential flow in this tank puts the force F = rho g V - C_a rho V a on it (C_a =
// 1.0547, cases/floating_box/confined_added_mass.py; the change of C_a over the 10-40 mm
// the body moves is neglected). The program prints, every millisecond, the measured
// vertical force, that potential-flow force and their difference, the resistance
// R = F_pf - F (positive: the water holds the body back more than potential flow does).
// A drag grows as U^2, a viscous history force as U sqrt(s), an added-mass error
// as the acceleration, so runs at several U and A tell the forms apart.
// With plate=L the body is instead a flat plate L long and 0.02 m thick (a box, same
// centre) moved along x, its length: the water slides along its two faces. Potential flow
// gives it no force at constant speed (and a negligible added mass along its length), so
// R = -F_x sign(U); plates of two lengths separate the faces' share from the ends'.
// Method options to find what sets R (each KEY=VALUE): cs (sound speed factor, c_s =
// F sqrt(2 g 0.5), default 10), mu [Pa s] (0.01), boff (0.5), h (h/dx, 1.2), strength
// (0.01), delta (density diffusion, 0.1), xsph (eps, 0.5), xsph_form (reference or
// monaghan), g [m/s^2] (9.81; c_s stays
// 10 sqrt(2 x 9.81 x 0.5) unless cs is given), effects (comma list, default
// pressure,viscosity,xsph,density_diffusion,gravity,walls), plate [m] (see above),
// sectors N (cylinder only: also print the force from each of N angular sectors of the
// surface, sector 0 centred on the direction of +axis, counter-clockwise, and the mean
// pressure of the fluid within 1.5 dx of the surface in each), dump S (at S ms after the
// start, print the fluid particles within 3 R of the centre as '# dump' lines and the
// body's particles as '# wall' lines).
// Usage: moorsph_towed_body DX accel A | speed U RAMP [END_AFTER_START=0.1] [KEY=VALUE...]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>
#include <moorsph/cases/command_line.hpp>
#include <moorsph/cases/submerged_body.hpp>
#include <moorsph/fluid/fluid_simulation.hpp>

namespace {

using namespace moorsph;

/// The body's prescribed vertical path: height above its start and speed at time s
/// after the start of the motion.
struct Path {
  bool accelerate = true;
  double a = 0.0, u = 0.0, ramp = 0.0;
  double rise(double s) const {
    if (s <= 0.0) return 0.0;
    if (accelerate) return 0.5 * a * s * s;
    if (s < ramp) return 0.5 * u / ramp * s * s;
    return 0.5 * u * ramp + u * (s - ramp);
  }
  double speed(double s) const {
    if (s <= 0.0) return 0.0;
    if (accelerate) return a * s;
    return s < ramp ? u * s / ramp : u;
  }
  double acceleration(double s) const {
    if (s <= 0.0) return 0.0;
    if (accelerate) return a;
    return s < ramp ? u / ramp : 0.0;
  }
};

/// Moves the body surface along the path (along axis 0 = x or 1 = y) before every
/// evaluation of the rates.
class PrescribedMotion final : public fluid::FluidEffect<2> {
 public:
  PrescribedMotion(fluid::Walls<2>* walls, std::size_t surface, fluid::Vec<2> start, double t0, Path path, int axis)
      : walls_(walls), surface_(surface), start_(start), t0_(t0), path_(path), axis_(axis) {}
  const char* name() const override { return "prescribed_motion"; }
  void addRates(fluid::FluidContext<2>&) override {}
  void advanceTo(double t, fluid::StepStage) override {
    fluid::Vec<2> position = start_, velocity = fluid::Vec<2>::Zero();
    position[axis_] += path_.rise(t - t0_);
    velocity[axis_] = path_.speed(t - t0_);
    walls_->setSurfaceMotion(surface_, fluid::RigidMotion<2>::translation(position, velocity));
  }

 private:
  fluid::Walls<2>* walls_;
  std::size_t surface_;
  fluid::Vec<2> start_;
  double t0_;
  Path path_;
  int axis_;
};

/// Sector j of n equal angular sectors about `centre` in which the point r lies, sector
/// j centred 360 j/n degrees from the +axis direction, counter-clockwise.
std::size_t sectorOf(const fluid::Vec<2>& r, const fluid::Vec<2>& centre, int axis, int n) {
  constexpr double two_pi = 6.283185307179586;
  const fluid::Vec<2> d = r - centre;
  const double along = d[axis], across = axis == 1 ? -d[0] : d[1];  // across: 90 deg counter-clockwise
  double turn = std::atan2(across, along) / two_pi + 0.5 / n;
  turn -= std::floor(turn);
  return std::min(static_cast<std::size_t>(turn * n), static_cast<std::size_t>(n - 1));
}

/// Where on the surface the force comes from: per sector, the force along `axis` on the
/// body's particles in it, then the mean pressure of the fluid particles within `reach`
/// of the surface (a cylinder of `radius`) in it.
std::vector<double> sectorLoads(const fluid::FluidSimulation<2>& sim, std::size_t body, const fluid::Vec<2>& centre,
                                double radius, double reach, int axis, int n) {
  std::vector<double> out(2 * static_cast<std::size_t>(n), 0.0), count(static_cast<std::size_t>(n), 0.0);
  const auto& b = sim.walls()->particles();
  const auto [first, last] = sim.walls()->surfaceRange(body);
  for (std::size_t k = first; k < last; ++k) out[sectorOf(b.r[k], centre, axis, n)] += b.reaction[k][axis];
  const auto& f = sim.fluid();
  for (std::size_t i = 0; i < f.size(); ++i) {
    if ((f.r[i] - centre).norm() > radius + reach) continue;
    const std::size_t j = sectorOf(f.r[i], centre, axis, n);
    out[static_cast<std::size_t>(n) + j] += f.p[i];
    count[j] += 1.0;
  }
  for (int j = 0; j < n; ++j) out[static_cast<std::size_t>(n + j)] /= std::max(1.0, count[static_cast<std::size_t>(j)]);
  return out;
}

/// The fluid particles within `reach` of `centre` as '# dump' comment lines on stdout
/// (x, y relative to the centre [m], vx, vy [m/s], rho [kg/m^3], p [Pa]), then the body's
/// particles as '# wall' lines (x, y relative to the centre, normal).
void dumpNearBody(const fluid::FluidSimulation<2>& sim, std::size_t body, const fluid::Vec<2>& centre, double reach,
                  double s) {
  const auto& f = sim.fluid();
  std::printf("# dump at s = %.4f s: x y (from the body centre) vx vy rho p\n", s);
  for (std::size_t i = 0; i < f.size(); ++i) {
    const fluid::Vec<2> d = f.r[i] - centre;
    if (d.norm() > reach) continue;
    std::printf("# dump %.6f %.6f %.5f %.5f %.4f %.2f\n", d[0], d[1], f.v[i][0], f.v[i][1], f.rho[i], f.p[i]);
  }
  // The body's boundary particles: x y (from the centre) and the normal, for force budgets.
  const auto& b = sim.walls()->particles();
  const auto [first, last] = sim.walls()->surfaceRange(body);
  for (std::size_t k = first; k < last; ++k) {
    const fluid::Vec<2> d = b.r[k] - centre;
    const fluid::Vec<2>& n = b.normals[b.normal_begin[k]];
    std::printf("# wall %.6f %.6f %.6f %.6f\n", d[0], d[1], n[0], n[1]);
  }
}

[[noreturn]] void usage() {
  std::fprintf(stderr, "usage: moorsph_towed_body DX accel A | speed U RAMP [END_AFTER_START=0.1] [KEY=VALUE...]\n");
  std::exit(2);
}

double parseNumber(const std::string& text, const std::string& what) {
  return cases::numberArgument(text, what, "moorsph_towed_body");
}

/// One KEY=VALUE option (see the header comment); plate, sectors and dump set their
/// own variables, the rest `spec`.
void applyOption(fluid::TankSpec<2>& spec, double& plate, int& sectors, double& dump_ms, const std::string& option) {
  const auto eq = option.find('=');
  if (eq == std::string::npos) usage();
  const std::string key = option.substr(0, eq), value = option.substr(eq + 1);
  const bool text_value = key == "xsph_form" || key == "effects";
  const double v = text_value ? 0.0 : parseNumber(value, key);
  auto& m = spec.fluid.method;
  if (key == "cs") spec.fluid.sound_speed = v * std::sqrt(2.0 * 9.81 * 0.5);
  else if (key == "mu") spec.fluid.mu = v;
  else if (key == "boff") m.boundary_offset = v;
  else if (key == "h") m.h_factor = v;
  else if (key == "strength") m.boundary_strength = v;
  else if (key == "delta") m.density_diffusion_delta = v;
  else if (key == "xsph") m.xsph_eps = v;
  else if (key == "xsph_form") {
    if (!fluid::optionFromName(fluid::kXsphFormNames, value, m.xsph_form)) usage();
  }
  else if (key == "g") spec.fluid.gravity[1] = -v;
  else if (key == "plate") plate = v;
  else if (key == "sectors") sectors = cases::countArgument(value, key, "moorsph_towed_body", 1);
  else if (key == "dump") dump_ms = v;
  else if (key == "effects") {
    spec.fluid.effects.clear();
    for (std::size_t b = 0, e; b <= value.size(); b = e + 1) {
      e = value.find(',', b);
      if (e == std::string::npos) e = value.size();
      spec.fluid.effects.push_back(value.substr(b, e - b));
    }
  } else usage();
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 4) usage();
  const double dx = parseNumber(argv[1], "DX");
  Path path;
  const std::string kind = argv[2];
  int next = 4;
  if (kind == "accel") {
    path.a = parseNumber(argv[3], "A");
  } else if (kind == "speed" && argc >= 5) {
    path.accelerate = false;
    path.u = parseNumber(argv[3], "U");
    path.ramp = parseNumber(argv[4], "RAMP");
    next = 5;
  } else {
    usage();
  }
  double window = 0.1;
  if (argc > next && std::string(argv[next]).find('=') == std::string::npos) window = parseNumber(argv[next++], "END_AFTER_START");
  const double radius = 0.05, hold = 0.3, rho = 1000.0;
  const fluid::Vec<2> centre(0.3, 0.2);

  // The water and tank of buildSubmergedBody<2>, the body as a moved wall surface.
  double plate = 0.0;
  int sectors = 0;
  double dump_ms = -1.0;
  fluid::TankSpec<2> options;  // parsed once first: the plate's size is needed before the build
  for (int a = next; a < argc; ++a) applyOption(options, plate, sectors, dump_ms, argv[a]);
  auto f = cases::buildSubmergedBodyFluid<2>(
      dx, radius, centre,
      [&](fluid::TankSpec<2>& spec) {
        for (int a = next; a < argc; ++a) applyOption(spec, plate, sectors, dump_ms, argv[a]);
      },
      fluid::Vec<2>(0.5 * plate, plate > 0.0 ? 0.01 : 0.0));
  const int axis = plate > 0.0 ? 0 : 1;
  if (plate > 0.0 && (sectors > 0 || dump_ms >= 0.0)) {
    std::fprintf(stderr, "moorsph_towed_body: sectors and dump measure round the cylinder; not with plate\n");
    return 2;
  }
  const std::size_t body = f.body_surface;
  fluid::FluidSimulation<2> sim(f.scene.setup, f.water, f.scene.boundary);
  const double g = -f.scene.setup.gravity[1];
  sim.addEffect(std::make_unique<PrescribedMotion>(sim.updWalls(), body, centre, hold, path, axis));

  const double volume = cases::displacedVolume<2>(radius);
  const double added_mass = cases::tankAddedMassCoefficient<2>() * rho * volume;
  const std::string motion = kind == "accel" ? "accel " + std::string(argv[3])
                                             : "speed " + std::string(argv[3]) + " ramp " + argv[4];
  if (plate > 0.0)
    std::printf("# towed plate %.3f x 0.02 m along x, %zu fluid particles, %s, hold %.2f s\n", plate, f.water.size(),
                motion.c_str(), hold);
  else
    std::printf("# towed cylinder R = %.3f m (%.1f dx), %zu fluid particles, %s, hold %.2f s\n", radius, radius / dx,
                f.water.size(), motion.c_str(), hold);
  std::printf("# s [ms]  travel [mm]  speed [m/s]  F [N/m]  F_pf [N/m]  R = F_pf - F [N/m]   (F along the motion's axis)%s\n",
              sectors > 0 ? "  then F of each sector, then the mean pressure [Pa] of the fluid within 1.5 dx of the surface in each (sectors=N)" : "");
  double next_row = hold - 0.05;  // rows every millisecond from 50 ms before the start
  while (sim.time() < hold + window - 1e-12) {
    sim.step();
    if (sim.time() < next_row - 1e-12) continue;
    next_row += 0.001;
    const double s = sim.time() - hold;
    const double force = sim.walls()->calcSurfaceWrench(body, centre).force[axis];
    // Potential flow: buoyancy and added mass for the rising cylinder; nothing along a plate.
    const double potential = plate > 0.0 ? 0.0 : rho * g * volume - added_mass * path.acceleration(s);
    std::printf("%8.2f  %9.3f  %11.4f  %9.3f  %10.3f  %10.3f", 1000.0 * s, 1000.0 * path.rise(s), path.speed(s),
                force, potential, potential - force);
    if (sectors > 0) {
      fluid::Vec<2> now = centre;
      now[axis] += path.rise(s);
      for (const double part : sectorLoads(sim, body, now, radius, 1.5 * dx, axis, sectors)) std::printf("  %9.3f", part);
    }
    std::printf("\n");
    if (dump_ms >= 0.0 && 1000.0 * s >= dump_ms - 1e-9) {
      fluid::Vec<2> now = centre;
      now[axis] += path.rise(s);
      dumpNearBody(sim, body, now, 3.0 * radius, s);
      dump_ms = -1.0;
    }
  }
  return 0;
}
