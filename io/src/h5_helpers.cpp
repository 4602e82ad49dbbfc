#include "h5_helpers.hpp"

#include <stdexcept>

namespace moorsph::io::h5 {

Handle::Handle(hid_t id, Closer close, const std::string& what) : id_(id), close_(close) {
  if (id_ < 0) throw std::runtime_error("HDF5: " + what);
}
Handle::~Handle() { close_(id_); }

void writeStringAttribute(hid_t object, const char* name, const std::string& value) {
  Handle type(H5Tcopy(H5T_C_S1), H5Tclose, "string type");
  H5Tset_size(type, value.empty() ? 1 : value.size());
  H5Tset_strpad(type, H5T_STR_NULLTERM);
  Handle space(H5Screate(H5S_SCALAR), H5Sclose, "scalar space");
  Handle attr(H5Acreate2(object, name, type, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose,
              std::string("create attribute ") + name);
  if (H5Awrite(attr, type, value.c_str()) < 0) throw std::runtime_error(std::string("HDF5: write attribute ") + name);
}

void writeDoubleAttribute(hid_t object, const char* name, double value) {
  Handle space(H5Screate(H5S_SCALAR), H5Sclose, "scalar space");
  Handle attr(H5Acreate2(object, name, H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose,
              std::string("create attribute ") + name);
  if (H5Awrite(attr, H5T_NATIVE_DOUBLE, &value) < 0) throw std::runtime_error(std::string("HDF5: write attribute ") + name);
}

bool hasAttribute(hid_t object, const char* name) { return H5Aexists(object, name) > 0; }

std::string readStringAttribute(hid_t object, const char* name) {
  Handle attr(H5Aopen(object, name, H5P_DEFAULT), H5Aclose, std::string("open attribute ") + name);
  Handle type(H5Aget_type(attr), H5Tclose, "attribute type");
  if (H5Tis_variable_str(type) > 0) {
    char* text = nullptr;
    Handle mem(H5Tget_native_type(type, H5T_DIR_ASCEND), H5Tclose, "native type");
    if (H5Aread(attr, mem, &text) < 0) throw std::runtime_error(std::string("HDF5: read attribute ") + name);
    std::string out = text ? text : "";
    H5free_memory(text);
    return out;
  }
  std::string buffer(H5Tget_size(type), '\0');
  if (H5Aread(attr, type, buffer.data()) < 0) throw std::runtime_error(std::string("HDF5: read attribute ") + name);
  return std::string(buffer.c_str());
}

double readDoubleAttribute(hid_t object, const char* name) {
  Handle attr(H5Aopen(object, name, H5P_DEFAULT), H5Aclose, std::string("open attribute ") + name);
  double v = 0.0;
  if (H5Aread(attr, H5T_NATIVE_DOUBLE, &v) < 0) throw std::runtime_error(std::string("HDF5: read attribute ") + name);
  return v;
}

namespace {
void writeRaw(hid_t where, const std::string& name, hid_t file_type, hid_t mem_type, const void* data, std::size_t rows,
              std::size_t cols, const std::string& units) {
  const hsize_t dims[2] = {rows, cols};
  Handle space(H5Screate_simple(cols == 1 ? 1 : 2, dims, nullptr), H5Sclose, "dataspace");
  Handle set(H5Dcreate2(where, name.c_str(), file_type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Dclose,
             "create dataset " + name);
  if (rows > 0 && H5Dwrite(set, mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) < 0)
    throw std::runtime_error("HDF5: write dataset " + name);
  writeStringAttribute(set, "units", units);
}
}  // namespace

void writeDoubles(hid_t where, const std::string& name, const std::vector<double>& data, std::size_t cols,
                  const std::string& units) {
  writeRaw(where, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, data.data(), data.size() / cols, cols, units);
}
void writeInt32(hid_t where, const std::string& name, const std::vector<std::int32_t>& data, const std::string& units) {
  writeRaw(where, name, H5T_STD_I32LE, H5T_NATIVE_INT32, data.data(), data.size(), 1, units);
}
void writeInt64(hid_t where, const std::string& name, const std::vector<std::int64_t>& data, const std::string& units) {
  writeRaw(where, name, H5T_STD_I64LE, H5T_NATIVE_INT64, data.data(), data.size(), 1, units);
}

namespace {
std::size_t elementCount(hid_t set) {
  Handle space(H5Dget_space(set), H5Sclose, "dataspace");
  const hssize_t n = H5Sget_simple_extent_npoints(space);
  return n < 0 ? 0 : static_cast<std::size_t>(n);
}
}  // namespace

std::vector<double> readDoubles(hid_t where, const std::string& name) {
  Handle set(H5Dopen2(where, name.c_str(), H5P_DEFAULT), H5Dclose, "open dataset " + name);
  std::vector<double> out(elementCount(set));
  if (!out.empty() && H5Dread(set, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()) < 0)
    throw std::runtime_error("HDF5: read dataset " + name);
  return out;
}

std::vector<std::int64_t> readInt64(hid_t where, const std::string& name) {
  Handle set(H5Dopen2(where, name.c_str(), H5P_DEFAULT), H5Dclose, "open dataset " + name);
  std::vector<std::int64_t> out(elementCount(set));
  if (!out.empty() && H5Dread(set, H5T_NATIVE_INT64, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()) < 0)
    throw std::runtime_error("HDF5: read dataset " + name);
  return out;
}

}  // namespace moorsph::io::h5
