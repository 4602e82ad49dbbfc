#include <moorsph/bodies/tension_only_spring.hpp>

#include <cmath>
#include <stdexcept>

namespace moorsph::bodies {

TensionOnlySpring::TensionOnlySpring(const TensionOnlySpringParams& params) : params_(params) {
  if (!(params_.stiffness > 0.0)) {
    throw std::invalid_argument("tension_only_spring: stiffness must be > 0 N/m");
  }
  if (!(params_.damping >= 0.0)) {
    throw std::invalid_argument("tension_only_spring: damping must be >= 0 N s/m");
  }
  const bool hasRest = std::isfinite(params_.restLength);
  const bool hasPre = std::isfinite(params_.pretension);
  if (hasRest == hasPre) {
    throw std::invalid_argument(
        "tension_only_spring: give exactly one of rest_length (m) and pretension (N)");
  }
  if (hasRest && params_.restLength < 0.0) {
    throw std::invalid_argument("tension_only_spring: rest_length must be >= 0 m");
  }
  if (hasPre && params_.pretension < 0.0) {
    throw std::invalid_argument("tension_only_spring: pretension must be >= 0 N");
  }
}

void TensionOnlySpring::initialize(const LineEnds& ends) {
  if (std::isfinite(params_.pretension)) {
    const double length = (ends.fairlead - ends.anchor).norm();
    params_.restLength = length - params_.pretension / params_.stiffness;
    if (params_.restLength <= 0.0) {
      throw std::invalid_argument(
          "tension_only_spring: pretension too large for the initial span "
          "(rest length would be <= 0)");
    }
    // Resolved once: re-initialising must not move the rest length again.
    params_.pretension = std::numeric_limits<double>::quiet_NaN();
  }
}

LineForces TensionOnlySpring::calcForces(const LineEnds& ends) const {
  LineForces out;
  const Eigen::Vector3d span = ends.fairlead - ends.anchor;
  const double length = span.norm();
  const double stretch = length - params_.restLength;
  if (stretch <= 0.0 || length == 0.0) {
    out.slack = true;
    return out;
  }
  const Eigen::Vector3d e = span / length;
  const double lengthRate = e.dot(ends.fairleadVelocity - ends.anchorVelocity);
  const double tension = params_.stiffness * stretch + params_.damping * lengthRate;
  if (tension <= 0.0) {
    // The damper would push: a rope cannot, so the line carries nothing this instant.
    // The spring energy released while shortening is then all taken by the damper:
    // dissipation = (T_applied - k s) Ldot with T_applied = 0.
    out.slack = true;
    out.dissipationPower = -params_.stiffness * stretch * lengthRate;
    return out;
  }
  out.fairleadTension = tension;
  out.anchorTension = tension;
  out.onFairlead = -tension * e;
  out.onAnchor = tension * e;
  out.dissipationPower = params_.damping * lengthRate * lengthRate;
  return out;
}

double TensionOnlySpring::calcPotentialEnergy(const LineEnds& ends) const {
  const double stretch = (ends.fairlead - ends.anchor).norm() - params_.restLength;
  return stretch > 0.0 ? 0.5 * params_.stiffness * stretch * stretch : 0.0;
}

std::vector<Eigen::Vector3d> TensionOnlySpring::calcShape(const LineEnds& ends) const {
  return {ends.fairlead, ends.anchor};
}

}  // namespace moorsph::bodies
