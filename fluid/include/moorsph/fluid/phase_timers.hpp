#pragma once
// Wall time accumulated per phase of the step (neighbour search, pair forces, each
// effect, integration, checks): how a run shows what its accuracy costs in time.
#include <chrono>
#include <string>
#include <vector>

namespace moorsph::fluid {

class PhaseTimers {
 public:
  /// Register a phase; returns its index.
  int add(const std::string& name) {
    names_.push_back(name);
    seconds_.push_back(0.0);
    return static_cast<int>(names_.size()) - 1;
  }
  const std::vector<std::string>& names() const { return names_; }
  /// Accumulated wall time per phase [s], in the order of names().
  const std::vector<double>& seconds() const { return seconds_; }

  /// Times the enclosing scope into one phase.
  class Scope {
   public:
    Scope(PhaseTimers& timers, int phase) : timers_(timers), phase_(phase), start_(std::chrono::steady_clock::now()) {}
    ~Scope() {
      timers_.seconds_[phase_] += std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    }
    Scope(const Scope&) = delete;
    Scope& operator=(const Scope&) = delete;

   private:
    PhaseTimers& timers_;
    int phase_;
    std::chrono::steady_clock::time_point start_;
  };

 private:
  std::vector<std::string> names_;
  std::vector<double> seconds_;
};

}  // namespace moorsph::fluid
