#include <moorsph/io/series_history.hpp>

#include <cmath>
#include <stdexcept>
#include "h5_helpers.hpp"

namespace moorsph::io {
namespace {

herr_t collectName(hid_t, const char* name, const H5L_info_t*, void* out) {
  static_cast<std::vector<std::string>*>(out)->push_back(name);
  return 0;
}

std::string unitsOf(hid_t group, const std::string& name) {
  h5::Handle set(H5Dopen2(group, name.c_str(), H5P_DEFAULT), H5Dclose, "open " + name);
  return h5::hasAttribute(set, "units") ? h5::readStringAttribute(set, "units") : "";
}

/// For each column of `wanted`, its index in `held`; empty when the two sets of names differ.
std::vector<std::size_t> matchColumns(const std::vector<SeriesColumn>& wanted, const std::vector<SeriesColumn>& held) {
  if (wanted.size() != held.size()) return {};
  std::vector<std::size_t> index;
  for (const auto& w : wanted) {
    std::size_t k = 0;
    while (k < held.size() && held[k].name != w.name) ++k;
    if (k == held.size()) return {};
    index.push_back(k);
  }
  return index;
}

}  // namespace

SeriesTable readSeriesTable(const std::string& path, const std::string& name) {
  h5::Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose, path + ": cannot open as HDF5");
  if (H5Lexists(file, name.c_str(), H5P_DEFAULT) <= 0) throw std::runtime_error(path + ": no series '" + name + "'");
  h5::Handle group(H5Gopen2(file, name.c_str(), H5P_DEFAULT), H5Gclose, path + ": open series " + name);
  std::vector<std::string> names;  // by name: SeriesFile does not track creation order
  H5Literate(group, H5_INDEX_NAME, H5_ITER_INC, nullptr, collectName, &names);
  SeriesTable t;
  t.time = h5::readDoubles(group, "time");
  for (const auto& column : names) {
    if (column == "time") continue;
    t.columns.push_back({column, unitsOf(group, column)});
    t.values.push_back(h5::readDoubles(group, column));
    if (t.values.back().size() != t.time.size())
      throw std::runtime_error(path + ": series " + name + "/" + column + " has " + std::to_string(t.values.back().size()) +
                               " rows, its time " + std::to_string(t.time.size()));
  }
  return t;
}

CarriedHistory carrySeriesHistory(const std::string& previous, SeriesFile& into, double up_to) {
  CarriedHistory h;
  // A row written at the checkpoint's own time belongs to the history; round-off in
  // the sum of steps must not drop it.
  const double last = up_to + 1e-9 * std::max(1.0, std::abs(up_to));
  for (int s = 0; s < into.seriesCount(); ++s) {
    SeriesTable old;
    try {
      old = readSeriesTable(previous, into.seriesName(s));
    } catch (const std::runtime_error&) {
      h.skipped.push_back(into.seriesName(s));
      continue;
    }
    const std::vector<std::size_t> column = matchColumns(into.seriesColumns(s), old.columns);
    if (column.size() != into.seriesColumns(s).size()) {
      h.skipped.push_back(into.seriesName(s));
      continue;
    }
    std::vector<double> row(column.size());
    for (std::size_t r = 0; r < old.time.size() && old.time[r] <= last; ++r) {
      for (std::size_t c = 0; c < row.size(); ++c) row[c] = old.values[column[c]][r];
      into.append(s, old.time[r], row);
      ++h.rows;
    }
    h.carried.push_back(into.seriesName(s));
  }
  return h;
}

}  // namespace moorsph::io
