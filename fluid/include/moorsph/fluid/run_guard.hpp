#pragma once
// Runtime guards (issue 8, item 4): the checks that stop a run that has gone wrong,
// and the diagnostic that names the particle, the time and the likely cause.
//
// The likely causes follow from the weakly-compressible method's own limits
// (METHOD.md sections 1-2):
//  - a particle through a wall: the wall force scale is 0.01 c_s^2 m/h, sized to stop
//    particles moving at up to the design speed c_s/10; a faster particle, a moving
//    surface faster than that, or boundary particles sparser than dx let it through;
//  - a non-positive density: the continuity equation lets a splash or a free surface
//    that is pulled apart go into tension until rho crosses zero; density diffusion
//    (method option) removes the noise that starts it;
//  - a particle faster than method.max_speed_fraction x c_s (default c_s/2): flung by
//    a numerical fault, most often a particle that got behind a boundary surface
//    through a gap in its particles and was thrown out by the wall force;
//  - a collapsing time step: dt = force_dt_factor sqrt(h/|a|) falls when some particle
//    is squeezed (a flow faster than c_s/10 compresses the fluid far beyond the 1%
//    of the weakly-compressible range; or a wall/body closes on a particle).
#include <cstddef>
#include <string>
#include <moorsph/fluid/boundary_particles.hpp>
#include <moorsph/fluid/fluid_particles.hpp>
#include <moorsph/fluid/fluid_setup.hpp>
#include <moorsph/fluid/walls.hpp>

namespace moorsph::fluid {

/// What the guards need to know about the run besides the particles.
template <int D>
struct GuardContext {
  const FluidSetup<D>& setup;
  const Walls<D>* walls;  ///< null when the scene has no walls
  double time;            ///< [s]
  std::size_t step;
};

/// Index of the first fluid particle with a non-finite state, outside the domain, with
/// rho <= 0 or faster than max_speed (0: no speed limit); fluid.size() if there is none.
template <int D>
std::size_t findUnhealthyParticle(const FluidParticles<D>& fluid, const Domain<D>& domain, double max_speed = 0.0);

/// Index of the fluid particle with the largest |dv/dt| (the one that sets the force
/// bound on dt).
template <int D>
std::size_t findLargestAcceleration(const FluidParticles<D>& fluid);

/// Message for particle i that failed findUnhealthyParticle (with the speed limit
/// method.max_speed_fraction x c_s): what, where, when, and the likely cause.
template <int D>
std::string describeUnhealthyParticle(const FluidParticles<D>& fluid, std::size_t i, const GuardContext<D>& ctx);

/// Message for a time step `dt` that fell below min_dt_fraction x cfl_dt, naming the
/// particle with the largest acceleration and the likely cause.
template <int D>
std::string describeDtCollapse(const FluidParticles<D>& fluid, double dt, double cfl_dt, const GuardContext<D>& ctx);

}  // namespace moorsph::fluid
