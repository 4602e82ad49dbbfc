#pragma once
// Turns a validated SceneConfig into the fluid scene: setup (properties, method,
// effects, domain), fluid particles, boundary surfaces (tanks first, then boxes, in
// file order; then the piston and the bodies), and the specs of the scene's gauges, pressure
// probes and velocity probes.
#include <string>
#include <vector>
#include <moorsph/fluid/fluid_simulation.hpp>
#include <moorsph/fluid/packing_probe.hpp>
#include <moorsph/fluid/pressure_probe.hpp>
#include <moorsph/fluid/tank_scene.hpp>
#include <moorsph/fluid/velocity_probe.hpp>
#include <moorsph/fluid/wave_gauge.hpp>
#include <moorsph/io/scene_config.hpp>

namespace moorsph::io {

template <int D>
struct BuiltScene {
  fluid::Scene<D> scene;
  std::vector<std::string> gauge_names;
  std::vector<fluid::WaveGaugeSpec<D>> gauges;
  std::vector<std::string> probe_names;
  std::vector<double> probe_means;  ///< per probe: moving-mean window [s], 0 = none
  std::vector<fluid::PressureProbeSpec<D>> probes;
  std::vector<std::string> velocity_probe_names;
  std::vector<fluid::VelocityProbeSpec<D>> velocity_probes;
  std::vector<std::string> packing_probe_names;
  std::vector<fluid::PackingProbeSpec<D>> packing_probes;
  std::vector<double> packing_warn_rises;  ///< per packing probe: rise of xi the log notes, 0 = none
  std::size_t piston_surface = 0;  ///< index of the piston's surface, if the scene has one
  /// Per body of the scene (in order): its surface, movable and reaction-tracking,
  /// with its reference point at the body's start position.
  std::vector<std::size_t> body_surfaces;
  /// Things the user should know that do not stop the run (printed by `check` and in
  /// the run's log), e.g. a water block whose height is not a whole number of spacings.
  std::vector<std::string> notes;
};

/// What buildScene does with the water blocks.
enum class WaterBuild {
  Particles,  ///< fill, pack and cut them round obstacles and bodies (a run from t = 0, `check`)
  Skip,       ///< leave scene.fluid empty: for a restart, whose particles come from its checkpoint
              ///< (the 4 m ship's restart: 1.9 s against 69.4 s with the water built)
};

/// Builds the particles. `config.dim` must equal D.
template <int D>
BuiltScene<D> buildScene(const SceneConfig& config, WaterBuild water = WaterBuild::Particles);

/// Adds the effects FluidSimulation does not build from its effect list (the wave
/// makers: piston, damping_zone, forcing_region), in that order. Call once, right after
/// constructing the simulation from `built`.
template <int D>
void addSceneEffects(fluid::FluidSimulation<D>& sim, const SceneConfig& config, const BuiltScene<D>& built);

/// The FluidSetup alone (no particles): what `moorsph check` reports before building.
template <int D>
fluid::FluidSetup<D> makeSetup(const SceneConfig& config);

/// Particle counts without building: fluid from the water lattices (an upper bound
/// where boxes or meshes displace water), boundary from the tank and box lattices
/// (exact for closed boxes; meshes are not counted).
struct ParticleCounts {
  std::size_t fluid = 0;
  std::size_t boundary = 0;
};
ParticleCounts countParticles(const SceneConfig& config);

}  // namespace moorsph::io
