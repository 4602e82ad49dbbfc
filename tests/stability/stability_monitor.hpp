#pragma once
// What every stability case asserts (issue 8, item 3), sampled after each step:
//  - no NaN/Inf and no fluid particle through a wall: the particle must stay inside
//    the tank box (x, y, z in [0, size]; no upper bound for an open tank) and outside
//    every body (a body's interior is given as a signed-distance test);
//  - the time step never below `min_dt_ratio` x the CFL step (the step of the fluid
//    at rest, which is the first step of every case);
//  - total energy minus its initial value never above the work injected so far (the
//    case supplies both) plus a stated allowance;
//  - body motion bounded (the case checks its own bodies against the tank).
// The runtime guards (run_guard.hpp) also stop a case with a SimulationError.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <string>
#include <vector>
#include <moorsph/fluid/fluid_simulation.hpp>

namespace moorsph::stability {

/// Integral of the wall force shape from q to 1: int_q^1 S(q') dq' (boundary_force_law.hpp),
/// (25/3)(1 - q)^3 on [0.8, 1], plus 0.8^8/7 (q^-7 - 0.8^-7) below 0.8.
inline double wallShapeIntegral(double q) {
  if (q >= 1.0) return 0.0;
  if (q >= 0.8) return 25.0 / 3.0 * std::pow(1.0 - q, 3);
  return 25.0 / 3.0 * std::pow(0.2, 3) + std::pow(0.8, 8) / 7.0 * (std::pow(q, -7) - std::pow(0.8, -7));
}

/// Energy stored in the wall force law (METHOD.md section 2) by the current state [J]:
/// sum over fluid-boundary pairs of m_i (strength c_s^2/h) B(r_par) h int_q^1 S. The
/// energy ledger omits it; every case starts with the water half a spacing from the
/// walls, inside the force's range, and the walls release this energy at once, so the
/// initial value is the allowance of the energy bound. Corner particles (several
/// normals) count with r_perp = r_ik and B = 1 when faced by several normals, as the
/// force law treats them in 2D. Brute force: call it once.
template <int D>
double wallForceEnergy(const fluid::FluidSimulation<D>& sim) {
  if (!sim.walls()) return 0.0;
  const auto& b = sim.walls()->particles();
  const auto& f = sim.fluid();
  const auto& setup = sim.setup();
  const double h = setup.h(), dx = setup.dx, off = setup.method.boundary_offset * dx;
  const double scale = setup.method.boundary_strength * setup.sound_speed * setup.sound_speed / h;
  double energy = 0.0;
  for (std::size_t i = 0; i < f.size(); ++i) {
    for (std::size_t k = 0; k < b.size(); ++k) {
      const fluid::Vec<D> r = f.r[i] - b.r[k];
      if (r.squaredNorm() > 4.0 * h * h) continue;
      int faced = 0;
      fluid::Vec<D> n = fluid::Vec<D>::Zero();
      for (std::uint32_t a = b.normal_begin[k]; a < b.normal_begin[k + 1]; ++a)
        if (r.dot(b.normals[a]) > 0.0) {
          ++faced;
          n = b.normals[a];
        }
      if (faced == 0) continue;
      const double perp = faced == 1 ? r.dot(n) : r.norm();
      const double par = faced == 1 ? std::sqrt(std::max(r.squaredNorm() - perp * perp, 0.0)) : 0.0;
      if (par >= dx) continue;
      energy += f.m[i] * scale * (1.0 - par / dx) * h * wallShapeIntegral((perp + off) / h);
    }
  }
  return energy;
}

template <int D>
class StabilityMonitor {
 public:
  /// Signed distance of point r from a body surface, negative inside the body.
  using BodyDistance = std::function<double(const fluid::Vec<D>&)>;

  StabilityMonitor(const fluid::FluidSimulation<D>& sim, const fluid::Vec<D>& tank_size, bool lid)
      : sim_(sim), tank_(tank_size), lid_(lid) {}

  void addBody(const std::string& name, BodyDistance distance) { bodies_.push_back({name, std::move(distance)}); }
  /// The tank's lower corner when it is not the origin (e.g. a piston that strokes back
  /// behind x = 0: the plate itself is then checked as a body).
  void setLowerCorner(const fluid::Vec<D>& lower) { lower_ = lower; }

  /// Call after every step with the current total energy and the work injected so far.
  void sample(double energy, double injected_work) {
    if (first_) {
      e0_ = energy;
      first_ = false;
    }
    ++samples_;
    if (sim_.stepCount() > 0) min_dt_ratio_ = std::min(min_dt_ratio_, sim_.lastDt() / sim_.cflDt());
    max_excess_ = std::max(max_excess_, energy - e0_ - injected_work);
    const auto& f = sim_.fluid();
    for (std::size_t i = 0; i < f.size(); ++i) {
      const fluid::Vec<D>& r = f.r[i];
      if (!r.allFinite() || !f.v[i].allFinite() || !std::isfinite(f.rho[i])) ++non_finite_;
      bool outside = false;
      for (int k = 0; k < D; ++k)
        if (r[k] < lower_[k] || (r[k] > tank_[k] && (k != 1 || lid_))) outside = true;
      through_wall_ += outside;
      for (const auto& b : bodies_) {
        const double d = b.distance(r);
        min_body_clearance_ = std::min(min_body_clearance_, d);
        through_body_ += d < 0.0;
      }
      const double speed = f.v[i].norm();
      if (speed > max_speed_) {
        max_speed_ = speed;
        fastest_ = "particle id " + std::to_string(f.id[i]) + " at t = " + std::to_string(sim_.time()) + " s, r = (" +
                   std::to_string(r[0]) + ", " + std::to_string(r[1]) + ") m, rho = " + std::to_string(f.rho[i]);
      }
      fast_ += speed > 0.1 * sim_.setup().sound_speed;
    }
  }

  double minDtRatio() const { return min_dt_ratio_; }
  double maxEnergyExcess() const { return max_excess_; }  ///< max of E - E0 - W_injected [J]
  std::size_t throughWall() const { return through_wall_; }
  std::size_t throughBody() const { return through_body_; }
  std::size_t nonFinite() const { return non_finite_; }
  double minBodyClearance() const { return min_body_clearance_; }  ///< [m], fluid particle to body surface
  double maxSpeed() const { return max_speed_; }
  const std::string& fastest() const { return fastest_; }  ///< where max |v| was seen
  /// Particle-samples faster than the design speed c_s/10.
  std::size_t fasterThanDesign() const { return fast_; }
  std::size_t samples() const { return samples_; }

  std::string summary() const {
    char buf[512];
    std::snprintf(buf, sizeof buf,
                  "steps %zu, min dt/dt_cfl %.3f, max E-E0-W %.4g J, through wall %zu, through body %zu, "
                  "min body clearance %.4g m, max |v| %.3f m/s = %.3f c_s (%s), particle-steps above c_s/10: %zu",
                  samples_, min_dt_ratio_, max_excess_, through_wall_, through_body_,
                  bodies_.empty() ? 0.0 : min_body_clearance_, max_speed_, max_speed_ / sim_.setup().sound_speed,
                  fastest_.c_str(), fast_);
    return buf;
  }

 private:
  struct Body {
    std::string name;
    BodyDistance distance;
  };
  const fluid::FluidSimulation<D>& sim_;
  fluid::Vec<D> tank_;
  fluid::Vec<D> lower_ = fluid::Vec<D>::Zero();
  bool lid_;
  std::vector<Body> bodies_;
  bool first_ = true;
  double e0_ = 0.0;
  double min_dt_ratio_ = std::numeric_limits<double>::infinity();
  double max_excess_ = -std::numeric_limits<double>::infinity();
  double min_body_clearance_ = std::numeric_limits<double>::infinity();
  double max_speed_ = 0.0;
  std::string fastest_;
  std::size_t fast_ = 0;
  std::size_t through_wall_ = 0, through_body_ = 0, non_finite_ = 0, samples_ = 0;
};

}  // namespace moorsph::stability
