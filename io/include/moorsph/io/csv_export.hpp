#pragma once
// `moorsph export DIR --csv`: every time series of DIR/series.h5 as
// DIR/csv/<group>.<name>.csv, two columns with a header line naming each with its
// SI units, time first:   time [s],kinetic [J]
#include <string>
#include <vector>

namespace moorsph::io {

/// Returns the files written. Throws std::runtime_error if DIR/series.h5 is missing
/// or unreadable.
std::vector<std::string> exportSeriesCsv(const std::string& run_directory);

}  // namespace moorsph::io
