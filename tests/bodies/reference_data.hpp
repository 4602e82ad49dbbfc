// Where the tests find external reference data: the workplace's canonical copy in
// ../shared/refdata first, then the copy vendored in tests/data/refdata (so that a clean
// clone without ../shared passes). Both are tried relative to MOORSPH_SOURCE_DIR (set
// by ctest) and to this file's own source location.
#pragma once

#include <cstdlib>
#include <fstream>
#include <string>

namespace moorsph::test {

inline std::string referenceDataPath(const std::string& relative) {
  const std::string here = __FILE__;
  const std::string sourceFromFile = here.substr(0, here.rfind("/tests/bodies/"));
  const char* env = std::getenv("MOORSPH_SOURCE_DIR");
  const std::string sources[] = {env ? std::string(env) : sourceFromFile, sourceFromFile};
  for (const std::string& root : sources)
    for (const char* folder : {"/../shared/refdata/", "/tests/data/refdata/"}) {
      const std::string path = root + folder + relative;
      if (std::ifstream(path).good()) return path;
    }
  return sourceFromFile + "/tests/data/refdata/" + relative;  // missing: the reader reports it
}

}  // namespace moorsph::test
