#pragma once
// The "bodies" fluid effect: two-way coupling of rigid bodies (bodies/, Simbody)
// with the boundary surfaces that represent them in the fluid (DESIGN.md section 2).
//
// Per fluid step (the fluid's predictor-corrector calls advanceTo at each stage):
//   Start      surfaces placed at the bodies' current kinematics.
//   Predicted  surfaces placed at the pose extrapolated to the predicted time from the
//              bodies' current velocity and angular velocity (rigid, first order).
//              The fluid then evaluates its rates, and the walls effect sums each
//              tracked surface's reactions: the wrench of the predicted state.
//   Corrected  that wrench (force, and torque about the body origin) is held constant
//              while Simbody advances to t + dt in as many internal steps as it needs;
//              the surfaces are then placed at the new kinematics for the evaluation
//              that starts the next step.
// Where the lag sits: the fluid sees the bodies at an extrapolated pose during the
// predicted evaluation (error O(a dt^2)), and the bodies see a wrench that is
// constant over the step (zero-order hold of the predicted-state force). Nothing
// lags by a whole step.
//
// Before `release_time` the bodies are held where the scene put them (the fluid
// settles around them); Simbody's clock starts at release. Over `ramp_time` after
// release the fluid wrench is ramped up smoothly (half-cosine) from zero.
#include <chrono>
#include <optional>
#include <vector>
#include <moorsph/bodies/multibody_system.hpp>
#include <moorsph/coupling/wall_contact.hpp>
#include <moorsph/fluid/fluid_setup.hpp>
#include <moorsph/fluid/domain.hpp>
#include <moorsph/fluid/walls.hpp>

namespace moorsph::coupling {

/// Which fluid boundary surface represents which body. The surface must be movable,
/// with its reference point at the body's origin, and track reactions.
struct CoupledBody {
  int body = 0;
  std::size_t surface = 0;
};

struct CouplingOptions {
  double release_time = 0.0;  ///< bodies held until this fluid time [s]
  double ramp_time = 0.0;     ///< fluid wrench ramped from 0 to 1 over this time after release [s]
  /// Bodies touching fixed walls are pushed back by the wall force law (wall_contact.hpp);
  /// without it a body heavier than water sinks through the floor.
  bool wall_contact = true;
};

template <int D>
class BodyCoupling final : public fluid::FluidEffect<D> {
 public:
  /// Throws std::invalid_argument if walls is null, or a surface is not movable or
  /// does not track reactions.
  BodyCoupling(bodies::MultibodySystem& system, fluid::Walls<D>* walls, std::vector<CoupledBody> links,
               CouplingOptions options);

  const char* name() const override { return "bodies"; }
  void addRates(fluid::FluidContext<D>&) override {}
  void advanceTo(double t, fluid::StepStage stage) override;

  /// The fluid wrench last applied to link k (ground frame, torque about the body origin):
  /// zero while the bodies are held, ramped after release, wall contact included.
  const bodies::BodyWrench& appliedWrench(std::size_t k) const { return applied_.at(k); }
  /// The fluid's own wrench on link k at the last corrector (the reactions of its surface,
  /// unramped, without wall contact). Kept during the hold too, where it is the load the
  /// hold restrains: a held body's buoyancy can be read while the water settles round it.
  const bodies::BodyWrench& fluidWrench(std::size_t k) const { return fluid_.at(k); }
  double bodySeconds() const { return body_seconds_; }        ///< wall time in Simbody
  double exchangeSeconds() const { return exchange_seconds_; }  ///< wall time in the exchange
  const CouplingOptions& options() const { return options_; }
  /// What the coupling takes from the fluid's setup (CoSimulation calls it): the domain
  /// and sound speed of the runtime guard (body_guard.hpp: after every body step a body
  /// outside the domain, or with a non-finite state, stops the run) and, if
  /// options.wall_contact, the scales of body-wall contact (wall_contact.hpp).
  void useFluidSetup(const fluid::FluidSetup<D>& setup);

 private:
  void placeSurfaces(double t, bool extrapolate);
  void sumFluidWrenches();
  void applyFluidWrenches(double t);
  double ramp(double t) const;

  bodies::MultibodySystem& system_;
  fluid::Walls<D>* walls_;
  std::vector<CoupledBody> links_;
  CouplingOptions options_;
  std::vector<bodies::BodyWrench> applied_;
  std::vector<bodies::BodyWrench> fluid_;
  double body_seconds_ = 0.0;
  double exchange_seconds_ = 0.0;
  std::optional<fluid::Domain<D>> guard_domain_;
  double guard_sound_speed_ = 0.0;
  std::optional<WallContact<D>> contact_;
};

/// bodies kinematics -> the fluid's rigid motion (2D: the x-y components and the
/// rotation about z), optionally extrapolated rigidly by `tau` seconds.
template <int D>
fluid::RigidMotion<D> toRigidMotion(const bodies::BodyKinematics& k, double tau = 0.0);

}  // namespace moorsph::coupling
