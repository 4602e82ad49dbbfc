#pragma once
// Checked reading of a YAML map: every read names its key; values of the wrong type,
// missing required keys and keys nobody asked for (with the closest known key as a
// suggestion) raise a SceneError at the node's file:line:column. Private to io/.
#include <yaml-cpp/yaml.h>

#include <set>
#include <string>
#include <vector>
#include <moorsph/io/scene_error.hpp>

namespace moorsph::io::detail {

/// The file being read and the key paths that came from --set (they have no line).
struct YamlSource {
  std::string file;
  std::set<std::string> overridden;  ///< dotted paths, e.g. "geometry.1.tank.lower"

  /// "file:line:column" of a node, or "--set key" if the key was overridden.
  std::string locate(const YAML::Node& node, const std::string& path) const;
  [[noreturn]] void fail(const YAML::Node& node, const std::string& path, const std::string& message) const;
};

/// "a.b[1].c" -> "a.b.1.c"
std::string dottedPath(const std::string& path);
/// A readable type name of a node, for "expected X, got Y".
std::string describeNode(const YAML::Node& node);

class MapReader {
 public:
  /// `node` must be a map (else SceneError naming `path`).
  MapReader(const YAML::Node& node, std::string path, const YamlSource& source);

  bool has(const std::string& key) const;
  /// The raw child (marks the key as known). Undefined if absent.
  YAML::Node child(const std::string& key);
  std::string childPath(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }

  double number(const std::string& key, double fallback);
  double requiredNumber(const std::string& key);
  int integer(const std::string& key, int fallback);
  bool boolean(const std::string& key, bool fallback);
  std::string text(const std::string& key, const std::string& fallback);
  std::string requiredText(const std::string& key);
  /// A list of `n` numbers (n = 2 or 3: a vector in the scene's dimension).
  std::vector<double> vector(const std::string& key, std::size_t n);
  std::vector<double> vector(const std::string& key, std::size_t n, const std::vector<double>& fallback);
  std::vector<std::string> textList(const std::string& key, const std::vector<std::string>& fallback);

  /// A value that must be > 0 (or >= 0 with allow_zero); `what` says the unit and meaning.
  double positive(const std::string& key, double fallback, const std::string& what, bool allow_zero = false);

  /// Keys that name features the code does not have yet: present => "not supported yet".
  void rejectUnsupported(const std::vector<std::string>& keys, const std::string& why);
  /// Every key present but never asked for is an error, with the closest known key.
  void finish() const;

  [[noreturn]] void fail(const std::string& key, const std::string& message) const;
  const YAML::Node& node() const { return node_; }
  const std::string& path() const { return path_; }
  const YamlSource& source() const { return source_; }

 private:
  YAML::Node required(const std::string& key, const std::string& what);

  YAML::Node node_;
  std::string path_;
  const YamlSource& source_;
  std::vector<std::string> known_;
};

/// Reads the list under `key` of `top`: read(m, i) for its i-th entry, a MapReader at path
/// "key[i]". Absent or null: nothing. Not a list: SceneError "expected a list of <what>".
template <class Read>
void forEachListEntry(MapReader& top, const std::string& key, const std::string& what, Read&& read) {
  const YAML::Node list = top.child(key);
  if (!list.IsDefined() || list.IsNull()) return;
  if (!list.IsSequence()) top.fail(key, "expected a list of " + what + ", got " + describeNode(list));
  for (std::size_t i = 0; i < list.size(); ++i) {
    MapReader m(list[i], top.childPath(key) + "[" + std::to_string(i) + "]", top.source());
    read(m, i);
  }
}

}  // namespace moorsph::io::detail
