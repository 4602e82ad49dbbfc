// Boundary-offset study (METHOD.md section 6.1), one run per invocation, one result
// line on stdout (cases/sphere_offset/run_study.sh and run_half_study.sh sweep b_off
// and the spacings).
//
// Fully submerged variant (default): a sphere of radius R = 0.1015 m held at mid-depth
// in still water; its buoyancy B is the time average of the vertical sum of its
// boundary reactions after the fluid settles. The effective radius R_e solves
// B = 4/3 pi rho0 g R_e^3, and eps_R = (R_e - R) / dx says by how many particle
// spacings the fluid sees the sphere too large (> 0) or too small. The tank is smaller
// than the reference's 0.4 x 0.4 x 0.4 m (0.32 x 0.36 x 0.32 m, sphere centre 0.18 m
// above the floor) to fit this machine; --tank/--depth check that this does not
// change eps_R.
//
// Half-submerged variant (--half 1): the reference tank, 0.4 x 0.4 m and 0.2 m deep,
// the sphere held with its centre at the still level. Eight wave gauges on a circle
// around the sphere (METHOD 6.1) give alpha, the mean surface height above the
// centre; the effective radius solves METHOD 6.1's
//   (rho0 g pi / 3) (2 R_e^3 + 3 R_e^2 alpha - alpha^3) = B,
// the weight of the water a sphere of radius R_e displaces below a surface alpha above
// its centre (a spherical cap). B and alpha are averaged over the same window; the
// mean of gauges set symmetrically around the sphere cancels the tank's antisymmetric
// sloshing modes, and B and alpha move together in the symmetric ones, so their
// averages stay consistent. The sphere is held rather than floating so that B is
// measured directly; a floating half-density sphere then sits at R_e - R too high.
//
// Fluid particles start at least dx/2 outside the sphere, as they start dx/2 inside
// tank walls (with b_off = 0 a particle on the surface would feel an unbounded force).

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <vector>
#include <moorsph/cases/command_line.hpp>
#include <moorsph/fluid/fluid_simulation.hpp>
#include <moorsph/fluid/wave_gauge.hpp>
#include <moorsph/fluid/shape_sampling.hpp>
#include <moorsph/fluid/tank_scene.hpp>

namespace {

using namespace moorsph::fluid;

constexpr double kR = 0.1015, kRho0 = 1000.0, kG = 9.81;
const double kPi = std::acos(-1.0);

struct Options {
  double dx = 0.01, boundary_spacing = 0.0, b_off = 0.5, end = 0.6, average_from = 0.3, tank = 0.32, depth = 0.36;
  bool half = false;   // half-submerged variant
  bool rings = false;  // ring sampling of the sphere (sampleSphereRings) instead of Fibonacci
};

Options parse(int argc, char** argv) {
  Options o;
  bool tank_given = false, depth_given = false;
  for (int a = 1; a + 1 < argc; a += 2) {
    const std::string key = argv[a];
    const double v = moorsph::cases::numberArgument(argv[a + 1], key, "moorsph_sphere_offset");
    if (key == "--dx") o.dx = v;
    else if (key == "--boundary-spacing") o.boundary_spacing = v;
    else if (key == "--b-off") o.b_off = v;
    else if (key == "--end") o.end = v;
    else if (key == "--average-from") o.average_from = v;
    else if (key == "--tank") o.tank = v, tank_given = true;
    else if (key == "--depth") o.depth = v, depth_given = true;
    else if (key == "--half") o.half = v != 0.0;
    else if (key == "--rings") o.rings = v != 0.0;
    else {
      std::fprintf(stderr, "unknown option %s (known: --dx --boundary-spacing --b-off --end --average-from --tank --depth --half --rings)\n", key.c_str());
      std::exit(1);
    }
  }
  if ((argc - 1) % 2 != 0) {
    std::fprintf(stderr, "option %s has no value\n", argv[argc - 1]);
    std::exit(1);
  }
  if (o.boundary_spacing <= 0.0) o.boundary_spacing = o.dx;
  if (o.half && !tank_given) o.tank = 0.4;    // METHOD 6.1: tank 0.4 x 0.4 m,
  if (o.half && !depth_given) o.depth = 0.2;  // 0.2 m deep
  return o;
}

/// Still water with the sphere at `centre`; fluid within R + dx/2 of it removed.
std::unique_ptr<FluidSimulation<3>> buildSimulation(const Options& o, const Vec<3>& centre) {
  TankSpec<3> spec;
  spec.size = Vec<3>(o.tank, o.depth + 0.1, o.tank);
  spec.water_upper = Vec<3>(o.tank, o.depth, o.tank);
  spec.dx = o.dx;
  spec.fluid.sound_speed = 10.0 * std::sqrt(2.0 * kG * o.depth);
  spec.fluid.mu = 0.01;  // damps the start-up transient (METHOD 1 allows a scene to raise it)
  spec.fluid.method.boundary_offset = o.b_off;
  spec.fluid.effects = {"pressure", "viscosity", "xsph", "density_diffusion", "gravity", "walls"};
  auto scene = buildTankScene<3>(spec);
  FluidParticles<3> water;
  for (std::size_t i = 0; i < scene.fluid.size(); ++i)
    if ((scene.fluid.r[i] - centre).norm() >= kR + 0.5 * o.dx) water.add(scene.fluid.r[i], scene.fluid.v[i], scene.fluid.rho[i], scene.fluid.m[i]);
  const auto surface = o.rings ? sampleSphereRings(centre, kR, o.boundary_spacing) : sampleSphere<3>(centre, kR, o.boundary_spacing);
  scene.boundary.addSurface(surface, SurfaceInfo{"sphere", true, false, Eigen::Vector3d::Zero(), true});
  return std::make_unique<FluidSimulation<3>>(scene.setup, water, scene.boundary);
}

/// Eight gauges on a circle halfway between the sphere and the tank wall, every 45 degrees.
std::vector<WaveGauge<3>> gaugesAround(const Options& o, const Vec<3>& centre) {
  std::vector<WaveGauge<3>> gauges;
  const double radius = 0.5 * (kR + 0.5 * o.tank);
  for (int k = 0; k < 8; ++k) {
    WaveGaugeSpec<3> g;
    const double a = kPi * k / 4.0;
    g.position = centre + Vec<3>(radius * std::cos(a), 0.0, radius * std::sin(a));
    g.bottom = 0.0;
    g.top = o.depth + 0.1;
    gauges.emplace_back(g);
  }
  return gauges;
}

/// Submerged volume of a sphere of radius r whose centre lies alpha below the surface
/// (a spherical cap of height r + alpha; alpha in [-r, r]).
double capVolume(double r, double alpha) { return kPi / 3.0 * (2.0 * r * r * r + 3.0 * r * r * alpha - alpha * alpha * alpha); }

/// R_e with rho0 g capVolume(R_e, alpha) = B, by bisection (capVolume rises with r for r >= |alpha|).
double effectiveRadiusHalf(double B, double alpha) {
  double lo = std::abs(alpha), hi = 2.0 * kR;
  for (int it = 0; it < 100; ++it) {
    const double mid = 0.5 * (lo + hi);
    (kRho0 * kG * capVolume(mid, alpha) < B ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace

int main(int argc, char** argv) {
  const Options o = parse(argc, argv);
  const Vec<3> centre(o.tank / 2, o.half ? o.depth : o.depth / 2, o.tank / 2);
  const auto sim_ptr = buildSimulation(o, centre);
  auto& sim = *sim_ptr;
  auto gauges = gaugesAround(o, centre);
  const double gauge_interval = 0.01;  // [s] gauge readings are cheap but not free

  const auto start = std::chrono::steady_clock::now();
  double sum_force = 0.0, sum_alpha = 0.0, next_gauge = o.average_from;
  long n_force = 0, n_alpha = 0;
  while (sim.time() < o.end) {
    sim.step();
    if (sim.time() < o.average_from) continue;
    sum_force += sim.walls()->calcSurfaceWrench(1, centre).force[1];
    ++n_force;
    if (o.half && sim.time() >= next_gauge) {
      double level = 0.0;
      for (const auto& g : gauges) level += g.read(sim) / gauges.size();
      sum_alpha += level - centre[1];
      ++n_alpha;
      next_gauge += gauge_interval;
    }
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (n_force == 0) {
    std::fprintf(stderr, "--average-from %.3f is not before --end %.3f: nothing averaged\n", o.average_from, o.end);
    return 1;
  }
  const double B = sum_force / n_force;
  const double alpha = o.half ? sum_alpha / n_alpha : 0.0;
  const double B0 = o.half ? kRho0 * kG * capVolume(kR, alpha) : 4.0 / 3.0 * kPi * kRho0 * kG * kR * kR * kR;
  const double Re = o.half ? effectiveRadiusHalf(B, alpha) : std::cbrt(3.0 * B / (4.0 * kPi * kRho0 * kG));
  std::printf("%sdx=%.4f boundary_spacing=%.4f b_off=%.2f tank=%.2f%s buoyancy=%.3f N (exact %.3f N, %+.2f%%) ",
              o.half ? "half " : "", o.dx, o.boundary_spacing, o.b_off, o.tank, o.rings ? " rings" : "", B, B0,
              100.0 * (B / B0 - 1.0));
  if (o.half) std::printf("alpha=%+.5f m ", alpha);
  std::printf("R_e=%.5f m eps_R=%+.3f particles=%zu boundary=%zu steps=%zu wall_s=%.1f\n", Re, (Re - kR) / o.dx,
              sim.fluid().size(), sim.walls()->particles().size(), sim.stepCount(), wall);
}
