#include <moorsph/bodies/elastic_catenary.hpp>

#include <Eigen/Geometry>

#include <cmath>
#include <stdexcept>

namespace moorsph::bodies {

struct ElasticCatenary::Plane {
  CatenaryInput input;
  CatenarySolution solution;
  Eigen::Vector3d lower;       // lower end of the line (the anchor unless swapped)
  Eigen::Vector3d horizontal;  // unit, from lower end towards upper end
  bool swapped = false;        // true when the fairlead is the lower end
  double anchorHeightAboveLower = 0.0;
};

ElasticCatenary::ElasticCatenary(const ElasticCatenaryParams& params) : params_(params) {
  if (!(params_.length > 0.0) || !(params_.axialStiffness > 0.0) || !(params_.weightPerLength > 0.0) ||
      !(params_.seabedFriction >= 0.0) || params_.shapePoints < 2 || !(params_.up.norm() > 0.0)) {
    throw std::invalid_argument(
        "elastic_catenary: need length > 0 m, EA > 0 N, weight per length > 0 N/m, friction >= 0");
  }
  params_.up.normalize();
}

ElasticCatenary::Plane ElasticCatenary::solve(const LineEnds& ends) const {
  Plane p;
  const Eigen::Vector3d& up = params_.up;
  const Eigen::Vector3d span = ends.fairlead - ends.anchor;
  const double rise = span.dot(up);
  p.swapped = rise < 0.0;
  p.lower = p.swapped ? ends.fairlead : ends.anchor;
  const Eigen::Vector3d upperMinusLower = p.swapped ? Eigen::Vector3d(-span) : span;
  const Eigen::Vector3d horizontal = upperMinusLower - upperMinusLower.dot(up) * up;
  const double x = horizontal.norm();
  if (x > 0.0) {
    p.horizontal = horizontal / x;
  } else {  // vertical line: any horizontal direction will do (HF ~ 0)
    p.horizontal = up.unitOrthogonal();
  }
  p.input.horizontalSpan = x;
  p.input.verticalSpan = std::abs(rise);
  p.input.length = params_.length;
  p.input.axialStiffness = params_.axialStiffness;
  p.input.weightPerLength = params_.weightPerLength;
  p.input.seabedFriction = params_.seabedFriction;
  p.input.anchorOnSeabed = params_.anchorOnSeabed && !p.swapped;
  p.solution = solveCatenary(p.input);
  p.anchorHeightAboveLower = p.swapped ? -rise : 0.0;
  return p;
}

LineForces ElasticCatenary::calcForces(const LineEnds& ends) const {
  const Plane p = solve(ends);
  const CatenarySolution& s = p.solution;
  const Eigen::Vector3d& up = params_.up;
  // Line on its upper end: pulls towards the lower end and down; on its lower end:
  // pulls towards the upper end horizontally and with VA vertically.
  const Eigen::Vector3d onUpper = -s.fairleadHorizontal * p.horizontal - s.fairleadVertical * up;
  const Eigen::Vector3d onLower = s.anchorHorizontal * p.horizontal + s.anchorVertical * up;
  LineForces out;
  out.onFairlead = p.swapped ? onLower : onUpper;
  out.onAnchor = p.swapped ? onUpper : onLower;
  out.fairleadTension = p.swapped ? s.anchorTension() : s.fairleadTension();
  out.anchorTension = p.swapped ? s.fairleadTension() : s.anchorTension();
  out.slack = s.fairleadHorizontal < 1e-9 * params_.weightPerLength * params_.length;
  return out;
}

double ElasticCatenary::calcPotentialEnergy(const LineEnds& ends) const {
  const Plane p = solve(ends);
  // Composite Simpson over the unstretched arc length; the integrand has a kink where
  // the line leaves the seabed, so integrate the two parts separately.
  auto integrand = [&](double s) {
    const double t = catenaryTension(p.input, p.solution, s);
    const double h = catenaryPoint(p.input, p.solution, s).y() - p.anchorHeightAboveLower;
    return t * t / (2.0 * params_.axialStiffness) + params_.weightPerLength * h;
  };
  auto simpson = [&](double a, double b) {
    const int n = 400;
    if (!(b > a)) return 0.0;
    const double hstep = (b - a) / n;
    double sum = integrand(a) + integrand(b);
    for (int i = 1; i < n; ++i) sum += (i % 2 ? 4.0 : 2.0) * integrand(a + i * hstep);
    return sum * hstep / 3.0;
  };
  const double lb = p.solution.seabedLength;
  return simpson(0.0, lb) + simpson(lb, params_.length);
}

std::vector<Eigen::Vector3d> ElasticCatenary::calcShape(const LineEnds& ends) const {
  const Plane p = solve(ends);
  std::vector<Eigen::Vector3d> points;
  const int n = params_.shapePoints;
  for (int i = 0; i < n; ++i) {
    // Fairlead first: s runs from the fairlead's end to the anchor's end.
    const double f = static_cast<double>(i) / (n - 1);
    const double s = p.swapped ? f * params_.length : (1.0 - f) * params_.length;
    const Eigen::Vector2d xz = catenaryPoint(p.input, p.solution, s);
    points.push_back(p.lower + xz.x() * p.horizontal + xz.y() * params_.up);
  }
  return points;
}

}  // namespace moorsph::bodies
