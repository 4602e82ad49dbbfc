#pragma once
// Exit codes of the moorsph command (documented in docs/scene-reference.md and --help).
namespace moorsph::app {

enum ExitCode : int {
  kSuccess = 0,
  kBadArguments = 1,    ///< command-line error
  kBadInput = 2,        ///< scene file or checkpoint rejected (nothing was run)
  kRunFailed = 3,       ///< numerical failure (SimulationError): failure checkpoint + diagnostic written
  kOutputError = 4,     ///< output could not be written
  kInterrupted = 130,   ///< stopped by SIGINT/SIGTERM after writing a checkpoint
};

}  // namespace moorsph::app
