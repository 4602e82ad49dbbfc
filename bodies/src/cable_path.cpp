#include <moorsph/bodies/cable_path.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace moorsph::bodies {

CablePathLine::CablePathLine(const CablePathParams& params) : params_(params) {
  if (!(params_.stiffness > 0.0) || !(params_.dissipation >= 0.0)) {
    throw std::invalid_argument("cable_path: stiffness must be > 0 N/m and dissipation >= 0 s/m");
  }
  if (std::isfinite(params_.restLength) == std::isfinite(params_.pretension)) {
    throw std::invalid_argument("cable_path: give exactly one of rest_length (m) and pretension (N)");
  }
}

void CablePathLine::resolveRestLength(double initialPathLength) {
  if (!std::isfinite(params_.pretension)) return;
  params_.restLength = initialPathLength - params_.pretension / params_.stiffness;
  if (params_.restLength <= 0.0) {
    throw std::invalid_argument("cable_path: pretension too large for the initial path (rest length <= 0)");
  }
  params_.pretension = std::numeric_limits<double>::quiet_NaN();
}

std::vector<Eigen::Vector3d> CablePathLine::groundPath(const LineEnds& ends) const {
  std::vector<Eigen::Vector3d> path{ends.fairlead};
  for (const CableViaPoint& via : params_.viaPoints) {
    if (via.body != LineAttachment::kGround) {
      throw std::logic_error("cable_path: body-mounted via points are evaluated inside MultibodySystem only");
    }
    path.push_back(via.point);
  }
  path.push_back(ends.anchor);
  return path;
}

void CablePathLine::initialize(const LineEnds& ends) {
  const std::vector<Eigen::Vector3d> path = groundPath(ends);
  double length = 0.0;
  for (std::size_t i = 1; i < path.size(); ++i) length += (path[i] - path[i - 1]).norm();
  resolveRestLength(length);
}

LineForces CablePathLine::calcForces(const LineEnds& ends) const {
  const std::vector<Eigen::Vector3d> path = groundPath(ends);
  double length = 0.0;
  for (std::size_t i = 1; i < path.size(); ++i) length += (path[i] - path[i - 1]).norm();
  // Only the end segments move (ground via points): Ldot from the end velocities.
  const Eigen::Vector3d eFirst = (path[1] - path[0]).normalized();
  const Eigen::Vector3d eLast = (path[path.size() - 2] - path.back()).normalized();
  const double lengthDot = -eFirst.dot(ends.fairleadVelocity) - eLast.dot(ends.anchorVelocity);
  LineForces out;
  const double stretch = length - params_.restLength;
  if (stretch <= 0.0) {
    out.slack = true;
    return out;
  }
  const double elastic = params_.stiffness * stretch;
  const double rate = std::max(-elastic, elastic * params_.dissipation * lengthDot);
  const double tension = elastic + rate;
  out.fairleadTension = out.anchorTension = tension;
  out.onFairlead = tension * eFirst;
  out.onAnchor = tension * eLast;
  out.dissipationPower = rate * lengthDot;
  out.slack = tension <= 0.0;
  return out;
}

double CablePathLine::calcPotentialEnergy(const LineEnds& ends) const {
  const std::vector<Eigen::Vector3d> path = groundPath(ends);
  double length = 0.0;
  for (std::size_t i = 1; i < path.size(); ++i) length += (path[i] - path[i - 1]).norm();
  const double stretch = std::max(0.0, length - params_.restLength);
  return 0.5 * params_.stiffness * stretch * stretch;
}

std::vector<Eigen::Vector3d> CablePathLine::calcShape(const LineEnds& ends) const { return groundPath(ends); }

}  // namespace moorsph::bodies
