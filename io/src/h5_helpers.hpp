#pragma once
// Small helpers over the HDF5 C API shared by the particle, checkpoint and export
// code (private to io/). Every failure throws std::runtime_error naming what failed.
#include <hdf5.h>

#include <cstdint>
#include <string>
#include <vector>

namespace moorsph::io::h5 {

/// Closes an HDF5 handle when it goes out of scope.
class Handle {
 public:
  using Closer = herr_t (*)(hid_t);
  Handle(hid_t id, Closer close, const std::string& what);
  ~Handle();
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  operator hid_t() const { return id_; }

 private:
  hid_t id_;
  Closer close_;
};

void writeStringAttribute(hid_t object, const char* name, const std::string& value);
void writeDoubleAttribute(hid_t object, const char* name, double value);
std::string readStringAttribute(hid_t object, const char* name);
double readDoubleAttribute(hid_t object, const char* name);
bool hasAttribute(hid_t object, const char* name);

/// A dataset of rows x cols (cols = 1 writes a 1-D dataset) with a units attribute.
void writeDoubles(hid_t where, const std::string& name, const std::vector<double>& data, std::size_t cols,
                  const std::string& units);
void writeInt32(hid_t where, const std::string& name, const std::vector<std::int32_t>& data, const std::string& units);
void writeInt64(hid_t where, const std::string& name, const std::vector<std::int64_t>& data, const std::string& units);
std::vector<double> readDoubles(hid_t where, const std::string& name);
std::vector<std::int64_t> readInt64(hid_t where, const std::string& name);

}  // namespace moorsph::io::h5
