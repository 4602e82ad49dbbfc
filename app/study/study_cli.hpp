#pragma once
// The `moorsph study` subcommand's options (CLI11), kept out of main.cpp.
#include <CLI/CLI.hpp>

#include <string>
#include "study/study.hpp"

namespace moorsph::app::study {

inline CLI::App* addStudyCommand(CLI::App& app, StudyOptions& o) {
  std::string metric_help = "metric to measure on each run:";
  for (const auto& m : metrics()) metric_help += "\n  " + m.name + ": " + m.summary;
  CLI::App* cmd = app.add_subcommand(
      "study", "run a scene at several dx (and --vary values), measure a metric, write error against cost "
               "(study.md, study.csv, study.png) with observed orders and Richardson extrapolation");
  cmd->add_option("scene", o.scene, "scene file (YAML)")->required()->check(CLI::ExistingFile);
  cmd->add_option("--dx", o.dx_list, "particle spacings [m], comma-separated, e.g. 0.02,0.01,0.005 (walls follow dx)")
      ->required();
  cmd->add_option("--metric", o.metric, metric_help)->required();
  cmd->add_option("--series", o.series, "series.h5 column GROUP/COLUMN the metric reads (e.g. gauges/G_mid), or a sum of columns and numbers "
                  "with spaced signs, e.g. \"gauges/G_left - body_box/y + 0.05\" (a draught); a column may carry a factor, "
                  "\"0.5*gauges/G1 + 0.5*gauges/G2\" (a mean)");
  cmd->add_option("--reference", o.reference,
                  "reference: a value, or a CSV file time,value (the metric applied to it; gauge_rms compares with it); "
                  "default: Richardson extrapolate of the three finest runs");
  cmd->add_option("--time", o.params.time, "time [s] for front_position / value_at");
  cmd->add_option("--from", o.params.window.from, "window start [s]");
  cmd->add_option("--to", o.params.window.to, "window end [s]");
  cmd->add_option("--width", o.params.width, "first_peak: half-width [s] a peak must dominate (default 5% of the window)");
  cmd->add_option("--floor", o.floor, "front_position: floor height [m] (default 0)");
  cmd->add_option("--band", o.band, "front_position: band above the floor [m] (default 2 dx)")->check(CLI::PositiveNumber);
  cmd->add_option("--set", o.sets, "override a scene key for every run: key.path=value (repeatable)")->allow_extra_args(false);
  cmd->add_option("--vary", o.vary,
                  "also vary a scene key: key.path=v1,v2 (repeatable; every combination is a variant, e.g. "
                  "--vary method.cfl=0.25,0.5)")
      ->allow_extra_args(false);
  cmd->add_option("--out", o.out, "study directory (default moorsph-output/study-<scene>-<metric>)");
  cmd->add_option("--end", o.end, "simulated end time [s] of each run (default: 1.02 x --time, else the scene's)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--threads", o.threads, "OpenMP threads per run (0: OMP_NUM_THREADS or all cores)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_flag("--reuse", o.reuse,
               "reuse a finished run in the study directory when its resolved scene is the same (its recorded steps and "
               "wall time are kept), e.g. to re-analyse with another metric or --reference");
  return cmd;
}

}  // namespace moorsph::app::study
