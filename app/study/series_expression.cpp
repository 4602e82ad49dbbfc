#include "study/series_expression.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <sstream>
#include <stdexcept>

namespace moorsph::app::study {

namespace {

/// The finite number `text` spells in full, if it does.
std::optional<double> wholeNumber(const std::string& text) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(v)) return std::nullopt;
  return v;
}

}  // namespace

std::vector<SeriesTerm> parseSeriesExpression(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> tokens;
  for (std::string t; in >> t;) tokens.push_back(t);
  auto bad = [&](const std::string& why) { return std::invalid_argument("--series '" + text + "': " + why); };
  if (tokens.empty()) throw bad("empty");
  std::vector<SeriesTerm> terms;
  double sign = 1.0;
  bool expect_term = true;
  for (const auto& t : tokens) {
    const bool is_sign = t == "+" || t == "-";
    if (expect_term == is_sign)
      throw bad(is_sign ? "a sign '" + t + "' where a term is expected" : "'" + t + "' follows a term without ' + ' or ' - '");
    if (is_sign) {
      sign = t == "-" ? -1.0 : 1.0;
      expect_term = true;
      continue;
    }
    SeriesTerm term;
    term.sign = sign;
    if (const auto number = wholeNumber(t)) {
      term.constant = *number;
    } else if (const auto star = t.find('*'); star != std::string::npos && wholeNumber(t.substr(0, star))) {
      // "NUMBER*NAME"; a '*' after anything but a number stays part of the name
      term.factor = *wholeNumber(t.substr(0, star));
      term.name = t.substr(star + 1);
      if (term.name.empty()) throw bad("'" + t + "' has a factor but no series after '*'");
    } else {
      term.name = t;
    }
    terms.push_back(term);
    expect_term = false;
  }
  if (expect_term) throw bad("ends with a sign");
  if (std::none_of(terms.begin(), terms.end(), [](const SeriesTerm& s) { return !s.name.empty(); }))
    throw bad("names no series (GROUP/COLUMN)");
  return terms;
}

Series combineSeries(const std::vector<SeriesTerm>& terms, const std::function<Series(const std::string&)>& load) {
  std::vector<Series> loaded;
  for (const auto& term : terms) loaded.push_back(term.name.empty() ? Series{} : load(term.name));
  const auto first = std::find_if(terms.begin(), terms.end(), [](const SeriesTerm& s) { return !s.name.empty(); });
  const Series& base = loaded[static_cast<std::size_t>(first - terms.begin())];
  // Keep the base times every series covers (runs of one scene share their output
  // times; a series that ends early, e.g. a killed run's last row, trims the result).
  double lo = -INFINITY, hi = INFINITY;
  for (std::size_t k = 0; k < terms.size(); ++k)
    if (!terms[k].name.empty()) {
      if (loaded[k].time.empty()) throw std::runtime_error("series " + terms[k].name + " has no samples");
      lo = std::max(lo, loaded[k].time.front());
      hi = std::min(hi, loaded[k].time.back());
    }
  Series sum;
  for (double t : base.time) {
    if (t < lo || t > hi) continue;
    double v = 0.0;
    for (std::size_t k = 0; k < terms.size(); ++k)
      v += terms[k].sign * (terms[k].name.empty() ? terms[k].constant : terms[k].factor * valueAt(loaded[k], t));
    sum.time.push_back(t);
    sum.value.push_back(v);
  }
  if (sum.time.empty()) throw std::runtime_error("the series of the expression share no time span");
  return sum;
}

}  // namespace moorsph::app::study
