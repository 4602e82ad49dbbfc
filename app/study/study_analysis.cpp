// Argument parsing and the error/order analysis of a study (no I/O).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include "study/convergence.hpp"
#include "study/study.hpp"

namespace moorsph::app::study {
namespace {

std::string num(double x, const char* fmt = "%g") {
  char text[64];
  std::snprintf(text, sizeof text, fmt, x);
  return text;
}

std::string trim(const std::string& s) {
  const auto a = s.find_first_not_of(" \t");
  const auto b = s.find_last_not_of(" \t");
  return a == std::string::npos ? "" : s.substr(a, b - a + 1);
}

/// Index ranges [begin, end) of consecutive rows with the same variant.
std::vector<std::pair<std::size_t, std::size_t>> variantRanges(const std::vector<StudyRow>& rows) {
  std::vector<std::pair<std::size_t, std::size_t>> ranges;
  for (std::size_t k = 0; k < rows.size(); ++k)
    if (k == 0 || rows[k].variant != rows[k - 1].variant) ranges.push_back({k, k + 1});
    else ranges.back().second = k + 1;
  return ranges;
}

}  // namespace

std::vector<std::string> splitTopLevel(const std::string& text) {
  std::vector<std::string> parts(1);
  int depth = 0;
  for (char c : text) {
    if (c == '[' || c == '{') ++depth;
    if (c == ']' || c == '}') --depth;
    if (c == ',' && depth == 0) parts.emplace_back();
    else parts.back() += c;
  }
  for (auto& p : parts) p = trim(p);
  return parts;
}

std::vector<double> parseDxList(const std::string& text) {
  std::vector<double> dx;
  for (const auto& part : splitTopLevel(text)) {
    char* end = nullptr;
    const double v = std::strtod(part.c_str(), &end);
    if (part.empty() || *end != '\0' || !(v > 0.0) || !std::isfinite(v))
      throw std::invalid_argument("--dx '" + text + "': '" + part + "' is not a particle spacing > 0 [m]");
    for (double seen : dx)
      if (seen == v) throw std::invalid_argument("--dx '" + text + "': " + part + " appears twice");
    dx.push_back(v);
  }
  if (dx.size() < 2) throw std::invalid_argument("--dx '" + text + "': a study needs at least two spacings");
  std::sort(dx.begin(), dx.end(), [](double a, double b) { return a > b; });
  return dx;
}

std::vector<std::vector<std::string>> varyCombinations(const std::vector<std::string>& vary) {
  std::vector<std::vector<std::string>> combos(1);
  for (const auto& item : vary) {
    const auto eq = item.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == item.size())
      throw std::invalid_argument("--vary '" + item + "': expected key.path=value1,value2,...");
    const std::string key = trim(item.substr(0, eq));
    const auto values = splitTopLevel(item.substr(eq + 1));
    for (const auto& v : values)
      if (v.empty()) throw std::invalid_argument("--vary '" + item + "': an empty value");
    std::vector<std::vector<std::string>> next;
    for (const auto& c : combos)
      for (const auto& v : values) {
        next.push_back(c);
        next.back().push_back(key + "=" + v);
      }
    combos = std::move(next);
  }
  return combos;
}

std::vector<VariantSummary> analyseStudy(std::vector<StudyRow>& rows, std::optional<double> given, bool error_metric,
                                         double scale) {
  std::vector<VariantSummary> summaries;
  for (const auto& [begin, end] : variantRanges(rows)) {
    VariantSummary s;
    s.variant = rows[begin].variant;
    std::vector<double> h, f;
    for (std::size_t k = begin; k < end; ++k) {
      h.push_back(rows[k].dx);
      f.push_back(rows[k].value);
    }
    if (error_metric) {
      s.reference = 0.0;
      s.reference_source = "the reference series (the metric is an error)";
    } else if (given) {
      s.reference = *given;
      s.reference_source = "given";
    } else {
      std::string why;
      if (const auto r = richardsonFromFinest(h, f, &why)) {
        s.reference = r->estimate;
        s.richardson_order = r->order;
        s.reference_source = "Richardson extrapolate of the three finest runs (observed order " + num(r->order, "%.2f") + ")";
      } else {
        // No extrapolate: measure against the finest run, and say how far the two
        // finest runs are apart (the uncertainty of that reference).
        s.reference = f.back();
        s.finest_is_reference = true;
        const double spread = f.size() >= 2 ? std::abs(f[f.size() - 1] - f[f.size() - 2]) / std::abs(f.back()) : NAN;
        s.reference_source = "the finest run (no Richardson extrapolate: " + why +
                             "); the two finest runs differ by " + num(100.0 * spread, "%.2g") +
                             "%, the uncertainty of this reference";
      }
    }
    const double divide_by = std::isnan(scale) ? std::abs(s.reference) : scale;
    std::vector<double> errors;
    for (std::size_t k = begin; k < end; ++k) {
      auto& row = rows[k];
      row.reference = s.reference;
      row.error = error_metric ? row.value : std::abs(row.value - s.reference);
      row.relative_error = divide_by > 0.0 ? row.error / divide_by : std::numeric_limits<double>::quiet_NaN();
      if (s.finest_is_reference && k + 1 == end) row.error = row.relative_error = NAN;  // zero by construction
      errors.push_back(row.error);
    }
    const auto orders = observedOrders(h, errors);
    for (std::size_t k = 0; k < orders.size(); ++k) rows[begin + k + 1].order = orders[k];
    summaries.push_back(s);
  }
  return summaries;
}

std::vector<std::string> adviceLines(const std::vector<StudyRow>& rows, const std::string& metric, double simulated) {
  std::vector<std::string> lines;
  for (auto [begin, end] : variantRanges(rows)) {
    const std::string who = metric + (rows[begin].variant.empty() ? "" : " (" + rows[begin].variant + ")");
    // Cost scales from the two finest runs, error from the finest with an error (the
    // finest run itself has none when it is the reference).
    const std::size_t all_end = end;
    while (end > begin && std::isnan(rows[end - 1].relative_error)) --end;
    if (end == begin) {
      lines.push_back("for " + who + ": no errors (no reference)");
      continue;
    }
    for (double percent : {10.0, 5.0, 2.0, 1.0}) {
      const double target = percent / 100.0;
      // The coarsest run from which every finer run is within the target.
      std::size_t pick = end;
      for (std::size_t k = end; k-- > begin;) {
        if (!(rows[k].relative_error <= target)) break;
        pick = k;
      }
      if (pick < end) {
        const auto& r = rows[pick];
        lines.push_back("for " + who + " within " + num(percent) + "% use dx <= " + num(r.dx) + " m; it costs " +
                        num(r.wall_seconds, "%.3g") + " s wall for " + num(simulated, "%.3g") + " s simulated (" +
                        std::to_string(r.fluid_particles) + " fluid particles, " + std::to_string(r.steps) +
                        " steps; measured)");
        continue;
      }
      // Not reached: extrapolate with the finest observed order and cost exponent.
      const auto& fine = rows[end - 1];
      if (end - begin < 2 || !(fine.order > 0.0) || !(fine.relative_error > 0.0)) {
        lines.push_back("for " + who + " within " + num(percent) + "% : not reached by the finest run (" +
                        num(100.0 * fine.relative_error, "%.3g") + "%), and no positive observed order to extrapolate");
        continue;
      }
      const double dx = fine.dx * std::pow(target / fine.relative_error, 1.0 / fine.order);
      const auto& cost_fine = rows[all_end - 1];
      const auto& cost_coarse = rows[all_end - 2];
      const double q = std::log(cost_fine.wall_seconds / cost_coarse.wall_seconds) / std::log(cost_coarse.dx / cost_fine.dx);
      const double cost = cost_fine.wall_seconds * std::pow(cost_fine.dx / dx, q);
      lines.push_back("for " + who + " within " + num(percent) + "% use dx <= " + num(dx, "%.3g") + " m; it costs about " +
                      num(cost, "%.3g") + " s wall for " + num(simulated, "%.3g") +
                      " s simulated (extrapolated: error ~ dx^" + num(fine.order, "%.2f") + " from the finest errors, wall ~ dx^-" +
                      num(q, "%.2f") + " from the two finest runs)");
    }
  }
  return lines;
}

}  // namespace moorsph::app::study
