#include <moorsph/coupling/body_guard.hpp>

#include <sstream>
#include <moorsph/fluid/fluid_simulation.hpp>

namespace moorsph::coupling {
namespace {

void describeBody(std::ostream& os, const bodies::BodyKinematics& k, const std::string& name, int body, double t) {
  os << " body '" << name << "' (body " << body << ") at t = " << t << " s: position (" << k.position.transpose()
     << ") m, velocity (" << k.velocity.transpose() << ") m/s";
}

}  // namespace

template <int D>
void checkBodiesInDomain(const bodies::MultibodySystem& system, const fluid::Walls<D>& walls,
                         const std::vector<CoupledBody>& links, const fluid::Domain<D>& domain, double sound_speed,
                         bool wall_contact, double t) {
  for (const CoupledBody& l : links) {
    const bodies::BodyKinematics k = system.kinematics(l.body);
    const std::string& name = walls.surfaces()[l.surface].name;
    std::ostringstream os;
    if (!k.position.allFinite() || !k.velocity.allFinite() || !k.angularVelocity.allFinite() ||
        !k.orientation.coeffs().allFinite()) {
      os << "non-finite state of";
      describeBody(os, k, name, l.body, t);
      os << ". Likely cause: the body integrator diverged, e.g. a mooring stiffer than the body's internal step "
            "resolves, or a fluid force that blew up first (check the fluid diagnostics of the previous outputs)";
      throw fluid::SimulationError(os.str());
    }
    const auto [first, last] = walls.surfaceRange(l.surface);
    for (std::size_t p = first; p < last; ++p) {
      const fluid::Vec<D>& r = walls.particles().r[p];
      if (domain.contains(r)) continue;
      const double speed = k.velocity.norm();
      os << "a coupled body left the domain:";
      describeBody(os, k, name, l.body, t);
      os << "; its surface point (" << r.transpose() << ") m is outside the domain (" << domain.lower.transpose()
         << ") .. (" << domain.upper.transpose() << ") m. Likely cause: ";
      if (speed > 0.1 * sound_speed)
        os << "the body moves at " << speed << " m/s, faster than c_s/10 = " << 0.1 * sound_speed
           << " m/s, so the fluid cannot cushion it; raise sound_speed or check its initial velocity and forces";
      else if (!wall_contact)
        os << "body-wall contact is off (CouplingOptions::wall_contact), so a body driven onto a wall or the floor "
              "(heavier than water, pulled by a mooring, or thrown by a wave) passes through once the fluid is "
              "squeezed out; turn contact on, or check its mass, moorings and position";
      else
        os << "the body was driven into a wall harder than the wall-contact force (the wall law acting on each "
              "surface particle as on a fluid particle) can stop, e.g. by a mooring or a load far above its weight; "
              "check its mass, moorings and initial velocity";
      throw fluid::SimulationError(os.str());
    }
  }
}

template void checkBodiesInDomain<2>(const bodies::MultibodySystem&, const fluid::Walls<2>&,
                                     const std::vector<CoupledBody>&, const fluid::Domain<2>&, double, bool, double);
template void checkBodiesInDomain<3>(const bodies::MultibodySystem&, const fluid::Walls<3>&,
                                     const std::vector<CoupledBody>&, const fluid::Domain<3>&, double, bool, double);

}  // namespace moorsph::coupling
