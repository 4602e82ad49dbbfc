// `moorsph plot DIR`: runs the plotting script compiled into the binary (no install
// path to find) with /usr/bin/python3, the interpreter Debian's python3-h5py and
// python3-matplotlib belong to.
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include "plot_script.hpp"
#include "run/run_scene.hpp"

namespace moorsph::app {

int plotRun(const std::string& directory) {
  const char* python = std::getenv("MOORSPH_PYTHON") ? std::getenv("MOORSPH_PYTHON") : "/usr/bin/python3";
  const std::string script =
      (std::filesystem::temp_directory_path() / ("moorsph_plot_" + std::to_string(getpid()) + ".py")).string();
  {
    std::ofstream out(script);
    out << kPlotScript;
    if (!out) {
      std::fprintf(stderr, "error: cannot write %s\n", script.c_str());
      return kOutputError;
    }
  }
  const std::string command = std::string(python) + " '" + script + "' '" + directory + "'";
  const int status = std::system(command.c_str());
  std::filesystem::remove(script);
  const int code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  if (code == 0) return kSuccess;
  if (code == 2) return kBadInput;
  if (code == 77 || code == 127) {
    std::fprintf(stderr, "error: plotting needs %s with h5py and matplotlib\n", python);
    return kOutputError;
  }
  std::fprintf(stderr, "error: the plotting script failed (exit %d)\n", code);
  return kOutputError;
}

}  // namespace moorsph::app
