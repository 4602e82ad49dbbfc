// Where the lab buoy left at rest gets the energy that rocks it (issue 5; findings in
// docs/validation/tethered-buoy.md). Runs the set-up of tests/coupling/test_lab_buoy_rest
// (D/6 unless told otherwise, tank a whole number of spacings, symmetric about the buoy)
// and prints every 0.02 s:
//  - the buoy's tilt (its symmetry axis' x and z components, deg) and the sway of its
//    centroid from the nominal rest (mm);
//  - the horizontal fluid force on it and the fluid moment about its centroid (the wall
//    law pushes along the radial normals of the sphere, so the moment must stay ~0);
//  - the work the fluid has done on the sway and on the rotation since release (J);
//  - the fluid's kinetic, potential and elastic energy (J), and the heave from the nominal
//    rest (mm);
// and at the end the test's drift (mean pose over 1-2 s against 4-5 s after release).
// At the end it prints how far the fluid particles moved up or down, grouped by where
// they started (next to the sphere, the top layer, the side walls, the floor, the bulk),
// with the potential energy each group gave up: the still water's own circulation.
// usage: moorsph_buoy_rest_energy [D/dx] [cfl] [c_s factor] [density diffusion 0|1]
//                                 [seconds after t = 0.3 s] [release time s]
//                                 [settling damping rate 1/s, while held]
//                                 [1: renormalised density diffusion (delta-SPH)]
//                                 [1: mirror floor (the mirror_floor effect)]
//                                 [h / dx] [b_off] [wall law h_w / dx]
//                                 [1: conservative wall law (method.boundary_force)]
//                                 [1: mirror side walls (the mirror_walls effect)]
// A release time past the end holds the buoy throughout (the fluid alone); while held the
// force columns show the fluid's wrench on the held sphere (its buoyancy in Fy_N).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>
#include <moorsph/cases/command_line.hpp>
#include <moorsph/cases/tethered_buoy.hpp>

namespace {

using namespace moorsph;


double argOr(int argc, char** argv, int i, double fallback) { return argc > i ? moorsph::cases::numberArgument(argv[i], "argument " + std::to_string(i), "moorsph_buoy_rest_energy") : fallback; }

Eigen::Vector3d toEigen(const fluid::Vec<3>& v) { return {v[0], v[1], v[2]}; }

/// Start positions indexed by particle id (the solver reorders particles by cell).
std::vector<Eigen::Vector3d> startPositions(const fluid::FluidParticles<3>& f) {
  std::vector<Eigen::Vector3d> r0(f.size());
  for (std::size_t i = 0; i < f.size(); ++i) r0[f.id[i]] = toEigen(f.r[i]);
  return r0;
}

void printWhereTheFluidMoved(const fluid::FluidParticles<3>& f, const std::vector<Eigen::Vector3d>& r0,
                             const cases::TetheredBuoyTank& tank, const cases::TetheredBuoyScene& scene,
                             const Eigen::Vector3d& centre) {
  const char* names[5] = {"next to the sphere", "top layer", "side walls", "floor", "bulk"};
  double dy[5] = {0}, work[5] = {0};
  int n[5] = {0};
  const double band = 2.5 * tank.dx;
  for (std::size_t i = 0; i < f.size(); ++i) {
    const Eigen::Vector3d q0 = r0[f.id[i]];
    const double wall = std::min({q0[0], q0[2], tank.length - q0[0], tank.width - q0[2]});
    const int g = (q0 - centre).norm() < tank.buoy.radius + band ? 0
                  : q0[1] > scene.still_level - band            ? 1
                  : wall < band                                  ? 2
                  : q0[1] < band                                 ? 3
                                                                 : 4;
    const double d = f.r[i][1] - q0[1];
    dy[g] += d;
    work[g] += f.m[i] * tank.buoy.g * d;
    ++n[g];
  }
  for (int g = 0; g < 5; ++g)
    std::printf("# %s: %d particles, mean rise %+.3f mm, potential energy change %+.3f J\n", names[g], n[g],
                n[g] ? 1e3 * dy[g] / n[g] : 0.0, work[g]);
}

}  // namespace

int main(int argc, char** argv) {
  cases::TetheredBuoyTank tank;
  tank.release = cases::BuoyRelease::Rest;
  tank.dx = 2.0 * tank.buoy.radius / argOr(argc, argv, 1, 6.0);
  tank.length = tank.width = std::round(0.6 / tank.dx) * tank.dx;  // symmetric about the buoy
  tank.depth = 0.4;
  tank.cfl = argOr(argc, argv, 2, tank.cfl);
  tank.sound_speed_factor = argOr(argc, argv, 3, tank.sound_speed_factor);
  tank.density_diffusion = argOr(argc, argv, 4, 1.0) != 0.0;
  const double t0 = 0.3, end = t0 + argOr(argc, argv, 5, 4.0);
  tank.release_time = argOr(argc, argv, 6, t0);
  tank.settling_damping = argOr(argc, argv, 7, 0.0);
  if (argOr(argc, argv, 8, 0.0) != 0.0) tank.density_diffusion_form = fluid::DensityDiffusionForm::Renormalised;
  tank.mirror_floor = argOr(argc, argv, 9, 0.0) != 0.0;
  tank.h_factor = argOr(argc, argv, 10, tank.h_factor);
  tank.b_off = argOr(argc, argv, 11, tank.b_off);
  tank.boundary_h_factor = argOr(argc, argv, 12, tank.boundary_h_factor);
  if (argOr(argc, argv, 13, 0.0) != 0.0) tank.boundary_force = fluid::BoundaryForceForm::Conservative;
  tank.mirror_walls = argOr(argc, argv, 14, 0.0) != 0.0;
  auto scene = cases::buildTetheredBuoy(tank);
  auto& co = *scene.co;
  const std::vector<Eigen::Vector3d> r0 = startPositions(co.fluid().fluid());
  double work_sway = 0.0, work_turn = 0.0, next = 0.0, before = co.time();
  std::printf("# t_s tilt_x_deg tilt_z_deg sway_x_mm sway_z_mm Fx_N Fz_N Fy_N Mx_Nm Mz_Nm work_sway_J work_turn_J "
              "kinetic_J potential_J elastic_J heave_mm\n");
  // The 1 mm test's measure (tests/coupling/test_lab_buoy_rest.cpp): the mean pose over
  // 1-2 s after release against the mean over 4-5 s.
  Eigen::Vector3d early = Eigen::Vector3d::Zero(), late = Eigen::Vector3d::Zero();
  int n_early = 0, n_late = 0;
  while (co.time() < end) {
    const auto k0 = co.bodies().kinematics(0);
    co.step();
    const double dt = co.time() - before;
    before = co.time();
    // Held, nothing is applied: report the fluid's wrench on the held buoy all the same.
    const bool held = co.time() <= tank.release_time;
    const auto& w = held ? co.coupling().fluidWrench(0) : co.coupling().appliedWrench(0);
    const auto k = co.bodies().kinematics(0);
    Eigen::Vector3d horizontal = w.force;
    horizontal[1] = 0.0;
    work_sway += horizontal.dot(0.5 * (k.velocity + k0.velocity)) * dt;
    work_turn += w.torque.dot(0.5 * (k.angularVelocity + k0.angularVelocity)) * dt;
    const double since = co.time() - tank.release_time;
    if (since > 1.0 && since <= 2.0) early += k.position, ++n_early;
    if (since > 4.0 && since <= 5.0) late += k.position, ++n_late;
    if (co.time() < next) continue;
    next += 0.02;
    const Eigen::Vector3d axis = k.orientation * Eigen::Vector3d::UnitY();
    const auto e = co.calcEnergy();
    const double deg = 180.0 / std::acos(-1.0);
    std::printf("%.3f %+.4f %+.4f %+.3f %+.3f %+.4f %+.4f %.3f %+.2e %+.2e %+.3e %+.3e %.4e %.5e %.4e %+.3f\n", co.time() - t0,
                std::asin(axis[2]) * deg, -std::asin(axis[0]) * deg, 1e3 * (k.position[0] - scene.rest[0]),
                1e3 * (k.position[2] - scene.rest[2]), w.force[0], w.force[2], w.force[1], w.torque[0], w.torque[2],
                work_sway, work_turn, e.fluid_kinetic, e.fluid_potential, e.fluid_elastic,
                1e3 * (k.position[1] - scene.rest[1]));
  }
  if (n_early > 0 && n_late > 0) {
    const Eigen::Vector3d drift = late / n_late - early / n_early;
    std::printf("# drift of the mean pose, 1-2 s -> 4-5 s after release: (%.3f, %.3f, %.3f) mm = %.3f mm\n",
                1e3 * drift[0], 1e3 * drift[1], 1e3 * drift[2], 1e3 * drift.norm());
  }
  printWhereTheFluidMoved(co.fluid().fluid(), r0, tank, scene, co.bodies().kinematics(0).position);
}
