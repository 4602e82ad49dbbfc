#include <moorsph/bodies/lumped_mass_line.hpp>

#include <moorsph/bodies/elastic_catenary.hpp>

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace moorsph::bodies {

namespace {
constexpr double kPi = 3.14159265358979323846;
}

LumpedMassLine::LumpedMassLine(const LumpedMassParams& params) : p_(params) {
  if (!(p_.length > 0.0) || p_.segments < 1 || !(p_.massPerLength > 0.0) || !(p_.diameter >= 0.0) ||
      !(p_.axialStiffness > 0.0) || !(p_.internalDamping >= 0.0) || !(p_.bendingStiffness >= 0.0) || !(p_.gravity.norm() > 0.0) ||
      !(p_.timeStep >= 0.0) || !(p_.seabedFriction >= 0.0)) {
    throw std::invalid_argument(
        "lumped_mass: need length > 0 m, segments >= 1, mass per length > 0 kg/m, diameter >= 0 m, "
        "EA > 0 N, BA >= 0 N s, nonzero gravity, time step >= 0 s, friction >= 0");
  }
  up_ = -p_.gravity.normalized();
  segLength_ = p_.length / p_.segments;
  if (p_.internalDampingRatio > 0.0) {
    p_.internalDamping = 2.0 * p_.internalDampingRatio * segLength_ * std::sqrt(p_.axialStiffness * p_.massPerLength);
  }
  area_ = 0.25 * kPi * p_.diameter * p_.diameter;
  nodeMass_ = p_.massPerLength * segLength_;
  netWeight_ = (p_.massPerLength - p_.waterDensity * area_) * segLength_;  // kg of net weight per (wet) node

  // Stability of semi-implicit Euler for the stiffest, most damped local mode
  // x'' + gamma x' + omega^2 x = 0: omega^2 dt^2 + 2 gamma dt < 4. Use half the limit.
  const double kSeg = p_.axialStiffness / segLength_, cSeg = p_.internalDamping / segLength_;
  double omega2 = 4.0 * kSeg / nodeMass_, gamma = 4.0 * cSeg / nodeMass_;
  // Zig-zag bending mode: alternate nodes +-d turn each joint by ~4d/l.
  omega2 += 64.0 * p_.bendingStiffness / (nodeMass_ * segLength_ * segLength_ * segLength_);
  if (p_.seabed) {
    omega2 += p_.seabedStiffness * p_.diameter * segLength_ / nodeMass_;
    gamma += p_.seabedDamping * p_.diameter * segLength_ / nodeMass_;
  }
  const double limit = (-gamma + std::sqrt(gamma * gamma + 4.0 * omega2)) / omega2;
  stableStep_ = 0.5 * limit;  // = 0.5 l / c without damping and seabed
  if (p_.timeStep > stableStep_) {
    std::ostringstream msg;
    msg << "lumped_mass: time step " << p_.timeStep << " s exceeds the stable step " << stableStep_
        << " s (0.5 l/c with l = " << segLength_ << " m, c = sqrt(EA/m) = "
        << std::sqrt(p_.axialStiffness / p_.massPerLength) << " m/s, reduced for damping/seabed)";
    throw std::invalid_argument(msg.str());
  }
  dt_ = p_.timeStep > 0.0 ? p_.timeStep : 0.9 * stableStep_;
  frictionSlope_ = 0.25 * nodeMass_ / dt_;
}

void LumpedMassLine::initialize(const LineEnds& ends) {
  const int n = p_.segments;
  if (!std::isfinite(p_.seabedPoint.x())) p_.seabedPoint = ends.anchor;
  r_.assign(n + 1, Eigen::Vector3d::Zero());
  v_.assign(n + 1, Eigen::Vector3d::Zero());
  // Catenary start: exact statics of the continuous line, evaluated at the nodes.
  bool haveShape = false;
  const double w = netWeight_ / segLength_ * p_.gravity.norm();
  if (w > 0.0) {
    ElasticCatenaryParams cp;
    cp.length = p_.length;
    cp.axialStiffness = p_.axialStiffness;
    cp.weightPerLength = w;
    cp.seabedFriction = 0.0;
    cp.anchorOnSeabed = p_.seabed && std::abs((ends.anchor - p_.seabedPoint).dot(up_)) < 1e-6 * p_.length;
    cp.up = up_;
    cp.shapePoints = n + 1;
    try {
      const std::vector<Eigen::Vector3d> shape = ElasticCatenary(cp).calcShape(ends);  // fairlead first
      for (int i = 0; i <= n; ++i) r_[i] = shape[n - i];
      haveShape = true;
    } catch (const std::runtime_error&) {
      haveShape = false;
    }
  }
  if (!haveShape) {  // straight line between the ends
    for (int i = 0; i <= n; ++i) r_[i] = ends.anchor + (ends.fairlead - ends.anchor) * (double(i) / n);
  }
  r_[0] = ends.anchor;
  r_[n] = ends.fairlead;
  v_[0] = ends.anchorVelocity;
  v_[n] = ends.fairleadVelocity;
  initialized_ = true;
  if (p_.relaxationTime > 0.0) relax(p_.relaxationTime);
  dissipated_ = 0.0;
  endWork_ = 0.0;
  time_ = 0.0;
}

double LumpedMassLine::segmentTension(int j, double* dampingPower) const {
  const Eigen::Vector3d d = r_[j + 1] - r_[j];
  const double len = d.norm();
  const double strain = len / segLength_ - 1.0;
  if (strain <= 0.0) return 0.0;
  const double strainRate = d.dot(v_[j + 1] - v_[j]) / (len * segLength_);
  const double elastic = p_.axialStiffness * strain;
  const double t = std::max(0.0, elastic + p_.internalDamping * strainRate);
  // Power taken by the damper (or by the clamp at T = 0), as for tension_only_spring.
  if (dampingPower) *dampingPower += (t - elastic) * strainRate * segLength_;
  return t;
}

void LumpedMassLine::computeAccelerations(std::vector<Eigen::Vector3d>& acc, double time, bool movingWater,
                                          double extraDamping, double* dissipation, double* endPower) const {
  const int n = p_.segments;
  std::vector<Eigen::Vector3d>& force = scratchForce_;  // no allocation per step
  force.assign(n + 1, Eigen::Vector3d::Zero());
  double damping = 0.0;
  for (int j = 0; j < n; ++j) {
    const Eigen::Vector3d d = r_[j + 1] - r_[j];
    const double t = segmentTension(j, &damping);
    if (t > 0.0) {
      const Eigen::Vector3d f = t * d / d.norm();
      force[j] += f;
      force[j + 1] -= f;
    }
  }
  addBendingForces(force);
  if (endPower) {
    // Power the moving ends put into the line: minus the line's force on them, times
    // their velocity.
    *endPower = -force[0].dot(v_[0]) - force[n].dot(v_[n]);
  }
  double power = -damping;  // damping accumulates -(dissipated power)
  const double rho = p_.waterDensity, d = p_.diameter, l = segLength_;
  for (int i = 1; i < n; ++i) {
    const double wet = wetFraction(i);
    Eigen::Vector3d f = force[i] + (nodeMass_ - wet * rho * area_ * l) * p_.gravity;
    const Eigen::Vector3d q = (r_[i + 1] - r_[i - 1]).normalized();
    const Eigen::Vector3d& v = v_[i];
    Eigen::Vector3d water = Eigen::Vector3d::Zero(), waterAcc = Eigen::Vector3d::Zero();
    if (movingWater && wet > 0.0) p_.waterKinematics(r_[i], time, water, waterAcc);
    const Eigen::Vector3d w = water - v;  // relative velocity of the water
    const Eigen::Vector3d wt = w.dot(q) * q, wn = w - wt;
    Eigen::Vector3d hydro = wet * (0.5 * rho * d * l * p_.cdNormal * wn.norm() * wn +
                                   0.5 * rho * kPi * d * l * p_.cdAxial * wt.norm() * wt);
    if (movingWater) {
      const Eigen::Vector3d at = waterAcc.dot(q) * q, an = waterAcc - at;
      hydro += wet * rho * area_ * l * ((1.0 + p_.caNormal) * an + (1.0 + p_.caAxial) * at);
    }
    f += hydro;
    power += hydro.dot(v);
    if (p_.seabed) {
      const double penetration = -(r_[i] - p_.seabedPoint).dot(up_);
      if (penetration > 0.0) {
        const double normalRate = v.dot(up_);
        const double springForce = p_.seabedStiffness * penetration * d * l;
        const double normal = std::max(0.0, springForce - p_.seabedDamping * normalRate * d * l);
        f += normal * up_;
        power += (normal - springForce) * normalRate;  // the seabed damper's share
        const Eigen::Vector3d vh = v - normalRate * up_;
        const double speed = vh.norm();
        if (p_.seabedFriction > 0.0 && speed > 0.0) {
          const Eigen::Vector3d friction =
              -std::min(p_.seabedFriction * normal, frictionSlope_ * speed) * (vh / speed);
          f += friction;
          power += friction.dot(v);
        }
      }
    }
    if (extraDamping > 0.0) f -= extraDamping * nodeMass_ * v;
    // M = a I + b q q^T (isotropic mass plus normal/axial added mass), inverted in
    // closed form: M^-1 = I/a - b/(a (a + b)) q q^T.
    const double added = wet * rho * area_ * l;
    const double a = nodeMass_ + added * p_.caNormal, b = added * (p_.caAxial - p_.caNormal);
    acc[i] = f / a - (b / (a * (a + b)) * q.dot(f)) * q;
  }
  if (dissipation) *dissipation = -power;
}

// Bending: U = sum over internal nodes EI/(2 l) |q_b - q_a|^2, forces = -grad U, with
// d q / d d = (I - q q^T)/|d| for a segment vector d and its unit vector q.
void LumpedMassLine::addBendingForces(std::vector<Eigen::Vector3d>& force) const {
  if (p_.bendingStiffness <= 0.0) return;
  const double c = p_.bendingStiffness / segLength_;
  for (int i = 1; i < p_.segments; ++i) {
    const Eigen::Vector3d da = r_[i] - r_[i - 1], db = r_[i + 1] - r_[i];
    const double la = da.norm(), lb = db.norm();
    const Eigen::Vector3d qa = da / la, qb = db / lb, g = qb - qa;
    const Eigen::Vector3d dUdb = c * (g - qb * qb.dot(g)) / lb;   // dU/d(db)
    const Eigen::Vector3d dUda = -c * (g - qa * qa.dot(g)) / la;  // dU/d(da)
    force[i + 1] -= dUdb;
    force[i] += dUdb - dUda;
    force[i - 1] += dUda;
  }
}

// Fraction of the line represented by node i (half of each adjacent segment) that lies
// below the water surface, from the straight half segments' heights.
double LumpedMassLine::wetFraction(int i) const {
  if (!std::isfinite(p_.waterSurfaceHeight)) return 1.0;
  const double s = p_.waterSurfaceHeight;
  auto below = [s](double h1, double h2) {  // submerged fraction of a straight piece
    const double lo = std::min(h1, h2), hi = std::max(h1, h2);
    if (hi <= s) return 1.0;
    if (lo >= s) return 0.0;
    return (s - lo) / (hi - lo);
  };
  const double h = r_[i].dot(up_);
  double sum = 0.0;
  int halves = 0;
  if (i > 0) sum += below(h, 0.5 * (h + r_[i - 1].dot(up_))), ++halves;
  if (i < p_.segments) sum += below(h, 0.5 * (h + r_[i + 1].dot(up_))), ++halves;
  return sum / halves;
}

// Work done by the buoyancy rho A l |g| f(h) when a node rises to height h: its
// potential is minus this, and with f = 1 it is rho A l |g| h.
double LumpedMassLine::buoyancyPotential(const Eigen::Vector3d& r) const {
  const double b = p_.waterDensity * area_ * segLength_ * p_.gravity.norm();
  const double h = r.dot(up_);
  if (!std::isfinite(p_.waterSurfaceHeight)) return b * h;
  const double lo = p_.waterSurfaceHeight - 0.5 * segLength_, hi = p_.waterSurfaceHeight + 0.5 * segLength_;
  if (h <= lo) return b * h;
  const double top = std::min(h, hi);
  // integral of f(s) = (S - s)/l + 1/2 from lo to top
  const double ramp = ((p_.waterSurfaceHeight + 0.5 * segLength_) * (top - lo) - 0.5 * (top * top - lo * lo)) / segLength_;
  return b * (lo + ramp);
}

double LumpedMassLine::bendingEnergy() const {
  double e = 0.0;
  for (int i = 1; i < p_.segments && p_.bendingStiffness > 0.0; ++i) {
    const Eigen::Vector3d g = (r_[i + 1] - r_[i]).normalized() - (r_[i] - r_[i - 1]).normalized();
    e += 0.5 * p_.bendingStiffness / segLength_ * g.squaredNorm();
  }
  return e;
}

void LumpedMassLine::advance(double dt, const LineEnds& start, const LineEnds& end) {
  if (!initialized_) throw std::logic_error("lumped_mass: advance() before initialize()");
  if (!(dt > 0.0)) return;
  const int n = p_.segments;
  const int steps = static_cast<int>(std::ceil(dt / dt_ - 1e-9));
  const double h = dt / steps;
  const Eigen::Vector3d fairleadVel = (end.fairlead - start.fairlead) / dt;
  const Eigen::Vector3d anchorVel = (end.anchor - start.anchor) / dt;
  std::vector<Eigen::Vector3d> acc(n + 1, Eigen::Vector3d::Zero());
  clearExceedance();
  const bool breakable = std::isfinite(breakingLoad());
  for (int k = 0; k < steps; ++k) {
    v_[0] = anchorVel;
    v_[n] = fairleadVel;
    double dissipation = 0.0, endPower = 0.0;
    computeAccelerations(acc, time_ + k * h, static_cast<bool>(p_.waterKinematics), 0.0, &dissipation, &endPower);
    dissipated_ += h * dissipation;
    endWork_ += h * endPower;
    for (int i = 1; i < n; ++i) {
      v_[i] += h * acc[i];
      r_[i] += h * v_[i];
    }
    const double f = double(k + 1) / steps;
    r_[0] = start.anchor + f * (end.anchor - start.anchor);
    r_[n] = start.fairlead + f * (end.fairlead - start.fairlead);
    if (breakable) {
      // Tested every sub-step so that a break is placed within one sub-step of the
      // crossing; the line stops there (it no longer exists past its break).
      const LineForces ends = calcForces(end);
      const double tension = std::max(ends.fairleadTension, ends.anchorTension);
      if (tension > breakingLoad()) {
        recordExceedance((k + 1) * h, tension);
        time_ += (k + 1) * h;
        return;
      }
    }
  }
  time_ += dt;
  for (int i = 0; i <= n; ++i) {
    if (!r_[i].allFinite() || !v_[i].allFinite()) {
      std::ostringstream msg;
      msg << "lumped_mass: node " << i << " became non-finite (time step " << dt_ << " s, stable step "
          << stableStep_ << " s)";
      throw std::runtime_error(msg.str());
    }
  }
}

double LumpedMassLine::relax(double maxTime, double speedTolerance) {
  const int n = p_.segments;
  std::vector<Eigen::Vector3d> acc(n + 1, Eigen::Vector3d::Zero());
  v_[0].setZero();
  v_[n].setZero();
  double t = 0.0;
  while (t < maxTime) {
    computeAccelerations(acc, 0.0, false, p_.relaxationDamping, nullptr, nullptr);  // still water
    double fastest = 0.0;
    for (int i = 1; i < n; ++i) {
      v_[i] += dt_ * acc[i];
      r_[i] += dt_ * v_[i];
      fastest = std::max(fastest, v_[i].norm());
    }
    t += dt_;
    if (fastest < speedTolerance && t > 10.0 * dt_) break;
  }
  for (int i = 1; i < n; ++i) v_[i].setZero();
  return t;
}

std::vector<double> LumpedMassLine::saveState() const {
  std::vector<double> out;
  out.reserve(6 * r_.size() + 2);
  for (std::size_t i = 0; i < r_.size(); ++i) {
    out.insert(out.end(), r_[i].data(), r_[i].data() + 3);
    out.insert(out.end(), v_[i].data(), v_[i].data() + 3);
  }
  out.push_back(dissipated_);
  out.push_back(endWork_);
  out.push_back(time_);
  return out;
}

void LumpedMassLine::startWithoutSavedState(const LineEnds& ends, double time) {
  initialize(ends);  // the static catenary (or straight) shape between the restored ends
  time_ = time;      // the wave field the line sees continues from the restart time
}

void LumpedMassLine::restoreState(const std::vector<double>& state) {
  const std::size_t nodes = static_cast<std::size_t>(p_.segments) + 1;
  if (state.size() != 6 * nodes + 3) {
    throw std::invalid_argument("lumped_mass: saved state does not match the number of segments");
  }
  r_.resize(nodes);
  v_.resize(nodes);
  for (std::size_t i = 0; i < nodes; ++i) {
    r_[i] = Eigen::Vector3d(state[6 * i], state[6 * i + 1], state[6 * i + 2]);
    v_[i] = Eigen::Vector3d(state[6 * i + 3], state[6 * i + 4], state[6 * i + 5]);
  }
  dissipated_ = state[6 * nodes];
  endWork_ = state[6 * nodes + 1];
  time_ = state[6 * nodes + 2];
  initialized_ = true;
}

std::vector<double> LumpedMassLine::segmentTensions() const {
  std::vector<double> t(p_.segments);
  for (int j = 0; j < p_.segments; ++j) t[j] = segmentTension(j, nullptr);
  return t;
}

LineForces LumpedMassLine::calcForces(const LineEnds& ends) const {
  (void)ends;  // the line's own end nodes are the attachment points
  LineForces out;
  const int n = p_.segments;
  const double buoyancy = p_.waterDensity * area_ * segLength_;
  const double tTop = segmentTension(n - 1, nullptr), tBottom = segmentTension(0, nullptr);
  const Eigen::Vector3d eTop = (r_[n] - r_[n - 1]).normalized(), eBottom = (r_[1] - r_[0]).normalized();
  out.onFairlead = -tTop * eTop + 0.5 * (nodeMass_ - wetFraction(n) * buoyancy) * p_.gravity;
  out.onAnchor = tBottom * eBottom + 0.5 * (nodeMass_ - wetFraction(0) * buoyancy) * p_.gravity;
  out.fairleadTension = out.onFairlead.norm();
  out.anchorTension = out.onAnchor.norm();
  out.slack = tTop == 0.0;
  return out;
}

double LumpedMassLine::kineticEnergy() const {
  double e = 0.0;
  for (int i = 1; i < p_.segments; ++i) {
    const Eigen::Vector3d q = (r_[i + 1] - r_[i - 1]).normalized();
    Eigen::Matrix3d mass = nodeMass_ * Eigen::Matrix3d::Identity();
    const Eigen::Matrix3d qq = q * q.transpose();
    mass += wetFraction(i) * p_.waterDensity * area_ * segLength_ *
            (p_.caNormal * (Eigen::Matrix3d::Identity() - qq) + p_.caAxial * qq);
    e += 0.5 * v_[i].dot(mass * v_[i]);
  }
  return e;
}

double LumpedMassLine::calcPotentialEnergy(const LineEnds& ends) const {
  (void)ends;
  double e = bendingEnergy();
  for (int j = 0; j < p_.segments; ++j) {
    const double strain = (r_[j + 1] - r_[j]).norm() / segLength_ - 1.0;
    if (strain > 0.0) e += 0.5 * p_.axialStiffness * strain * strain * segLength_;
  }
  for (int i = 1; i < p_.segments; ++i) {
    e -= nodeMass_ * p_.gravity.dot(r_[i] - r_[0]);
    e -= buoyancyPotential(r_[i]) - buoyancyPotential(r_[0]);
    if (p_.seabed) {
      const double penetration = -(r_[i] - p_.seabedPoint).dot(up_);
      if (penetration > 0.0) e += 0.5 * p_.seabedStiffness * p_.diameter * segLength_ * penetration * penetration;
    }
  }
  return e;
}

std::vector<Eigen::Vector3d> LumpedMassLine::calcShape(const LineEnds& ends) const {
  (void)ends;
  return std::vector<Eigen::Vector3d>(r_.rbegin(), r_.rend());  // fairlead first
}

}  // namespace moorsph::bodies
