#include <moorsph/coupling/green_water.hpp>

#include <stdexcept>

namespace moorsph::coupling {

bool insideOutline(const std::vector<Eigen::Vector2d>& polygon, double x, double z) {
  bool inside = false;
  const std::size_t n = polygon.size();
  for (std::size_t a = 0, b = n - 1; a < n; b = a++) {
    const Eigen::Vector2d& p = polygon[a];
    const Eigen::Vector2d& q = polygon[b];
    // Edge (q, p) crosses the line z = const to the right of x: flip (even-odd rule).
    if ((p[1] > z) != (q[1] > z) && x < q[0] + (p[0] - q[0]) * (z - q[1]) / (p[1] - q[1])) inside = !inside;
  }
  return inside;
}

template <int D>
double greenWaterVolume(const fluid::FluidParticles<D>& fluid, const bodies::BodyKinematics& body,
                        const DeckOutline& deck) {
  if (D == 3 && deck.outline.size() < 3) throw std::invalid_argument("green water: a deck outline needs 3 or more vertices");
  if (D == 2 && deck.outline.size() != 2) throw std::invalid_argument("green water: a 2D deck is an interval [x_min, x_max]");
  const Eigen::Matrix3d to_body = body.orientation.toRotationMatrix().transpose();
  double volume = 0.0;
  const std::size_t n = fluid.size();
#pragma omp parallel for schedule(static) reduction(+ : volume)
  for (std::size_t i = 0; i < n; ++i) {
    Eigen::Vector3d r = Eigen::Vector3d::Zero();
    r.template head<D>() = fluid.r[i];
    const Eigen::Vector3d q = to_body * (r - body.position);
    if (q[1] <= deck.deck_height) continue;
    const bool over = D == 2 ? q[0] >= deck.outline[0][0] && q[0] <= deck.outline[1][0]
                             : insideOutline(deck.outline, q[0], q[2]);
    if (over) volume += fluid.m[i] / fluid.rho[i];
  }
  return volume;
}

template double greenWaterVolume<2>(const fluid::FluidParticles<2>&, const bodies::BodyKinematics&, const DeckOutline&);
template double greenWaterVolume<3>(const fluid::FluidParticles<3>&, const bodies::BodyKinematics&, const DeckOutline&);

}  // namespace moorsph::coupling
