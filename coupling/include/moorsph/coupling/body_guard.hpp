#pragma once
// Runtime guard for coupled bodies (issue 8, item 4): a body whose state turned
// non-finite, or whose surface left the fluid domain (the tank plus a margin of 2h),
// stops the run with a fluid::SimulationError naming the body, the time and the
// likely cause, so the run's driver writes its failure checkpoint and flushes output
// as for a fluid failure.
#include <vector>
#include <moorsph/bodies/multibody_system.hpp>
#include <moorsph/coupling/body_coupling.hpp>
#include <moorsph/fluid/domain.hpp>
#include <moorsph/fluid/walls.hpp>

namespace moorsph::coupling {

/// Throws fluid::SimulationError for the first link whose body state is non-finite or
/// whose surface has a point outside `domain` (bounded directions only). The likely
/// cause named depends on the body's speed against c_s/10 and on whether body-wall
/// contact (wall_contact.hpp) is on.
template <int D>
void checkBodiesInDomain(const bodies::MultibodySystem& system, const fluid::Walls<D>& walls,
                         const std::vector<CoupledBody>& links, const fluid::Domain<D>& domain, double sound_speed,
                         bool wall_contact, double t);

}  // namespace moorsph::coupling
