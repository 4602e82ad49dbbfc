#include "yaml_reader.hpp"

#include <algorithm>
#include <cmath>

namespace moorsph::io::detail {

std::string dottedPath(const std::string& path) {
  std::string out;
  for (char c : path) {
    if (c == '[') out += '.';
    else if (c != ']') out += c;
  }
  return out;
}

std::string YamlSource::locate(const YAML::Node& node, const std::string& path) const {
  const std::string dotted = dottedPath(path);
  for (const auto& o : overridden)
    if (dotted == o || dotted.rfind(o + ".", 0) == 0) return "--set " + o;
  if (node.IsDefined() && node.Mark().line >= 0)
    return file + ":" + std::to_string(node.Mark().line + 1) + ":" + std::to_string(node.Mark().column + 1);
  return file;
}

void YamlSource::fail(const YAML::Node& node, const std::string& path, const std::string& message) const {
  throw SceneError(locate(node, path), path, message);
}

std::string describeNode(const YAML::Node& node) {
  if (!node.IsDefined() || node.IsNull()) return "nothing";
  if (node.IsSequence()) return "a list";
  if (node.IsMap()) return "a map";
  return "'" + node.Scalar() + "'";
}

MapReader::MapReader(const YAML::Node& node, std::string path, const YamlSource& source)
    : node_(node), path_(std::move(path)), source_(source) {
  if (!node_.IsMap()) source_.fail(node_, path_.empty() ? "(top level)" : path_, "expected a map of keys, got " + describeNode(node_));
}

bool MapReader::has(const std::string& key) const {
  const YAML::Node c = node_[key];
  return c.IsDefined() && !c.IsNull();
}

YAML::Node MapReader::child(const std::string& key) {
  known_.push_back(key);
  return node_[key];
}

void MapReader::fail(const std::string& key, const std::string& message) const {
  const YAML::Node c = node_[key];
  source_.fail(c.IsDefined() ? c : node_, childPath(key), message);
}

YAML::Node MapReader::required(const std::string& key, const std::string& what) {
  const YAML::Node c = child(key);
  if (!c.IsDefined() || c.IsNull())
    source_.fail(node_, childPath(key), "required key is missing (expected " + what + ")");
  return c;
}

namespace {
bool readNumber(const YAML::Node& n, double& out) {
  if (!n.IsScalar()) return false;
  if (!YAML::convert<double>::decode(n, out)) return false;
  return std::isfinite(out);
}
}  // namespace

double MapReader::number(const std::string& key, double fallback) {
  const YAML::Node c = child(key);
  if (!c.IsDefined() || c.IsNull()) return fallback;
  double v = 0.0;
  if (!readNumber(c, v)) fail(key, "expected a number, got " + describeNode(c));
  return v;
}

double MapReader::requiredNumber(const std::string& key) {
  const YAML::Node c = required(key, "a number");
  double v = 0.0;
  if (!readNumber(c, v)) fail(key, "expected a number, got " + describeNode(c));
  return v;
}

int MapReader::integer(const std::string& key, int fallback) {
  const YAML::Node c = child(key);
  if (!c.IsDefined() || c.IsNull()) return fallback;
  int v = 0;
  if (!c.IsScalar() || !YAML::convert<int>::decode(c, v)) fail(key, "expected an integer, got " + describeNode(c));
  return v;
}

bool MapReader::boolean(const std::string& key, bool fallback) {
  const YAML::Node c = child(key);
  if (!c.IsDefined() || c.IsNull()) return fallback;
  bool v = false;
  if (!c.IsScalar() || !YAML::convert<bool>::decode(c, v)) fail(key, "expected true or false, got " + describeNode(c));
  return v;
}

std::string MapReader::text(const std::string& key, const std::string& fallback) {
  const YAML::Node c = child(key);
  if (!c.IsDefined() || c.IsNull()) return fallback;
  if (!c.IsScalar()) fail(key, "expected a word, got " + describeNode(c));
  return c.Scalar();
}

std::string MapReader::requiredText(const std::string& key) {
  const YAML::Node c = required(key, "a word");
  if (!c.IsScalar()) fail(key, "expected a word, got " + describeNode(c));
  return c.Scalar();
}

std::vector<double> MapReader::vector(const std::string& key, std::size_t n) {
  const YAML::Node c = required(key, "a list of " + std::to_string(n) + " numbers");
  return vector(key, n, {});
}

std::vector<double> MapReader::vector(const std::string& key, std::size_t n, const std::vector<double>& fallback) {
  const YAML::Node c = child(key);
  if (!c.IsDefined() || c.IsNull()) return fallback;
  const std::string expected = "expected a list of " + std::to_string(n) + " numbers (one per axis of the " +
                               std::to_string(n) + "D scene)";
  if (!c.IsSequence()) fail(key, expected + ", got " + describeNode(c));
  if (c.size() != n) fail(key, expected + ", got " + std::to_string(c.size()) + " entries");
  std::vector<double> out(n);
  for (std::size_t k = 0; k < n; ++k)
    if (!readNumber(c[k], out[k]))
      source_.fail(c[k], childPath(key) + "[" + std::to_string(k) + "]", "expected a number, got " + describeNode(c[k]));
  return out;
}

std::vector<std::string> MapReader::textList(const std::string& key, const std::vector<std::string>& fallback) {
  const YAML::Node c = child(key);
  if (!c.IsDefined() || c.IsNull()) return fallback;
  if (!c.IsSequence()) fail(key, "expected a list of words, got " + describeNode(c));
  std::vector<std::string> out;
  for (std::size_t k = 0; k < c.size(); ++k) {
    if (!c[k].IsScalar())
      source_.fail(c[k], childPath(key) + "[" + std::to_string(k) + "]", "expected a word, got " + describeNode(c[k]));
    out.push_back(c[k].Scalar());
  }
  return out;
}

double MapReader::positive(const std::string& key, double fallback, const std::string& what, bool allow_zero) {
  const double v = number(key, fallback);
  if (allow_zero ? v < 0.0 : !(v > 0.0))
    fail(key, std::string("expected ") + (allow_zero ? "a number >= 0" : "a number > 0") + " (" + what + "), got " +
                  describeNode(node_[key]));
  return v;
}

void MapReader::rejectUnsupported(const std::vector<std::string>& keys, const std::string& why) {
  for (const auto& k : keys) {
    known_.push_back(k);
    if (node_[k].IsDefined()) fail(k, "not supported yet: " + why);
  }
}

void MapReader::finish() const {
  for (auto it = node_.begin(); it != node_.end(); ++it) {
    const std::string key = it->first.as<std::string>();
    if (std::find(known_.begin(), known_.end(), key) != known_.end()) continue;
    const std::string guess = closestWord(key, known_);
    std::string known_list;
    for (const auto& k : known_) known_list += (known_list.empty() ? "" : ", ") + k;
    source_.fail(it->first, childPath(key),
                 "unknown key" + (guess.empty() ? std::string() : " (did you mean '" + guess + "'?)") +
                     "; known keys here: " + known_list);
  }
}

}  // namespace moorsph::io::detail
