#pragma once
// Shared by the io tests that run scenes or the moorsph binary: a fresh output
// directory, RunOptions for a short run, and running the CLI with its output captured
// (the including test defines MOORSPH_BINARY, the built program's path).
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace moorsph::test_support {

/// An empty directory under the test's temporary directory.
inline std::string freshDir(const std::string& name) {
  const std::string dir = testing::TempDir() + name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

/// A series exported by `moorsph export --csv` (DIR/csv/GROUP.NAME.csv: header, then
/// time,value rows): the times and the values.
struct ExportedSeries {
  std::vector<double> time, value;
};
inline ExportedSeries exportedSeries(const std::string& dir, const std::string& series) {
  std::ifstream in(dir + "/csv/" + series + ".csv");
  std::string line;
  std::getline(in, line);
  ExportedSeries out;
  while (std::getline(in, line)) {
    const auto comma = line.find(',');
    out.time.push_back(std::stod(line.substr(0, comma)));
    out.value.push_back(std::stod(line.substr(comma + 1)));
  }
  return out;
}

struct CliResult {
  int code = -1;
  std::string output;  ///< stdout and stderr together
};

#ifdef MOORSPH_BINARY
/// Runs `moorsph ARGUMENTS` and returns its exit code and output.
inline CliResult runMoorsph(const std::string& arguments) {
  CliResult r;
  std::FILE* pipe = popen((std::string(MOORSPH_BINARY) + " " + arguments + " 2>&1").c_str(), "r");
  char buffer[512];
  while (pipe && std::fgets(buffer, sizeof buffer, pipe)) r.output += buffer;
  const int status = pipe ? pclose(pipe) : -1;
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}
#endif

}  // namespace moorsph::test_support
