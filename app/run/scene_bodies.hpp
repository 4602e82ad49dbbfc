#pragma once
// A scene's rigid bodies and mooring lines as a bodies::MultibodySystem, and the
// co-simulation that couples them to the fluid (coupling/co_simulation.hpp); the time
// series they add to series.h5; their state in checkpoints. Used by `moorsph run`
// and `moorsph check` when a scene has bodies.
#include <memory>
#include <string>
#include <vector>
#include <moorsph/cases/run_recorder.hpp>
#include <moorsph/coupling/co_simulation.hpp>
#include <moorsph/io/scene_builder.hpp>

namespace moorsph::app {

/// The multibody system of the scene, initialized (line pretensions resolved at the
/// rest pose, i.e. `position` without `offset`, for tension-only springs).
std::unique_ptr<bodies::MultibodySystem> buildSceneBodies(const io::SceneConfig& config);

/// Co-simulation of the built fluid scene and the scene's bodies. The fluid is built
/// from `particles` (the scene's, or a checkpoint's); `restore` (may be empty) is a
/// packed SystemSnapshot from a checkpoint.
template <int D>
std::unique_ptr<coupling::CoSimulation<D>> makeCoSimulation(const io::SceneConfig& config, const io::BuiltScene<D>& built,
                                                             const fluid::FluidParticles<D>& particles,
                                                             const std::vector<double>& restore);

/// Roll (about x), pitch (about z), yaw (about y, up) [rad] of a body -> ground rotation
/// R = Ry(yaw) Rz(pitch) Rx(roll):
/// pitch in [-pi/2, pi/2], roll and yaw in (-pi, pi].
Eigen::Vector3d rollPitchYaw(const Eigen::Quaterniond& orientation);

/// SystemSnapshot <-> a flat list of numbers for checkpoint.h5 (dataset "bodies").
std::vector<double> packSnapshot(const bodies::SystemSnapshot& snapshot);
bodies::SystemSnapshot unpackSnapshot(const std::vector<double>& packed);

/// Adds /bodies.<name> (pose, roll/pitch/yaw, velocities, fluid wrench), /lines.<name>
/// (tensions, slack, broken), /ledger (energy ledger) and /coupling_timing.
template <int D>
void attachBodySeries(cases::RunRecorder<D>& recorder, const coupling::CoSimulation<D>& co, const io::SceneConfig& config);

/// Lines for `moorsph check` and the run log: bodies (mass, DOF, draught numbers) and
/// lines (model, end points, initial tension).
std::vector<std::string> describeBodies(const io::SceneConfig& config, const bodies::MultibodySystem& system);

}  // namespace moorsph::app
