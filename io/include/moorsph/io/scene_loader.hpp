#pragma once
// Reads a scene file (YAML, docs/scene-reference.md) into a validated SceneConfig.
// Everything is checked here, before any particle is allocated: unknown or
// misspelled keys, wrong types, missing required keys, out-of-range values and
// inconsistent geometry raise a SceneError naming file:line:column and the key.
#include <string>
#include <vector>
#include <moorsph/io/scene_config.hpp>
#include <moorsph/io/scene_error.hpp>

namespace moorsph::io {

/// Load and validate a scene file. `assignments` are command-line overrides
/// "key.path=value" (e.g. "resolution.dx=0.01", "geometry[1].water.upper=[0.1,0.2]"),
/// applied to the YAML tree before it is read; the value is parsed as YAML.
SceneConfig loadSceneFile(const std::string& path, const std::vector<std::string>& assignments = {});

/// Same, from text; `name` stands for the file name in messages.
SceneConfig loadSceneText(const std::string& text, const std::string& name,
                          const std::vector<std::string>& assignments = {});

/// The scene as YAML with every default filled in (written as scene.resolved.yaml;
/// loading it gives the same SceneConfig).
std::string resolvedSceneYaml(const SceneConfig& config);

/// Effects the fluid code builds, and effects a scene may name that do not exist yet.
const std::vector<std::string>& knownEffects();

}  // namespace moorsph::io
