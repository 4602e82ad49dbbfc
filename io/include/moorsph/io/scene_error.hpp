#pragma once
// The error a scene file raises: its message starts with "file:line:column:" and
// names the key and what was expected, so an editor can jump to the spot.
#include <stdexcept>
#include <string>
#include <vector>

namespace moorsph::io {

class SceneError : public std::runtime_error {
 public:
  SceneError(const std::string& location, const std::string& key, const std::string& message)
      : std::runtime_error(location + ": " + (key.empty() ? "" : "'" + key + "': ") + message),
        location_(location), key_(key) {}
  /// "file:line:column", or "--set key" for a value given on the command line.
  const std::string& location() const { return location_; }
  /// The full key path, e.g. "method.cfl" or "geometry[1].water.lower".
  const std::string& key() const { return key_; }

 private:
  std::string location_;
  std::string key_;
};

/// The candidate closest to `word` by edit distance, or "" if none is close enough to
/// be a likely misspelling (at most a third of the word's letters differ).
std::string closestWord(const std::string& word, const std::vector<std::string>& candidates);

}  // namespace moorsph::io
