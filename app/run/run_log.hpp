#pragma once
// The run's log: every line goes to DIR/log.txt (flushed at once, so a killed run
// keeps it) and to stdout.
#include <cstdio>
#include <string>

namespace moorsph::app {

class RunLog {
 public:
  /// A fresh run starts the file; `append` continues it.
  explicit RunLog(const std::string& path, bool append = false) : file_(std::fopen(path.c_str(), append ? "a" : "w")) {}
  ~RunLog() {
    if (file_) std::fclose(file_);
  }
  RunLog(const RunLog&) = delete;
  RunLog& operator=(const RunLog&) = delete;
  bool ok() const { return file_ != nullptr; }

  /// A line for both the terminal and the file. `clear_line` erases a progress line first.
  void line(const std::string& text, bool clear_line = false) {
    std::printf("%s%s\n", clear_line ? "\r\033[K" : "", text.c_str());
    std::fflush(stdout);
    if (file_) {
      std::fprintf(file_, "%s\n", text.c_str());
      std::fflush(file_);
    }
  }
  /// A line for the file only.
  void fileOnly(const std::string& text) {
    if (file_) {
      std::fprintf(file_, "%s\n", text.c_str());
      std::fflush(file_);
    }
  }

 private:
  std::FILE* file_;
};

}  // namespace moorsph::app
