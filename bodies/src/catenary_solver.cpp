#include <moorsph/bodies/catenary_solver.hpp>

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace moorsph::bodies {

double CatenarySolution::fairleadTension() const { return std::hypot(fairleadHorizontal, fairleadVertical); }
double CatenarySolution::anchorTension() const { return std::hypot(anchorHorizontal, anchorVertical); }

namespace {

struct Residual {
  Eigen::Vector2d r;   // (x(HF,VF) - x, z(HF,VF) - z)
  Eigen::Matrix2d j;   // d r / d (HF, VF)
};

bool touchesSeabed(const CatenaryInput& in, double vf) {
  return in.anchorOnSeabed && vf < in.weightPerLength * in.length;
}

// Closed-form spans and their analytic derivatives (header comment for the equations).
Residual evaluate(const CatenaryInput& in, double hf, double vf) {
  const double w = in.weightPerLength, l = in.length, ea = in.axialStiffness;
  Residual out;
  const double a = vf / hf;
  const double sa = std::sqrt(1.0 + a * a);
  if (!touchesSeabed(in, vf)) {
    const double b = (vf - w * l) / hf;
    const double sb = std::sqrt(1.0 + b * b);
    out.r(0) = hf / w * (std::asinh(a) - std::asinh(b)) + hf * l / ea - in.horizontalSpan;
    out.r(1) = hf / w * (sa - sb) + (vf * l - 0.5 * w * l * l) / ea - in.verticalSpan;
    out.j(0, 0) = (std::asinh(a) - std::asinh(b) - a / sa + b / sb) / w + l / ea;
    out.j(0, 1) = (1.0 / sa - 1.0 / sb) / w;
    out.j(1, 0) = (1.0 / sa - 1.0 / sb) / w;
    out.j(1, 1) = (a / sa - b / sb) / w + l / ea;
    return out;
  }
  const double lb = l - vf / w;
  double frictionX = 0.0, dFrictionDh = 0.0, dFrictionDv = 0.0;
  if (in.seabedFriction > 0.0) {
    const double cbw = in.seabedFriction * w;
    const double c = hf / cbw;          // length over which friction takes up HF
    const double m = std::max(lb - c, 0.0);  // slack length at the anchor end
    frictionX = cbw / (2.0 * ea) * (-lb * lb + m * m);
    dFrictionDh = -m / ea;
    dFrictionDv = in.seabedFriction * std::min(lb, c) / ea;
  }
  out.r(0) = lb + hf / w * std::asinh(a) + hf * l / ea + frictionX - in.horizontalSpan;
  out.r(1) = hf / w * (sa - 1.0) + vf * vf / (2.0 * ea * w) - in.verticalSpan;
  out.j(0, 0) = (std::asinh(a) - a / sa) / w + l / ea + dFrictionDh;
  out.j(0, 1) = (1.0 / sa - 1.0) / w + dFrictionDv;
  out.j(1, 0) = (1.0 / sa - 1.0) / w;
  out.j(1, 1) = a / (w * sa) + vf / (ea * w);
  return out;
}

}  // namespace

CatenarySolution solveCatenary(const CatenaryInput& in) {
  if (!(in.length > 0.0) || !(in.axialStiffness > 0.0) || !(in.weightPerLength > 0.0) ||
      !(in.horizontalSpan >= 0.0) || !(in.verticalSpan >= 0.0) || !(in.seabedFriction >= 0.0)) {
    throw std::invalid_argument("solveCatenary: need L > 0, EA > 0, w > 0, x >= 0, z >= 0, cb >= 0");
  }
  const double l = in.length, w = in.weightPerLength;
  // A vertical line makes HF = 0, where the equations are singular; a span of 1e-9 L
  // changes nothing measurable.
  CatenaryInput q = in;
  q.horizontalSpan = std::max(in.horizontalSpan, 1e-9 * l);
  const double x = q.horizontalSpan, z = q.verticalSpan;

  // Peyrot & Goulois start (as in Jonkman 2007 eq. 4-12).
  double lambda;
  if (std::hypot(x, z) >= l) {
    lambda = 0.2;
  } else {
    lambda = std::sqrt(3.0 * ((l * l - z * z) / (x * x) - 1.0));
  }
  double hf = std::max(std::abs(0.5 * w * x / lambda), 1e-6 * w * l);
  double vf = 0.5 * w * (z / std::tanh(lambda) + l);

  const double tol = 1e-12 * std::max(l, std::hypot(x, z));
  CatenarySolution sol;
  for (int it = 1; it <= 200; ++it) {
    const Residual res = evaluate(q, hf, vf);
    if (!res.r.allFinite() || !res.j.allFinite()) break;
    const Eigen::Vector2d step = res.j.inverse() * (-res.r);  // 2x2: closed-form inverse
    if (res.r.cwiseAbs().maxCoeff() < tol && std::abs(step(0)) < 1e-10 * hf + 1e-12 &&
        std::abs(step(1)) < 1e-10 * std::abs(vf) + 1e-12) {
      sol.iterations = it;
      sol.fairleadHorizontal = hf;
      sol.fairleadVertical = vf;
      if (touchesSeabed(q, vf)) {
        sol.seabedLength = l - vf / w;
        sol.anchorHorizontal = std::max(hf - q.seabedFriction * w * sol.seabedLength, 0.0);
        sol.anchorVertical = 0.0;
      } else {
        sol.anchorHorizontal = hf;
        sol.anchorVertical = vf - w * l;
      }
      return sol;
    }
    // Keep HF positive and, on a seabed, VF positive (a cut-back Newton step).
    double nh = hf + step(0), nv = vf + step(1);
    if (nh <= 0.0) nh = 0.1 * hf;
    if (q.anchorOnSeabed && nv <= 0.0) nv = 0.1 * std::max(vf, 1e-9 * w * l);
    hf = nh;
    vf = nv;
  }
  std::ostringstream msg;
  msg << "solveCatenary: Newton did not converge (x = " << in.horizontalSpan << " m, z = " << in.verticalSpan
      << " m, L = " << l << " m, EA = " << in.axialStiffness << " N, w = " << w << " N/m)";
  throw std::runtime_error(msg.str());
}

double catenaryTension(const CatenaryInput& in, const CatenarySolution& sol, double s) {
  const double w = in.weightPerLength, hf = sol.fairleadHorizontal;
  if (sol.seabedLength > 0.0 && s <= sol.seabedLength) {
    return std::max(hf - in.seabedFriction * w * (sol.seabedLength - s), 0.0);
  }
  const double v = sol.anchorVertical + w * (s - sol.seabedLength);
  return std::hypot(hf, v);
}

Eigen::Vector2d catenaryPoint(const CatenaryInput& in, const CatenarySolution& sol, double s) {
  const double w = in.weightPerLength, ea = in.axialStiffness, hf = sol.fairleadHorizontal;
  const double lb = sol.seabedLength;
  // Horizontal stretch of the seabed part: (1/EA) int_0^s T ds with T linear, clipped at 0.
  auto seabedStretch = [&](double upTo) {
    if (in.seabedFriction <= 0.0) return hf * upTo / ea;
    const double start = std::max(lb - hf / (in.seabedFriction * w), 0.0);  // T > 0 beyond here
    if (upTo <= start) return 0.0;
    const double t0 = hf - in.seabedFriction * w * (lb - start);  // = 0 unless start == 0
    const double t1 = hf - in.seabedFriction * w * (lb - upTo);
    return 0.5 * (t0 + t1) * (upTo - start) / ea;
  };
  if (lb > 0.0 && s <= lb) return Eigen::Vector2d(s + seabedStretch(s), 0.0);
  const double sigma = s - lb;  // arc length of the suspended part measured from its start
  const double va = sol.anchorVertical;
  const double b = va / hf, c = (va + w * sigma) / hf;
  const double x0 = lb > 0.0 ? lb + seabedStretch(lb) : 0.0;
  const double xs = hf / w * (std::asinh(c) - std::asinh(b)) + hf * sigma / ea;
  const double zs = hf / w * (std::sqrt(1.0 + c * c) - std::sqrt(1.0 + b * b)) + (va * sigma + 0.5 * w * sigma * sigma) / ea;
  return Eigen::Vector2d(x0 + xs, zs);
}

}  // namespace moorsph::bodies
