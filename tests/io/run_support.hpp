#pragma once
// Shared by the io tests that run scenes or the moorsph binary: a fresh output
// directory, RunOptions for a short run, and running the CLI with its output captured
// (the including test defines MOORSPH_BINARY, the built program's path).
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <string>

namespace moorsph::test_support {

/// An empty directory under the test's temporary directory.
inline std::string freshDir(const std::string& name) {
  const std::string dir = testing::TempDir() + name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
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
