#pragma once
// A `moorsph study --series` expression: recorded series and constants added and
// subtracted, so that a metric can read a quantity no single column holds, e.g. a
// floating box's draught "gauges/G_left - body_box/y + 0.05" (water level minus the
// box centre plus its half-height) or a relative wave elevation at the bow. Terms are
// separated by " + " or " - " with spaces around the sign (names and numbers such as
// 1e-3 hold none); a plain "GROUP/COLUMN" is the one-term case. A series term may carry
// a factor, "0.125*gauges/G1": eight such terms are the mean of eight gauges (a floating
// sphere's surrounding level, METHOD.md 6.1).
#include <functional>
#include <string>
#include <vector>
#include "study/metrics.hpp"

namespace moorsph::app::study {

struct SeriesTerm {
  double sign = 1.0;     ///< +1 or -1
  std::string name;      ///< GROUP/COLUMN or "front"; empty for a constant
  double factor = 1.0;   ///< a series term's scale ("0.125*gauges/G1")
  double constant = 0.0; ///< the value of a constant term
};

/// The terms of `text`; throws std::invalid_argument naming the bad part (a dangling
/// sign, two terms without a sign, no series at all).
std::vector<SeriesTerm> parseSeriesExpression(const std::string& text);

/// The sum of the terms on the times of the first series term; every other series is
/// linearly interpolated there and must cover those times (a shorter one trims the
/// result to the span it covers). `load` reads one named series.
Series combineSeries(const std::vector<SeriesTerm>& terms, const std::function<Series(const std::string&)>& load);

}  // namespace moorsph::app::study
