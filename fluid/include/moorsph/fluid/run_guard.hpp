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
//  - a fluid particle inside a closed surface (a body), deeper than
//    method.max_leak_depth x dx behind the faces of its nearest boundary particle: it
//    got through a gap in the surface's particles (or came too fast for the wall force).
//    Caught while it is still slow: the speed guard only sees it once the wall force
//    throws it out (the 6 m ship's bow leak was caught 0.73 s earlier this way);
//  - a collapsing time step: dt = force_dt_factor sqrt(h/|a|) falls when some particle
//    is squeezed (a flow faster than c_s/10 compresses the fluid far beyond the 1%
//    of the weakly-compressible range; or a wall/body closes on a particle).
#include <cstddef>
#include <cstdint>
#include <string>
#include <moorsph/fluid/boundary_particles.hpp>
#include <moorsph/fluid/fluid_particles.hpp>
#include <moorsph/fluid/fluid_setup.hpp>
#include <moorsph/fluid/neighbour_list.hpp>
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

/// A fluid particle found behind a boundary surface by findLeakedParticle.
struct LeakedParticle {
  std::size_t fluid = 0;      ///< index of the fluid particle (the fluid's size if none)
  std::uint32_t boundary = 0;  ///< its nearest boundary particle
  double depth = 0.0;          ///< [m] behind that particle's faces (the least deep of its normals)
};

/// The first fluid particle that has leaked into a closed surface (SurfaceInfo::closed):
/// more than `depth` behind every face of its nearest boundary particle, and behind every
/// face of the surface's other particles up to half a spacing `dx` farther than that one
/// (in front of any one it is outside the surface, beside a part thinner than the
/// spacing). Its index is the fluid's size if there is none. The fluid-boundary list
/// reaches 2h, so the nearest boundary particle within 2h is found; one pass over the
/// list, as the wall force's.
template <int D>
LeakedParticle findLeakedParticle(const FluidParticles<D>& fluid, const Walls<D>& walls,
                                  const NeighbourList& fluid_boundary, const Domain<D>& domain, double depth, double dx);

/// Message for a particle found by findLeakedParticle: what, where, when, which surface
/// and the likely cause.
template <int D>
std::string describeLeakedParticle(const FluidParticles<D>& fluid, const LeakedParticle& leak, const GuardContext<D>& ctx);

/// Message for a time step `dt` that fell below min_dt_fraction x cfl_dt, naming the
/// particle with the largest acceleration and the likely cause.
template <int D>
std::string describeDtCollapse(const FluidParticles<D>& fluid, double dt, double cfl_dt, const GuardContext<D>& ctx);

}  // namespace moorsph::fluid
