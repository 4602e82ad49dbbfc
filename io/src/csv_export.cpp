#include <moorsph/io/csv_export.hpp>

#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include "h5_helpers.hpp"

namespace moorsph::io {
namespace {

herr_t collectName(hid_t, const char* name, const H5L_info_t*, void* out) {
  static_cast<std::vector<std::string>*>(out)->push_back(name);
  return 0;
}

std::vector<std::string> members(hid_t group) {
  std::vector<std::string> names;
  H5Literate(group, H5_INDEX_NAME, H5_ITER_INC, nullptr, collectName, &names);
  return names;
}

std::string unitsOf(hid_t group, const std::string& name) {
  h5::Handle set(H5Dopen2(group, name.c_str(), H5P_DEFAULT), H5Dclose, "open " + name);
  return h5::hasAttribute(set, "units") ? h5::readStringAttribute(set, "units") : "";
}

}  // namespace

std::vector<std::string> exportSeriesCsv(const std::string& dir) {
  const std::string path = dir + "/series.h5";
  if (!std::filesystem::exists(path)) throw std::runtime_error(path + ": no such file (is " + dir + " a run directory?)");
  h5::Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose, path + ": cannot open");
  const std::string out_dir = dir + "/csv";
  std::filesystem::create_directories(out_dir);
  std::vector<std::string> written;
  for (const auto& group_name : members(file)) {
    H5O_info_t info;
    if (H5Oget_info_by_name2(file, group_name.c_str(), &info, H5O_INFO_BASIC, H5P_DEFAULT) < 0 || info.type != H5O_TYPE_GROUP)
      continue;
    h5::Handle group(H5Gopen2(file, group_name.c_str(), H5P_DEFAULT), H5Gclose, "open " + group_name);
    const std::vector<double> time = h5::readDoubles(group, "time");
    for (const auto& name : members(group)) {
      if (name == "time") continue;
      const std::vector<double> values = h5::readDoubles(group, name);
      const std::string units = unitsOf(group, name);
      const std::string csv = out_dir + "/" + group_name + "." + name + ".csv";
      std::FILE* f = std::fopen(csv.c_str(), "w");
      if (!f) throw std::runtime_error(csv + ": cannot write");
      std::fprintf(f, "time [s],%s [%s]\n", name.c_str(), units.c_str());
      for (std::size_t k = 0; k < time.size() && k < values.size(); ++k) std::fprintf(f, "%.17g,%.17g\n", time[k], values[k]);
      std::fclose(f);
      written.push_back(csv);
    }
  }
  return written;
}

}  // namespace moorsph::io
