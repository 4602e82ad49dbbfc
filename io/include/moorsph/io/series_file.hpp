#pragma once
// Time series output in HDF5 (series.h5), readable with h5py and ParaView.
//
// Each series is a group holding a `time` dataset [s] and one 1-D dataset per
// column, all extendible and of equal length, each with a `units` attribute:
//   /front/time, /front/x           (dam-break surge front)
//   /energy/time, /energy/kinetic, /energy/potential, ...
// Rows are buffered and written by flush(), which also flushes the file to disk, so
// a run that is killed keeps everything up to its last flush.
#include <memory>
#include <string>
#include <vector>

namespace moorsph::io {

struct SeriesColumn {
  std::string name;
  std::string units;  ///< SI, e.g. "m", "Pa", "J"
};

class SeriesFile {
 public:
  /// Create (truncate) the file. Throws std::runtime_error naming the path on failure.
  explicit SeriesFile(const std::string& path);
  ~SeriesFile();
  SeriesFile(const SeriesFile&) = delete;
  SeriesFile& operator=(const SeriesFile&) = delete;

  /// Declare a series; returns its handle for append().
  int addSeries(const std::string& name, const std::vector<SeriesColumn>& columns, const std::string& description = "");
  /// Buffer one row: time [s] and one value per column.
  void append(int series, double time, const std::vector<double>& values);
  /// Write the buffered rows and flush the file.
  void flush();
  const std::string& path() const { return path_; }
  /// The series declared so far, in the order of addSeries (handles 0 .. seriesCount() - 1).
  int seriesCount() const;
  const std::string& seriesName(int series) const;
  const std::vector<SeriesColumn>& seriesColumns(int series) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::string path_;
};

}  // namespace moorsph::io
