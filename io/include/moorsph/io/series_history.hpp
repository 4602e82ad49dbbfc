#pragma once
// A restart's series.h5 holds the whole run: the rows the interrupted run wrote up to
// its checkpoint are copied into the new file before the restart writes its own, so a
// user (and `moorsph study`, `moorsph plot`, the case reports) reads one series from
// t = 0, as from a run that was never stopped.
#include <string>
#include <vector>
#include <moorsph/io/series_file.hpp>

namespace moorsph::io {

/// One series group of a series.h5 read back: its columns (time excluded, in name
/// order) and rows.
struct SeriesTable {
  std::vector<SeriesColumn> columns;
  std::vector<double> time;                  ///< [s]
  std::vector<std::vector<double>> values;   ///< values[c][row], one vector per column
};

/// Reads group `name` of the series file `path`. Throws std::runtime_error naming the
/// file and the group when either is missing or unreadable.
SeriesTable readSeriesTable(const std::string& path, const std::string& name);

struct CarriedHistory {
  std::size_t rows = 0;               ///< rows copied, over all series
  std::vector<std::string> carried;   ///< series copied
  std::vector<std::string> skipped;   ///< series absent from the earlier file or with other columns
};

/// Appends to `into`, for each series declared in it so far, the rows of the same
/// series in the earlier file `previous` with time <= up_to (the checkpoint's time:
/// rows a run wrote after its last checkpoint are dropped, the restart writes them
/// again). A series is carried only when it has the same column names.
CarriedHistory carrySeriesHistory(const std::string& previous, SeriesFile& into, double up_to);

}  // namespace moorsph::io
