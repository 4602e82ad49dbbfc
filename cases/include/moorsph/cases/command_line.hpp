#pragma once
// Strict number arguments for the case drivers' command lines: std::atof reads "abc" or
// "1e-3x" as 0 or 0.001 and the run goes on with it; these stop with the argument named.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

namespace moorsph::cases {

/// The number `text` spells in full; otherwise prints "PROGRAM: WHAT: 'TEXT' is not a
/// number" and exits with status 2.
inline double numberArgument(const std::string& text, const std::string& what, const char* program) {
  std::size_t used = 0;
  double v = 0.0;
  try {
    v = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size() || !std::isfinite(v)) {
    std::fprintf(stderr, "%s: %s: '%s' is not a number\n", program, what.c_str(), text.c_str());
    std::exit(2);
  }
  return v;
}

/// A whole number >= `least`, as numberArgument.
inline int countArgument(const std::string& text, const std::string& what, const char* program, int least) {
  const double v = numberArgument(text, what, program);
  if (v < least || v != std::floor(v) || v > 2e9) {
    std::fprintf(stderr, "%s: %s: expected a whole number >= %d, got '%s'\n", program, what.c_str(), least, text.c_str());
    std::exit(2);
  }
  return static_cast<int>(v);
}

}  // namespace moorsph::cases
