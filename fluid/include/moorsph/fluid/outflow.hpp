#pragma once
// The "outflow" effect: water that goes over the walls of an open tank leaves the
// simulation instead of stopping it.
//
// Without it, a fluid particle outside the domain stops the run (run_guard.hpp): in a
// closed scene that is a leak through a wall, a numerical failure. In an open tank a
// splash can go over a wall top and out of the domain (SPHERIC Test 2 at dx = 19.6 mm,
// a buoy breaching at D/8: docs/stability.md 3g), or a surge can spill over a low wall;
// that water is physically gone, and a scene that names `outflow` removes it at once.
// A particle is removed when, with a finite state and rho > 0,
//  - it is beyond a static wall (outside the walls' horizontal extent on that side) and
//    above that wall's top: water that went over the wall, not through it (a leak
//    through a wall is below its top), and that cannot fall back in; or it is outside
//    the domain above every wall's top (thrown above the domain's top);
//  - and its speed is below `speed_limit` (half the sound speed): flow speeds are
//    designed to stay near c_s/10 (METHOD.md section 1), and a particle near c_s has
//    been flung by a numerical fault, which the run guard must still report.
// The check runs after every step, so spilled water is removed as it crosses the wall's
// plane, before it can fall below the wall's top outside the tank.
// Everything else that leaves the domain still stops the run with its diagnostic.
// What leaves is tallied (count, mass, and the kinetic + potential + elastic energy it
// carried), so mass and energy ledgers still close.
#include <cstddef>
#include <limits>
#include <moorsph/fluid/domain.hpp>
#include <moorsph/fluid/fluid_particles.hpp>
#include <moorsph/fluid/tait_eos.hpp>
#include <moorsph/fluid/wall_extent.hpp>

namespace moorsph::fluid {

/// What the outflow has removed since the run started (restored from a checkpoint).
struct OutflowTally {
  std::size_t particles = 0;
  double mass = 0.0;    ///< [kg] (2D: kg/m)
  double energy = 0.0;  ///< kinetic + potential (-m g.r) + Tait elastic at removal [J] (2D: J/m)
  double first_time = std::numeric_limits<double>::quiet_NaN();  ///< time of the first removal [s]
};

template <int D>
class Outflow {
 public:
  /// walls: the static walls' extent; speed_limit [m/s]: faster particles are left to the run guard.
  Outflow(const WallExtent<D>& walls, double speed_limit);

  /// Remove every particle that qualifies (see the file comment) from the state arrays,
  /// keeping the others in order. Returns how many were removed; when that is nonzero
  /// the caller must resize the work arrays and rebuild the neighbour lists.
  std::size_t apply(FluidParticles<D>& fluid, const Domain<D>& domain, const Vec<D>& gravity, const TaitEos& eos,
                    double time);

  bool qualifies(const FluidParticles<D>& fluid, std::size_t i, const Domain<D>& domain) const;

  double wallTop() const { return walls_.top(); }
  double speedLimit() const { return speed_limit_; }
  const OutflowTally& tally() const { return tally_; }
  void restoreTally(const OutflowTally& tally) { tally_ = tally; }

 private:
  WallExtent<D> walls_;
  double speed_limit_;
  double lowest_top_;  ///< below it nothing qualifies (the common case, one comparison)
  OutflowTally tally_;
};

}  // namespace moorsph::fluid
