#include "study/run_data.hpp"

#include <hdf5.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <regex>
#include <stdexcept>
#include <yaml-cpp/yaml.h>

namespace moorsph::app::study {
namespace {

/// Closes an HDF5 handle at scope exit; throws naming `what` when opening failed.
class H5 {
 public:
  H5(hid_t id, herr_t (*close)(hid_t), const std::string& what) : id_(id), close_(close) {
    if (id_ < 0) throw std::runtime_error(what);
  }
  ~H5() { close_(id_); }
  H5(const H5&) = delete;
  H5& operator=(const H5&) = delete;
  operator hid_t() const { return id_; }

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

H5 openFile(const std::string& path) {
  if (!std::filesystem::exists(path)) throw std::runtime_error(path + ": no such file");
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // errors are reported by the exceptions below
  return H5(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose, path + ": cannot open as HDF5");
}

bool exists(hid_t where, const std::string& name) { return H5Lexists(where, name.c_str(), H5P_DEFAULT) > 0; }

std::vector<double> readDoubles(hid_t where, const std::string& name, const std::string& file) {
  H5 set(H5Dopen2(where, name.c_str(), H5P_DEFAULT), H5Dclose, file + ": cannot open dataset " + name);
  H5 space(H5Dget_space(set), H5Sclose, file + ": dataspace of " + name);
  std::vector<double> out(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space)));
  // HDF5 converts integer datasets (the particle type) to double on read.
  if (!out.empty() && H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()) < 0)
    throw std::runtime_error(file + ": cannot read " + name);
  return out;
}

double readTimeAttribute(hid_t group, const std::string& file) {
  H5 attr(H5Aopen(group, "time", H5P_DEFAULT), H5Aclose, file + ": snapshot without a time attribute");
  double t = 0.0;
  if (H5Aread(attr, H5T_NATIVE_DOUBLE, &t) < 0) throw std::runtime_error(file + ": cannot read a snapshot time");
  return t;
}

herr_t collectName(hid_t, const char* name, const H5L_info_t*, void* out) {
  static_cast<std::vector<std::string>*>(out)->push_back(name);
  return 0;
}

/// Index of the axis gravity points along in the run's resolved scene (y if none).
int upAxis(const std::string& run_dir) {
  const std::string path = run_dir + "/scene.resolved.yaml";
  if (!std::filesystem::exists(path)) return 1;
  const YAML::Node g = YAML::LoadFile(path)["fluid"]["gravity"];
  if (!g.IsSequence()) return 1;
  int axis = 1;
  double largest = 0.0;
  for (std::size_t d = 0; d < g.size(); ++d)
    if (std::abs(g[d].as<double>()) > largest) {
      largest = std::abs(g[d].as<double>());
      axis = static_cast<int>(d);
    }
  return axis;
}

}  // namespace

Series readRunSeries(const std::string& run_dir, const std::string& group_column) {
  const std::string path = run_dir + "/series.h5";
  const auto slash = group_column.find('/');
  if (slash == std::string::npos || slash == 0 || slash + 1 == group_column.size())
    throw std::runtime_error("series '" + group_column + "': expected GROUP/COLUMN, e.g. gauges/G_mid");
  const std::string group_name = group_column.substr(0, slash), column = group_column.substr(slash + 1);
  H5 file = openFile(path);
  if (!exists(file, group_name)) throw std::runtime_error(path + ": no series group '" + group_name + "'");
  H5 group(H5Gopen2(file, group_name.c_str(), H5P_DEFAULT), H5Gclose, path + ": cannot open " + group_name);
  if (!exists(group, column)) {
    std::vector<std::string> names;
    H5Literate(group, H5_INDEX_NAME, H5_ITER_INC, nullptr, collectName, &names);
    std::string known;
    for (const auto& n : names)
      if (n != "time") known += (known.empty() ? "" : ", ") + n;
    throw std::runtime_error(path + ": group '" + group_name + "' has no column '" + column + "' (it has: " + known + ")");
  }
  Series s{readDoubles(group, "time", path), readDoubles(group, column, path)};
  const std::size_t rows = std::min(s.time.size(), s.value.size());  // a killed run may differ by one row
  s.time.resize(rows);
  s.value.resize(rows);
  return s;
}

double frontOfSnapshot(const std::vector<double>& position, const std::vector<double>& type, int up_axis, double floor,
                       double band) {
  double front = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < type.size() && 3 * i + 2 < position.size(); ++i)
    if (type[i] == 0.0 && position[3 * i + up_axis] < floor + band) front = std::max(front, position[3 * i]);
  if (!std::isfinite(front)) throw std::runtime_error("no fluid particle within the front band above the floor");
  return front;
}

Series readFrontSeries(const std::string& run_dir, double floor, double band) {
  {
    const std::string series = run_dir + "/series.h5";
    H5 file = openFile(series);
    if (exists(file, "front")) return readRunSeries(run_dir, "front/x");
  }
  const std::string path = run_dir + "/particles.h5";
  if (!std::filesystem::exists(path))
    throw std::runtime_error(path + ": no such file; the front is measured on particle snapshots: set "
                             "output.particles_interval (e.g. --set output.particles_interval=0.01)");
  H5 file = openFile(path);
  H5 snapshots(H5Gopen2(file, "snapshots", H5P_DEFAULT), H5Gclose, path + ": no /snapshots group");
  std::vector<std::string> names;
  H5Literate(snapshots, H5_INDEX_NAME, H5_ITER_INC, nullptr, collectName, &names);
  const int up = upAxis(run_dir);
  Series s;
  for (const auto& name : names) {
    H5 g(H5Gopen2(snapshots, name.c_str(), H5P_DEFAULT), H5Gclose, path + ": cannot open snapshot " + name);
    const double t = readTimeAttribute(g, path);
    try {
      s.value.push_back(frontOfSnapshot(readDoubles(g, "position", path), readDoubles(g, "type", path), up, floor, band));
    } catch (const std::runtime_error& e) {
      throw std::runtime_error(path + ": snapshot " + name + " (t = " + std::to_string(t) + " s): " + e.what());
    }
    s.time.push_back(t);
  }
  return s;
}

Series readCsvSeries(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot read the reference series");
  Series s;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    const char* text = line.c_str();
    char* end = nullptr;
    const double t = std::strtod(text, &end);
    if (end == text) continue;  // header or blank line
    while (*end == ' ' || *end == '\t') ++end;
    if (*end != ',') throw std::runtime_error(path + ":" + std::to_string(number) + ": expected 'time,value'");
    const char* second = end + 1;
    const double v = std::strtod(second, &end);
    if (end == second) throw std::runtime_error(path + ":" + std::to_string(number) + ": expected 'time,value'");
    if (!s.time.empty() && t <= s.time.back())
      throw std::runtime_error(path + ":" + std::to_string(number) + ": times must increase");
    s.time.push_back(t);
    s.value.push_back(v);
  }
  if (s.time.empty()) throw std::runtime_error(path + ": no 'time,value' rows");
  return s;
}

RunCounts readRunCounts(const std::string& run_dir) {
  std::ifstream in(run_dir + "/log.txt");
  const std::regex pattern(R"(([0-9]+) fluid, ([0-9]+) boundary particles)");
  std::string line;
  std::smatch m;
  while (std::getline(in, line))
    if (std::regex_search(line, m, pattern))
      return {static_cast<std::size_t>(std::stoull(m[1])), static_cast<std::size_t>(std::stoull(m[2]))};
  throw std::runtime_error(run_dir + "/log.txt: no particle count line");
}

}  // namespace moorsph::app::study
