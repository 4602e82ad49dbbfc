#pragma once
// What `moorsph study` reads back from a run directory (docs/scene-reference.md,
// "Output"): a column of series.h5, the surge front from the particle snapshots of
// particles.h5, the particle and step counts from log.txt; and a reference series
// from a CSV file. Every failure throws std::runtime_error naming the file.
#include <cstddef>
#include <string>
#include "study/metrics.hpp"

namespace moorsph::app::study {

/// DIR/series.h5 column "group/column", e.g. "gauges/G_mid", "front/x".
Series readRunSeries(const std::string& run_dir, const std::string& group_column);

/// The surge front of a dam break: at each particle snapshot of DIR/particles.h5, the
/// largest x of the fluid particles within `band` [m] above `floor` [m] (the vertical
/// axis is the one gravity points along in DIR/scene.resolved.yaml), as used by the
/// dam-break demo (cases::measureFront, band 2 dx). Uses DIR/series.h5 front/x when
/// the run wrote that series.
Series readFrontSeries(const std::string& run_dir, double floor, double band);

/// Fluid-only largest x within the band, from one snapshot's plain arrays (3 values
/// per particle, type 0 = fluid). Throws if no fluid particle lies in the band.
double frontOfSnapshot(const std::vector<double>& position, const std::vector<double>& type, int up_axis, double floor,
                       double band);

/// A reference series from CSV: two columns time,value; lines that do not start with
/// a number (a header) are skipped.
Series readCsvSeries(const std::string& path);

struct RunCounts {
  std::size_t fluid_particles = 0, boundary_particles = 0;
};
/// From the scene line of DIR/log.txt ("N fluid, M boundary particles").
RunCounts readRunCounts(const std::string& run_dir);

}  // namespace moorsph::app::study
