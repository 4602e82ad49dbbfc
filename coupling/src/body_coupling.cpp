#include <moorsph/coupling/body_coupling.hpp>
#include <moorsph/coupling/body_guard.hpp>
#include <moorsph/fluid/fluid_simulation.hpp>

#include <cmath>
#include <stdexcept>
#include <string>

namespace moorsph::coupling {
namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

template <int D>
fluid::RigidMotion<D> toRigidMotion(const bodies::BodyKinematics& k, double tau) {
  Eigen::Quaterniond q = k.orientation;
  const double w = k.angularVelocity.norm();
  if (tau != 0.0 && w > 0.0) q = Eigen::Quaterniond(Eigen::AngleAxisd(w * tau, k.angularVelocity / w)) * q;
  const Eigen::Vector3d position = k.position + tau * k.velocity;
  fluid::RigidMotion<D> m;
  m.position = position.template head<D>();
  m.rotation = q.normalized().toRotationMatrix().template topLeftCorner<D, D>();
  m.velocity = k.velocity.template head<D>();
  m.angular_velocity = k.angularVelocity;
  return m;
}

template <int D>
BodyCoupling<D>::BodyCoupling(bodies::MultibodySystem& system, fluid::Walls<D>* walls, std::vector<CoupledBody> links,
                              CouplingOptions options)
    : system_(system), walls_(walls), links_(std::move(links)), options_(options), applied_(links_.size()), fluid_(links_.size()) {
  if (!walls_) throw std::invalid_argument("effects: 'bodies' needs 'walls' (bodies are boundary surfaces)");
  if (!system_.isInitialized()) throw std::invalid_argument("bodies: initialize() the multibody system first");
  for (const CoupledBody& l : links_) {
    if (l.surface >= walls_->surfaces().size()) throw std::invalid_argument("bodies: unknown surface index");
    const auto& info = walls_->surfaces()[l.surface];
    if (!info.movable || !info.track_reaction)
      throw std::invalid_argument("bodies: surface '" + info.name + "' must be movable and track reactions");
    if (l.body < 0 || l.body >= system_.bodyCount()) throw std::invalid_argument("bodies: unknown body index");
  }
}

template <int D>
void BodyCoupling<D>::useFluidSetup(const fluid::FluidSetup<D>& setup) {
  guard_domain_ = setup.domain;
  guard_sound_speed_ = setup.sound_speed;
  if (options_.wall_contact) contact_.emplace(*walls_, setup.rho0 * std::pow(setup.dx, D), setup.h());
}

template <int D>
double BodyCoupling<D>::ramp(double t) const {
  const double s = t - options_.release_time;
  if (options_.ramp_time <= 0.0 || s >= options_.ramp_time) return 1.0;
  if (s <= 0.0) return 0.0;
  return 0.5 * (1.0 - std::cos(3.14159265358979323846 * s / options_.ramp_time));
}

template <int D>
void BodyCoupling<D>::placeSurfaces(double t, bool extrapolate) {
  const double body_time = options_.release_time + system_.time();
  const double tau = (extrapolate && t > options_.release_time) ? t - body_time : 0.0;
  for (const CoupledBody& l : links_) walls_->setSurfaceMotion(l.surface, toRigidMotion<D>(system_.kinematics(l.body), tau));
}

template <int D>
void BodyCoupling<D>::sumFluidWrenches() {
  for (std::size_t k = 0; k < links_.size(); ++k) {
    const fluid::SurfaceWrench w =
        walls_->calcSurfaceWrench(links_[k].surface, walls_->surfaceMotion(links_[k].surface).position);
    fluid_[k].force = w.force;
    fluid_[k].torque = w.torque;
  }
}

template <int D>
void BodyCoupling<D>::applyFluidWrenches(double t) {
  const double factor = ramp(t);
  for (std::size_t k = 0; k < links_.size(); ++k) {
    const auto& origin = walls_->surfaceMotion(links_[k].surface).position;
    applied_[k].force = factor * fluid_[k].force;
    applied_[k].torque = factor * fluid_[k].torque;
    if (contact_) {
      const bodies::BodyWrench c = contact_->wrench(links_[k].surface, origin);
      applied_[k].force += c.force;
      applied_[k].torque += c.torque;
    }
    system_.setExternalWrench(links_[k].body, applied_[k]);
  }
}

template <int D>
void BodyCoupling<D>::advanceTo(double t, fluid::StepStage stage) {
  const auto start = std::chrono::steady_clock::now();
  switch (stage) {
    case fluid::StepStage::Start:
      placeSurfaces(t, false);
      break;
    case fluid::StepStage::Predicted:
      placeSurfaces(t, true);
      break;
    case fluid::StepStage::Corrected: {
      sumFluidWrenches();
      if (t <= options_.release_time) break;  // held: the fluid settles around the bodies
      applyFluidWrenches(t);
      const auto simbody_start = std::chrono::steady_clock::now();
      try {
        system_.advanceTo(t - options_.release_time);
      } catch (const fluid::SimulationError&) {
        throw;
      } catch (const std::runtime_error& e) {
        // E.g. the integrator's work bound (bodies/src/system_core.cpp): stop the run as
        // for a fluid failure, so the driver writes its failure checkpoint and output.
        throw fluid::SimulationError("at t = " + std::to_string(t) + " s: " + e.what());
      }
      body_seconds_ += secondsSince(simbody_start);
      placeSurfaces(t, false);
      if (guard_domain_) checkBodiesInDomain(system_, *walls_, links_, *guard_domain_, guard_sound_speed_, contact_.has_value(), t);
      break;
    }
  }
  exchange_seconds_ += secondsSince(start);
}

template class BodyCoupling<2>;
template class BodyCoupling<3>;
template fluid::RigidMotion<2> toRigidMotion<2>(const bodies::BodyKinematics&, double);
template fluid::RigidMotion<3> toRigidMotion<3>(const bodies::BodyKinematics&, double);

}  // namespace moorsph::coupling
