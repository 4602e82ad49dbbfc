#include <moorsph/io/series_file.hpp>

#include <hdf5.h>

#include <stdexcept>

namespace moorsph::io {
namespace {

void check(herr_t status, const std::string& what) {
  if (status < 0) throw std::runtime_error("HDF5: " + what);
}

void writeStringAttribute(hid_t object, const char* name, const std::string& value) {
  const hid_t type = H5Tcopy(H5T_C_S1);
  H5Tset_size(type, value.empty() ? 1 : value.size());
  H5Tset_strpad(type, H5T_STR_NULLTERM);
  const hid_t space = H5Screate(H5S_SCALAR);
  const hid_t attr = H5Acreate2(object, name, type, space, H5P_DEFAULT, H5P_DEFAULT);
  check(H5Awrite(attr, type, value.empty() ? "" : value.c_str()), std::string("attribute ") + name);
  H5Aclose(attr);
  H5Sclose(space);
  H5Tclose(type);
}

hid_t createExtendible(hid_t group, const std::string& name, const std::string& units) {
  hsize_t dims[1] = {0};
  hsize_t maxdims[1] = {H5S_UNLIMITED};
  hsize_t chunk[1] = {1024};
  const hid_t space = H5Screate_simple(1, dims, maxdims);
  const hid_t props = H5Pcreate(H5P_DATASET_CREATE);
  H5Pset_chunk(props, 1, chunk);
  const hid_t set = H5Dcreate2(group, name.c_str(), H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, props, H5P_DEFAULT);
  H5Pclose(props);
  H5Sclose(space);
  if (set < 0) throw std::runtime_error("HDF5: cannot create dataset " + name);
  writeStringAttribute(set, "units", units);
  return set;
}

void appendValues(hid_t set, hsize_t old_size, const std::vector<double>& values) {
  const hsize_t count[1] = {values.size()};
  const hsize_t new_size[1] = {old_size + values.size()};
  check(H5Dset_extent(set, new_size), "extend dataset");
  const hid_t file_space = H5Dget_space(set);
  const hsize_t start[1] = {old_size};
  H5Sselect_hyperslab(file_space, H5S_SELECT_SET, start, nullptr, count, nullptr);
  const hid_t mem_space = H5Screate_simple(1, count, nullptr);
  check(H5Dwrite(set, H5T_NATIVE_DOUBLE, mem_space, file_space, H5P_DEFAULT, values.data()), "write rows");
  H5Sclose(mem_space);
  H5Sclose(file_space);
}

}  // namespace

struct SeriesFile::Impl {
  struct Series {
    std::string name;
    std::vector<SeriesColumn> columns;
    hid_t group = -1;
    std::vector<hid_t> sets;               // time first, then one per column
    std::vector<std::vector<double>> pending;  // buffered values per set
    hsize_t written = 0;
  };
  hid_t file = -1;
  std::vector<Series> series;
};

SeriesFile::SeriesFile(const std::string& path) : impl_(std::make_unique<Impl>()), path_(path) {
  impl_->file = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  if (impl_->file < 0) throw std::runtime_error(path + ": cannot create HDF5 file");
}

SeriesFile::~SeriesFile() {
  try {
    flush();
  } catch (...) {
  }
  for (auto& s : impl_->series) {
    for (hid_t set : s.sets) H5Dclose(set);
    H5Gclose(s.group);
  }
  if (impl_->file >= 0) H5Fclose(impl_->file);
}

int SeriesFile::addSeries(const std::string& name, const std::vector<SeriesColumn>& columns,
                          const std::string& description) {
  Impl::Series s;
  s.name = name;
  s.columns = columns;
  s.group = H5Gcreate2(impl_->file, name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  if (s.group < 0) throw std::runtime_error(path_ + ": cannot create series '" + name + "'");
  if (!description.empty()) writeStringAttribute(s.group, "description", description);
  s.sets.push_back(createExtendible(s.group, "time", "s"));
  for (const auto& c : columns) s.sets.push_back(createExtendible(s.group, c.name, c.units));
  s.pending.resize(s.sets.size());
  impl_->series.push_back(std::move(s));
  return static_cast<int>(impl_->series.size()) - 1;
}

void SeriesFile::append(int series, double time, const std::vector<double>& values) {
  auto& s = impl_->series.at(series);
  if (values.size() + 1 != s.sets.size()) throw std::invalid_argument("series row has the wrong number of values");
  s.pending[0].push_back(time);
  for (std::size_t c = 0; c < values.size(); ++c) s.pending[c + 1].push_back(values[c]);
}

int SeriesFile::seriesCount() const { return static_cast<int>(impl_->series.size()); }
const std::string& SeriesFile::seriesName(int series) const { return impl_->series.at(series).name; }
const std::vector<SeriesColumn>& SeriesFile::seriesColumns(int series) const { return impl_->series.at(series).columns; }

void SeriesFile::flush() {
  for (auto& s : impl_->series) {
    if (s.pending[0].empty()) continue;
    for (std::size_t c = 0; c < s.sets.size(); ++c) {
      appendValues(s.sets[c], s.written, s.pending[c]);
    }
    s.written += s.pending[0].size();
    for (auto& p : s.pending) p.clear();
  }
  check(H5Fflush(impl_->file, H5F_SCOPE_GLOBAL), "flush " + path_);
}

}  // namespace moorsph::io
