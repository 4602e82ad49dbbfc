#include <moorsph/fluid/piston.hpp>

#include <stdexcept>

namespace moorsph::fluid {

template <int D>
Piston<D>::Piston(Walls<D>* walls, std::size_t surface, Signal displacement, Signal velocity)
    : walls_(walls), surface_(surface), displacement_(std::move(displacement)), velocity_(std::move(velocity)) {
  if (!walls_) throw std::invalid_argument("effects: 'piston' needs 'walls' (the piston is a wall surface)");
  origin_ = walls_->surfaceMotion(surface_).position;  // throws if the surface is not movable
}

template <int D>
void Piston<D>::advanceTo(double t, StepStage stage) {
  if (stage == StepStage::Start) last_t_ = t;
  if (stage == StepStage::Corrected) {
    if (walls_->surfaces()[surface_].track_reaction)
      work_ += (t - last_t_) * velocity_(t) * -walls_->calcSurfaceWrench(surface_, Vec<D>::Zero()).force[0];
    last_t_ = t;
  }
  x_ = displacement_(t);
  Vec<D> offset = origin_;
  offset[0] += x_;
  Vec<D> speed = Vec<D>::Zero();
  speed[0] = velocity_(t);
  walls_->setSurfaceMotion(surface_, RigidMotion<D>::translation(offset, speed));
}

template class Piston<2>;
template class Piston<3>;

}  // namespace moorsph::fluid
