#pragma once
// Natural cubic spline through samples (t_i, x_i): the piston wave maker's
// displacement X(t) from a time series (METHOD.md section 4b). Second derivative
// zero at both ends; outside the samples the end values are held (the piston rests).
#include <vector>

namespace moorsph::fluid {

class CubicSpline {
 public:
  /// Times strictly increasing, at least two samples. Throws std::invalid_argument.
  CubicSpline(std::vector<double> t, std::vector<double> x);

  double value(double t) const;
  double derivative(double t) const;
  double firstTime() const { return t_.front(); }
  double lastTime() const { return t_.back(); }

 private:
  std::size_t interval(double t) const;

  std::vector<double> t_, x_, m_;  // m_: second derivatives at the knots
};

}  // namespace moorsph::fluid
