#pragma once
// Section readers of the scene loader (private to io/).
#include <moorsph/io/scene_config.hpp>
#include "yaml_reader.hpp"

namespace moorsph::io::detail {

/// Reads `geometry`, `gauges` and `pressure_probes`; needs dim, dx and the boundary spacing.
void readGeometry(MapReader& top, SceneConfig& config);
void readSensors(MapReader& top, SceneConfig& config);
/// Reads `piston`, `damping_zones`, `forcing_region`; needs geometry and the method.
void readWaveMakers(MapReader& top, SceneConfig& config);
/// Reads `bodies`, `moorings` and `coupling`; needs geometry and effects.
void readBodies(MapReader& top, SceneConfig& config);
/// One item of `moorings`; needs the bodies.
MooringConfig readMooring(MapReader& m, const SceneConfig& config, std::size_t index);
/// Writes `bodies`, `moorings` and `coupling` into scene.resolved.yaml (nothing without bodies).
void writeBodySections(YAML::Emitter& e, const SceneConfig& config);
/// Reads `method` on top of the reference preset.
void readMethod(MapReader& top, SceneConfig& config);

/// One numeric row of a CSV file and its line number (for messages).
struct NumberRow {
  int line = 0;
  std::vector<double> values;
};
/// A file named in a scene, resolved against the scene file's folder.
std::string resolveSceneFile(const SceneConfig& c, const std::string& file);
/// The numeric rows of `path` (header and comment lines skipped); a file that cannot be
/// opened fails on `key` as "cannot open the <what> '<path>'".
std::vector<NumberRow> readNumberRows(MapReader& m, const std::string& key, const std::string& path,
                                      const std::string& what);

/// A vector of the scene's dimension, padded to three entries.
Triple toTriple(const std::vector<double>& v);

}  // namespace moorsph::io::detail
