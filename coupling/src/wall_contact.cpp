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
  // Bounding sphere of the body's particles about its origin, then the fixed wall
  // particles within it plus the law's reach.
  double radius2 = 0.0;
  for (std::size_t p = first; p < last; ++p) radius2 = std::max(radius2, (b.r[p] - origin).squaredNorm());
  const double reach = reach_;
  const double r_max = std::sqrt(radius2) + reach;
  std::vector<std::size_t> near;
  for (std::size_t k : fixed_)
    if ((b.r[k] - origin).squaredNorm() <= r_max * r_max) near.push_back(k);
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
