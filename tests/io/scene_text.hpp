#pragma once
// Small scenes for the run tests: a 2D dam break at dx = 1 cm (200 fluid particles),
// 0.1 s, with a gauge in the column and a probe on the floor under it.
#include <fstream>
#include <string>

namespace moorsph::test {

inline const char* const kSmallDamBreak = R"(dim: 2
name: small_dam_break
end_time: 0.1
resolution: {dx: 0.01}
fluid: {sound_speed: 28}
method: {density_diffusion: {delta: 0.1}}
effects: [pressure, viscosity, xsph, density_diffusion, gravity, walls]
geometry:
  - tank: {name: tank, lower: [0, 0], upper: [0.4, 0.3], lid: true}
  - water: {lower: [0, 0], upper: [0.1, 0.2]}
gauges:
  - {name: G_col, x: 0.05, top: 0.3}
pressure_probes:
  - {name: P_floor, surface: tank, point: [0.05, 0], normal: [0, 1]}
output: {interval: 0.01, particles_interval: 0.05, checkpoint_minutes: 0}
)";

inline std::string writeScene(const std::string& path, const std::string& text) {
  std::ofstream(path) << text;
  return path;
}

}  // namespace moorsph::test
