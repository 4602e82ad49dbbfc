// `moorsph study`: the driver. Validates the arguments, runs the scene once per
// (variant, dx) with runScene (so each run directory is an ordinary run directory),
// measures the metric on each, and writes the report (study_report.cpp).
#include "study/study.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <optional>
#include <stdexcept>
#include <yaml-cpp/yaml.h>
#include <moorsph/io/scene_loader.hpp>
#include "run/run_scene.hpp"
#include "study/run_data.hpp"
#include "study/series_expression.hpp"

namespace moorsph::app::study {
namespace {

namespace fs = std::filesystem;

// 17 significant digits: the value the user gave, to the last bit. With 10 a spacing
// like 0.016666666666 (1/60, rounded down so that 0.5 m holds 30 spacings) became
// 0.01666666667, which the water fill counts as 29.99999999 spacings: one layer short.
std::string num(double x) {
  char text[64];
  std::snprintf(text, sizeof text, "%.17g", x);
  return text;
}

std::string knownMetrics() {
  std::string list;
  for (const auto& m : metrics()) list += "\n  " + m.name + ": " + m.summary;
  return list;
}

/// The reference: a number, or a CSV series (needed by error metrics).
struct Reference {
  std::optional<double> value;
  std::optional<Series> series;
};

Reference parseReference(const std::string& text) {
  Reference r;
  if (text.empty()) return r;
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (*end == '\0' && std::isfinite(v)) {
    r.value = v;
    return r;
  }
  if (!fs::exists(text)) throw std::invalid_argument("--reference '" + text + "': neither a number nor an existing file");
  r.series = readCsvSeries(text);
  return r;
}

/// Why a --series expression cannot be read ("" when it can), checked before any run.
std::string expressionProblem(const std::string& series) {
  try {
    parseSeriesExpression(series);
    return "";
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
}

/// The scene's end time as the run resolved it.
double resolvedEndTime(const std::string& run_dir) {
  return YAML::LoadFile(run_dir + "/scene.resolved.yaml")["end_time"].as<double>();
}

double measure(const StudyOptions& o, const std::string& series, const std::string& run_dir, double dx,
               const Series* reference) {
  const auto load = [&](const std::string& name) {
    return name == "front" ? readFrontSeries(run_dir, o.floor, std::isnan(o.band) ? 2.0 * dx : o.band)
                           : readRunSeries(run_dir, name);
  };
  const Series s = combineSeries(parseSeriesExpression(series), load);
  return evaluateMetric(o.metric, s, o.params, reference);
}

std::string runLabel(std::size_t index, double dx) {
  char text[64];
  std::snprintf(text, sizeof text, "%02zu_dx%g", index, dx);
  return text;
}

/// A finished run of the same resolved scene in `run.out` (written by an earlier
/// study): its steps and wall time from study_run.txt, so --reuse need not repeat it.
/// A run that went on past the end this study needs (e.g. a --time metric after a
/// full-length study) is the same scene with a later end_time, and is reused too;
/// `ran_to` is then its end [s], else 0.
bool reusableRun(const RunOptions& run, StudyRow& row, double& ran_to) {
  ran_to = 0.0;
  std::ifstream record(run.out + "/study_run.txt");
  std::ifstream saved(run.out + "/scene.resolved.yaml");
  if (!record || !saved) return false;
  const std::string saved_text(std::istreambuf_iterator<char>(saved), {});
  const double saved_end = YAML::Load(saved_text)["end_time"].as<double>();
  const double needed_end = run.end > 0.0 ? run.end : io::loadSceneFile(run.scene, run.sets).end_time;
  if (saved_end < needed_end) return false;
  std::vector<std::string> sets = run.sets;
  char end[64];
  std::snprintf(end, sizeof end, "end_time=%.17g", saved_end);  // as runScene adds it
  sets.push_back(end);
  if (io::resolvedSceneYaml(io::loadSceneFile(run.scene, sets)) != saved_text) return false;
  if (saved_end > needed_end) ran_to = saved_end;
  std::string key;
  while (record >> key) {
    if (key == "steps") record >> row.steps;
    else if (key == "wall_s") record >> row.wall_seconds;
  }
  return row.steps > 0 && row.wall_seconds > 0.0;
}

std::string variantName(const std::vector<std::string>& assignments) {
  std::string name;
  for (const auto& a : assignments) name += (name.empty() ? "" : " ") + a;
  return name;
}

}  // namespace

int runStudy(const StudyOptions& o) {
  const MetricInfo* metric = findMetric(o.metric);
  if (!metric) {
    std::fprintf(stderr, "error: --metric '%s': unknown metric; known metrics:%s\n", o.metric.c_str(), knownMetrics().c_str());
    return kBadArguments;
  }
  std::vector<double> dxs;
  std::vector<std::vector<std::string>> variants;
  Reference reference;
  try {
    dxs = parseDxList(o.dx_list);
    variants = varyCombinations(o.vary);
    reference = parseReference(o.reference);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return kBadArguments;
  }
  const std::string series = o.series.empty() ? metric->default_series : o.series;
  std::string problem;
  if (series.empty()) problem = "--metric " + o.metric + " needs --series GROUP/COLUMN (e.g. gauges/G_mid)";
  else if (const std::string why = expressionProblem(series); !why.empty()) problem = why;
  else if (metric->needs_time && std::isnan(o.params.time)) problem = "--metric " + o.metric + " needs --time T";
  else if (metric->is_error && !reference.series)
    problem = "--metric " + o.metric + " needs --reference FILE (CSV time,value)";
  else if (!metric->is_error && !reference.value && !reference.series && dxs.size() < 3)
    problem = "without --reference the study needs at least three --dx values (Richardson extrapolate)";
  if (!problem.empty()) {
    std::fprintf(stderr, "error: %s\n", problem.c_str());
    return kBadArguments;
  }
  std::optional<double> given = reference.value;
  double scale = std::numeric_limits<double>::quiet_NaN();
  try {
    if (reference.series && !metric->is_error) given = evaluateMetric(o.metric, *reference.series, o.params);
    if (reference.series && metric->is_error) {
      const double lo = *std::min_element(reference.series->value.begin(), reference.series->value.end());
      const double hi = *std::max_element(reference.series->value.begin(), reference.series->value.end());
      scale = hi > lo ? hi - lo : std::numeric_limits<double>::quiet_NaN();  // RMS error relative to the range
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: --reference %s: %s\n", o.reference.c_str(), e.what());
    return kBadInput;
  }

  const std::string out =
      o.out.empty() ? "moorsph-output/study-" + fs::path(o.scene).stem().string() + "-" + o.metric : o.out;
  std::error_code ec;
  fs::create_directories(out + "/runs", ec);
  if (ec) {
    std::fprintf(stderr, "error: cannot create %s/runs: %s\n", out.c_str(), ec.message().c_str());
    return kOutputError;
  }
  const double end = o.end > 0.0 ? o.end : (metric->needs_time ? 1.02 * o.params.time : 0.0);
  std::vector<StudyRow> rows;
  double simulated = end;
  const std::size_t total = variants.size() * dxs.size();
  for (const auto& variant : variants)
    for (double dx : dxs) {
      StudyRow row;
      row.variant = variantName(variant);
      row.dx = dx;
      RunOptions run;
      run.scene = o.scene;
      run.out = out + "/runs/" + runLabel(rows.size(), dx);
      run.threads = o.threads;
      run.end = end;
      run.sets = o.sets;
      run.sets.insert(run.sets.end(), variant.begin(), variant.end());
      // The walls follow the fluid spacing (boundary_spacing must not exceed dx).
      run.sets.push_back("resolution.dx=" + num(dx));
      run.sets.push_back("resolution.boundary_spacing=" + num(dx));
      run.after_step = [&row](std::size_t steps) { row.steps = steps; };
      std::printf("study run %zu/%zu: dx = %g m%s -> %s\n", rows.size() + 1, total, dx,
                  row.variant.empty() ? "" : (", " + row.variant).c_str(), run.out.c_str());
      std::fflush(stdout);
      bool reused = false;
      double ran_to = 0.0;
      try {
        reused = o.reuse && reusableRun(run, row, ran_to);
      } catch (const std::exception&) {
        reused = false;  // runScene reports a bad scene below
      }
      if (reused) {
        std::printf("study run %zu/%zu: reusing the finished run in %s\n", rows.size() + 1, total, run.out.c_str());
        if (ran_to > 0.0)
          std::printf("  (it ran to %g s, past the %g s needed: its steps and wall time are for the longer run)\n", ran_to,
                      end);
      } else {
        const auto start = std::chrono::steady_clock::now();
        const int code = runScene(run);
        row.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (code != kSuccess) {
          std::fprintf(stderr, "error: study run %s stopped (exit %d); see %s/log.txt\n", run.out.c_str(), code,
                       run.out.c_str());
          return code;
        }
        std::ofstream(run.out + "/study_run.txt") << "steps " << row.steps << "\nwall_s " << num(row.wall_seconds) << "\n";
      }
      try {
        const RunCounts counts = readRunCounts(run.out);
        row.fluid_particles = counts.fluid_particles;
        row.boundary_particles = counts.boundary_particles;
        if (end == 0.0) simulated = resolvedEndTime(run.out);
        row.value = measure(o, series, run.out, dx, reference.series ? &*reference.series : nullptr);
      } catch (const std::exception& e) {
        std::fprintf(stderr,
                     "error: %s: cannot measure %s of '%s': %s\n(a later --end, or more frequent outputs with --set "
                     "output.interval=... / output.particles_interval=..., may be needed)\n",
                     run.out.c_str(), o.metric.c_str(), series.c_str(), e.what());
        return kBadInput;
      }
      std::printf("study run %zu/%zu: %s = %.8g (%zu fluid particles, %zu steps, %.2f s wall)\n", rows.size() + 1,
                  total, o.metric.c_str(), row.value, row.fluid_particles, row.steps, row.wall_seconds);
      rows.push_back(row);
    }
  const auto summaries = analyseStudy(rows, given, metric->is_error, scale);
  if (!writeStudyReport(out, o, rows, summaries, simulated)) return kOutputError;
  std::ifstream md(out + "/study.md");
  std::printf("\n%s", std::string(std::istreambuf_iterator<char>(md), {}).c_str());
  std::printf("\nstudy written to %s (study.md, study.csv, study.png, runs/)\n", fs::absolute(out).c_str());
  return kSuccess;
}

}  // namespace moorsph::app::study
