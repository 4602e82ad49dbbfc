#include <moorsph/fluid/fluid_simulation.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <moorsph/fluid/gravity.hpp>
#include <moorsph/fluid/mirror_reflection.hpp>
#include <moorsph/fluid/particle_shifting.hpp>
#include <moorsph/fluid/run_guard.hpp>

namespace moorsph::fluid {
namespace {

const char* const kKnownEffects[] = {"pressure", "viscosity", "xsph", "density_diffusion", "gravity", "walls", "particle_shifting",
                                     "mirror_floor", "mirror_walls", "outflow"};

void checkSetup(const std::vector<std::string>& effects) {
  for (const auto& e : effects) {
    if (std::find(std::begin(kKnownEffects), std::end(kKnownEffects), e) == std::end(kKnownEffects)) {
      std::string known;
      for (const char* k : kKnownEffects) known += std::string(known.empty() ? "" : ", ") + k;
      throw std::invalid_argument("effects: unknown effect '" + e + "' (known: " + known + ")");
    }
  }
}

}  // namespace

template <int D>
FluidSimulation<D>::FluidSimulation(FluidSetup<D> setup, FluidParticles<D> fluid, BoundaryGeometry<D> boundary)
    : setup_(std::move(setup)),
      fluid_(std::move(fluid)),
      kernel_(setup_.h()),
      eos_(setup_.rho0, setup_.sound_speed, setup_.method.gamma),
      neighbours_(setup_.domain, 2.0 * setup_.h(), setup_.method.skin_factor * 2.0 * setup_.h()) {
  if (!(setup_.dx > 0.0)) throw std::invalid_argument("dx must be positive");
  if (!(setup_.sound_speed > 0.0)) throw std::invalid_argument("sound_speed must be positive");
  if (fluid_.size() == 0) throw std::invalid_argument("the scene has no fluid particles");
  checkSetup(setup_.effects);
  pairs_ = makePairForces(setup_);
  buildEffects(std::move(boundary));
  phase_neighbours_ = timers_.add("neighbours");
  phase_pairs_ = timers_.add("pairs");
  for (const auto& e : effects_) phase_effects_.push_back(timers_.add(e->name()));
  if (outflow_) phase_outflow_ = timers_.add("outflow");
  phase_integrate_ = timers_.add("integrate");
  phase_checks_ = timers_.add("checks");
  fluid_.allocateWorkArrays();
  const double visc_speed = 2.0 * setup_.method.viscosity_xi * setup_.mu / (setup_.h() * setup_.rho0);
  cfl_dt_ = setup_.method.cfl * setup_.h() / (setup_.sound_speed + visc_speed);
}

template <int D>
void FluidSimulation<D>::buildEffects(BoundaryGeometry<D> boundary) {
  if (setup_.has("gravity")) effects_.push_back(std::make_unique<Gravity<D>>(setup_.gravity));
  if (!setup_.mirrorPlanes().empty()) effects_.push_back(std::make_unique<MirrorReflection<D>>(setup_.mirrorPlanes()));
  if (setup_.has("walls")) {
    auto walls = std::make_unique<Walls<D>>(std::move(boundary), setup_);
    walls_ = walls.get();
    effects_.push_back(std::move(walls));
  } else if (!boundary.empty()) {
    throw std::invalid_argument("the scene has boundary surfaces but 'walls' is not in its effects");
  }
  // After the pair forces and walls: it adds to the transport velocity they leave.
  if (setup_.has("particle_shifting"))
    effects_.push_back(std::make_unique<ParticleShifting<D>>(setup_.method.shifting, setup_.dx, setup_.h(),
                                                             walls_ ? &walls_->particles() : nullptr));
  if (setup_.has("outflow")) {
    if (!walls_) throw std::invalid_argument("effect 'outflow' needs 'walls' (water counts as gone once it is over them)");
    const WallExtent<D> extent = walls_->staticExtent(0.5 * setup_.dx);
    if (extent.empty())
      throw std::invalid_argument("effect 'outflow' needs a static wall (a tank) to tell water that went over it");
    outflow_ = std::make_unique<Outflow<D>>(extent, 0.5 * setup_.sound_speed);
  }
}

template <int D>
void FluidSimulation<D>::addEffect(std::unique_ptr<FluidEffect<D>> effect) {
  phase_effects_.push_back(timers_.add(effect->name()));
  effects_.push_back(std::move(effect));
  rates_current_ = false;
}

template <int D>
std::vector<std::string> FluidSimulation<D>::effectNames() const {
  std::vector<std::string> names{"pressure"};
  for (const char* term : {"viscosity", "xsph", "density_diffusion", "mirror_floor", "mirror_walls"})
    if (setup_.has(term)) names.emplace_back(term);
  for (const auto& e : effects_) names.emplace_back(e->name());
  if (outflow_) names.emplace_back("outflow");
  return names;
}

template <int D>
void FluidSimulation<D>::evaluateRates(double t, bool may_rebuild) {
  const BoundaryParticles<D>* boundary = walls_ ? &walls_->particles() : nullptr;
  if (may_rebuild) {
    PhaseTimers::Scope timing(timers_, phase_neighbours_);
    double vmax2 = 0.0;
    const std::size_t n = fluid_.size();
#pragma omp parallel for schedule(static) reduction(max : vmax2)
    for (std::size_t i = 0; i < n; ++i) vmax2 = std::max(vmax2, fluid_.v[i].squaredNorm());
    // Travel bound for the coming step; XSPH can exceed |v| a little, hence the margin.
    // Moving surfaces add their own speed (two particles approach at most at the sum).
    const double wall_speed = walls_ ? walls_->maxMovingSpeed() : 0.0;
    const double travel = 1.5 * (std::sqrt(vmax2) + wall_speed) * cfl_dt_;
    if (rebuild_requested_ || neighbours_.needsRebuild(fluid_, boundary, travel))
      neighbours_.rebuild(fluid_, boundary, walls_ ? walls_->trackedMask() : no_tracking_);
    rebuild_requested_ = false;
  }
  FluidContext<D> ctx{fluid_, neighbours_, kernel_, eos_, setup_, t};
  {
    PhaseTimers::Scope timing(timers_, phase_pairs_);
    pairs_->evaluate(ctx);
  }
  total_interactions_ += pairs_->lastInteractions();
  for (std::size_t k = 0; k < effects_.size(); ++k) {
    PhaseTimers::Scope timing(timers_, phase_effects_[k]);
    effects_[k]->addRates(ctx);
  }
  rates_current_ = true;
}

template <int D>
void FluidSimulation<D>::restoreNeighbourLists(const std::vector<Vec<D>>& fluid_at_build,
                                              const std::vector<Vec<D>>& boundary_at_build) {
  PhaseTimers::Scope timing(timers_, phase_neighbours_);
  const BoundaryParticles<D>* boundary = walls_ ? &walls_->particles() : nullptr;
  neighbours_.restore(fluid_, fluid_at_build, boundary, boundary_at_build,
                      walls_ ? walls_->trackedMask() : no_tracking_);
  rebuild_requested_ = false;
  rates_current_ = false;
}

template <int D>
double FluidSimulation<D>::computeDt() const {
  double amax2 = 0.0;
  const std::size_t n = fluid_.size();
#pragma omp parallel for schedule(static) reduction(max : amax2)
  for (std::size_t i = 0; i < n; ++i) amax2 = std::max(amax2, fluid_.dvdt[i].squaredNorm());
  double dt = cfl_dt_;
  if (amax2 > 0.0) dt = std::min(dt, setup_.method.force_dt_factor * std::sqrt(setup_.h() / std::sqrt(amax2)));
  return dt;
}

template <int D>
void FluidSimulation<D>::predict(double dt) {
  FluidParticles<D>& f = fluid_;
  const Domain<D> domain = setup_.domain;
  const std::size_t n = f.size();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    f.r_start[i] = f.r[i];
    f.v_start[i] = f.v[i];
    f.rho_start[i] = f.rho[i];
    f.r[i] = domain.wrap(f.r[i] + dt * f.drdt[i]);
    f.v[i] += dt * f.dvdt[i];
    f.rho[i] += dt * f.drhodt[i];
  }
}

template <int D>
void FluidSimulation<D>::correct(double dt) {
  FluidParticles<D>& f = fluid_;
  const Domain<D> domain = setup_.domain;
  const std::size_t n = f.size();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    f.r[i] = domain.wrap(f.r_start[i] + dt * f.drdt[i]);
    f.v[i] = f.v_start[i] + dt * f.dvdt[i];
    f.rho[i] = f.rho_start[i] + dt * f.drhodt[i];
  }
}

template <int D>
void FluidSimulation<D>::correctSymplectic(double dt) {
  FluidParticles<D>& f = fluid_;
  const Domain<D> domain = setup_.domain;
  const std::size_t n = f.size();
  // The velocity change from the mid-state, v^{n+1} - v*, in f.v for the continuity sum
  // (which is linear in the velocities; mirror images mirror it).
  transport_.resize(n);
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    const Vec<D> v_new = f.v_start[i] + dt * f.dvdt[i];
    transport_[i] = f.drdt[i] - f.v[i];  // the XSPH / shifting part of the transport velocity
    f.v[i] = v_new - f.v[i];
  }
  FluidContext<D> ctx{fluid_, neighbours_, kernel_, eos_, setup_, time_};
  pairs_->continuityRate(ctx, continuity_change_);
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    const Vec<D> v_new = f.v_start[i] + dt * f.dvdt[i];  // recomputed: cheaper than a scratch array
    f.v[i] = v_new;
    f.r[i] = domain.wrap(f.r[i] + 0.5 * dt * (v_new + transport_[i]));
    f.rho[i] += 0.5 * dt * (f.drhodt[i] + continuity_change_[i]);
  }
}

template <int D>
void FluidSimulation<D>::step() {
  if (!rates_current_) {
    for (auto& e : effects_) e->advanceTo(time_, StepStage::Start);
    evaluateRates(time_, true);
  }
  const double dt = computeDt();
  const bool symplectic = setup_.method.integrator == Integrator::Symplectic;
  const double predicted_dt = (symplectic ? 0.5 : setup_.method.predictor_fraction) * dt;
  {
    PhaseTimers::Scope timing(timers_, phase_integrate_);
    predict(predicted_dt);
    for (auto& e : effects_) e->constrain(fluid_, StepStage::Predicted);
  }
  for (auto& e : effects_) e->advanceTo(time_ + predicted_dt, StepStage::Predicted);
  evaluateRates(time_ + predicted_dt, false);
  {
    PhaseTimers::Scope timing(timers_, phase_integrate_);
    if (symplectic) correctSymplectic(dt);
    else correct(dt);
    for (auto& e : effects_) e->constrain(fluid_, StepStage::Corrected);
  }
  time_ += dt;
  dt_ = dt;
  ++steps_;
  for (auto& e : effects_) e->advanceTo(time_, StepStage::Corrected);
  if (outflow_) removeOutflow();
  {
    PhaseTimers::Scope timing(timers_, phase_checks_);
    checkHealth();
  }
  evaluateRates(time_, true);  // the rates that start the next step (and set its dt)
}

template <int D>
void FluidSimulation<D>::advanceTo(double t) {
  while (time_ < t) step();
}

// After a whole step (never between predictor and corrector, whose start-of-step
// arrays must stay aligned): spray that left over the walls is removed. The work
// arrays are resized (an allocation, but only on the rare steps that remove) and the
// neighbour lists rebuilt before the next evaluation.
template <int D>
void FluidSimulation<D>::removeOutflow() {
  PhaseTimers::Scope timing(timers_, phase_outflow_);
  const Vec<D> g = setup_.has("gravity") ? setup_.gravity : Vec<D>::Zero();
  if (outflow_->apply(fluid_, setup_.domain, g, eos_, time_) == 0) return;
  if (fluid_.size() == 0) throw SimulationError("outflow: every fluid particle has left the domain at t = " + std::to_string(time_) + " s");
  fluid_.allocateWorkArrays();
  rebuild_requested_ = true;
}

// Runtime guards (run_guard.hpp): the step just taken is compared with the CFL step,
// then one O(N) pass finds the first particle that is non-finite, outside the domain,
// at rho <= 0 or faster than max_speed_fraction x c_s, and one pass over the fluid-
// boundary list the first that is inside a closed surface (deeper than max_leak_depth x
// dx; skipped on a step whose outflow left the list stale). Each stops the run with
// the particle, time and likely cause named. The step is checked first because a collapsed
// step is the cause of what it flings: the squeezed particle's neighbours leave it at
// more than c_s (tests/stability/test_run_guards.cpp).
template <int D>
void FluidSimulation<D>::checkHealth() const {
  const GuardContext<D> ctx{setup_, walls_, time_, steps_};
  if (dt_ < setup_.method.min_dt_fraction * cfl_dt_)
    throw SimulationError(describeDtCollapse(fluid_, dt_, cfl_dt_, ctx));
  const double max_speed = setup_.method.max_speed_fraction * setup_.sound_speed;
  const std::size_t bad = findUnhealthyParticle(fluid_, setup_.domain, max_speed);
  if (bad < fluid_.size()) throw SimulationError(describeUnhealthyParticle(fluid_, bad, ctx));
  if (walls_ && setup_.method.max_leak_depth > 0.0 && !rebuild_requested_) {
    const LeakedParticle leak = findLeakedParticle(fluid_, *walls_, neighbours_.fluidBoundary(), setup_.domain,
                                                   setup_.method.max_leak_depth * setup_.dx, setup_.dx);
    if (leak.fluid < fluid_.size()) throw SimulationError(describeLeakedParticle(fluid_, leak, ctx));
  }
}

template <int D>
FluidEnergy FluidSimulation<D>::calcEnergy() const {
  double kinetic = 0.0, potential = 0.0, elastic = 0.0;
  const FluidParticles<D>& f = fluid_;
  const std::size_t n = f.size();
  const Vec<D> g = setup_.has("gravity") ? setup_.gravity : Vec<D>::Zero();
#pragma omp parallel for schedule(static) reduction(+ : kinetic, potential, elastic)
  for (std::size_t i = 0; i < n; ++i) {
    kinetic += 0.5 * f.m[i] * f.v[i].squaredNorm();
    potential -= f.m[i] * g.dot(f.r[i]);
    elastic += f.m[i] * eos_.elasticEnergy(f.rho[i]);
  }
  return {kinetic, potential, elastic};
}

template class FluidSimulation<2>;
template class FluidSimulation<3>;

}  // namespace moorsph::fluid
