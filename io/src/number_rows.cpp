// Numeric CSV files named by a scene key (piston tables, deck outlines): the file is
// resolved next to the scene, header and comment lines are skipped, commas or blanks
// separate the numbers.
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <sstream>
#include "scene_sections.hpp"

namespace moorsph::io::detail {

std::string resolveSceneFile(const SceneConfig& c, const std::string& file) {
  const std::filesystem::path path(file);
  return path.is_absolute() ? file : (std::filesystem::path(c.file).parent_path() / path).string();
}

std::vector<NumberRow> readNumberRows(MapReader& m, const std::string& key, const std::string& path,
                                      const std::string& what) {
  std::ifstream in(path);
  if (!in) m.fail(key, "cannot open the " + what + " '" + path + "'");
  std::vector<NumberRow> rows;
  int line_number = 0;
  for (std::string line; std::getline(in, line);) {
    ++line_number;
    if (line.empty() || !(std::isdigit(static_cast<unsigned char>(line[0])) || line[0] == '-' || line[0] == '.')) continue;
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream words(line);
    NumberRow row{line_number, {}};
    for (double x = 0.0; words >> x;) row.values.push_back(x);
    rows.push_back(std::move(row));
  }
  return rows;
}

}  // namespace moorsph::io::detail
