#include <moorsph/coupling/wall_contact.hpp>

#include <algorithm>
#include <cmath>

namespace moorsph::coupling {

template <int D>
WallContact<D>::WallContact(const fluid::Walls<D>& walls, double particle_mass, double h)
    : walls_(walls), mass_(particle_mass), reach_(2.0 * h) {
  const auto& b = walls_.particles();
  for (std::size_t k = 0; k < b.size(); ++k)
    if (!walls_.surfaces()[b.surface[k]].movable) fixed_.push_back(k);
}

template <int D>
bodies::BodyWrench WallContact<D>::wrench(std::size_t surface, const fluid::Vec<D>& origin) const {
  bodies::BodyWrench w;
  const auto& b = walls_.particles();
  const auto [first, last] = walls_.surfaceRange(surface);
  if (first == last) return w;
  // The fixed wall particles inside the body particles' bounding box grown by the law's
  // reach. A box, not a sphere about the origin: the 3 m ship's sphere took in 804 floor
  // particles 120 m below the keel, each tried against each of its 3,770 hull particles
  // every step; its box ends above the floor and takes in none.
  const double reach = reach_;
  fluid::Vec<D> lower = b.r[first], upper = b.r[first];
  for (std::size_t p = first; p < last; ++p) {
    lower = lower.cwiseMin(b.r[p]);
    upper = upper.cwiseMax(b.r[p]);
  }
  lower.array() -= reach;
  upper.array() += reach;
  std::vector<std::size_t> near;
  for (std::size_t k : fixed_)
    if ((b.r[k].array() >= lower.array()).all() && (b.r[k].array() <= upper.array()).all()) near.push_back(k);
  if (near.empty()) return w;
  for (std::size_t p = first; p < last; ++p) {
    fluid::Vec<D> f = fluid::Vec<D>::Zero();
    for (std::size_t k : near) {
      const fluid::Vec<D> r = b.r[p] - b.r[k];
      if (r.squaredNorm() < reach * reach) f += mass_ * walls_.law().acceleration(r, b, k);
    }
    if (f.isZero()) continue;
    Eigen::Vector3d force = Eigen::Vector3d::Zero(), arm = Eigen::Vector3d::Zero();
    force.head<D>() = f;
    arm.head<D>() = b.r[p] - origin;
    w.force += force;
    w.torque += arm.cross(force);
  }
  return w;
}

template class WallContact<2>;
template class WallContact<3>;

}  // namespace moorsph::coupling
