#pragma once
// `moorsph study SCENE.yaml --dx 0.02,0.01,0.005 --metric NAME [--reference VALUE|FILE]`:
// runs a scene at several particle spacings (and, with --vary, for several values of
// other scene keys), measures one metric on each run, and writes to the output
// directory study.md and study.csv (dx, particles, steps, wall time, value, error,
// observed order) and study.png (error against wall time and against particle count,
// log-log). Without --reference the Richardson extrapolate of the three finest runs
// is the reference (study/convergence.hpp). See docs/accuracy-cost.md.
#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>
#include "study/metrics.hpp"

namespace moorsph::app::study {

struct StudyOptions {
  std::string scene;
  std::string out;                   ///< "" = moorsph-output/study-<scene name>-<metric>
  std::string dx_list;               ///< "0.02,0.01,0.005"
  std::string metric;
  std::string series;                ///< GROUP/COLUMN of series.h5; "" = the metric's default
  std::string reference;             ///< a number, a CSV file (time,value), or "" (Richardson)
  std::vector<std::string> sets;     ///< key.path=value for every run
  std::vector<std::string> vary;     ///< key.path=v1,v2,... (each a variant; all combinations)
  MetricParams params;
  double end = 0.0;                  ///< simulated end [s]; 0: --time x 1.02 for value-at metrics, else the scene's
  double floor = 0.0;                ///< front_position: floor height [m]
  double band = std::numeric_limits<double>::quiet_NaN();  ///< front_position: band above it [m]; NaN: 2 dx
  int threads = 0;
  bool reuse = false;                ///< keep finished runs of the same resolved scene (study_run.txt)
};

/// Comma-separated positive spacings, at least two distinct; returned coarse to fine.
/// Throws std::invalid_argument naming the bad entry.
std::vector<double> parseDxList(const std::string& text);
/// Split at commas outside [] and {} (so a YAML list can be one value).
std::vector<std::string> splitTopLevel(const std::string& text);
/// Every combination of the --vary values, as lists of "key=value" assignments.
std::vector<std::vector<std::string>> varyCombinations(const std::vector<std::string>& vary);

/// One run of the study.
struct StudyRow {
  std::string variant;   ///< "" without --vary, else "key=value key=value"
  double dx = 0.0;
  std::size_t fluid_particles = 0, boundary_particles = 0, steps = 0;
  double wall_seconds = 0.0;
  double value = 0.0;
  double reference = std::numeric_limits<double>::quiet_NaN();
  double error = std::numeric_limits<double>::quiet_NaN();           ///< |value - reference| (or value, for error metrics)
  double relative_error = std::numeric_limits<double>::quiet_NaN();  ///< error / scale
  double order = std::numeric_limits<double>::quiet_NaN();           ///< from this run and the next coarser one
};

/// How the reference of a variant was obtained.
struct VariantSummary {
  std::string variant;
  std::string reference_source;       ///< "given", "file ...", "Richardson (p = ...)", or why none
  double reference = std::numeric_limits<double>::quiet_NaN();
  std::optional<double> richardson_order;
  bool finest_is_reference = false;   ///< no extrapolate: errors are differences from the finest run
};

/// Fill reference, errors and observed orders of the rows of each variant (rows in
/// run order, coarse to fine within a variant). `given` is the reference value when
/// one was given; `scale` divides errors into relative errors (NaN: |reference|).
std::vector<VariantSummary> analyseStudy(std::vector<StudyRow>& rows, std::optional<double> given, bool error_metric,
                                         double scale);

/// "for METRIC within Y% use dx <= ..; it costs .." lines for Y = 10, 5, 2, 1 %.
std::vector<std::string> adviceLines(const std::vector<StudyRow>& rows, const std::string& metric, double simulated);

/// Write study.md, study.csv (and study.png through /usr/bin/python3 when it has
/// matplotlib); returns false with a message on stderr when a file cannot be written.
bool writeStudyReport(const std::string& out, const StudyOptions& o, const std::vector<StudyRow>& rows,
                      const std::vector<VariantSummary>& summaries, double simulated);
/// study.png from study.csv; returns the exit status of the plotting script (0 written,
/// 77 or 127 python/matplotlib missing).
int plotStudy(const std::string& out, const std::string& title);

int runStudy(const StudyOptions& o);

}  // namespace moorsph::app::study
