#pragma once
// One description of a mooring line, many models: a scene names the model with one
// word and keeps the rest of the description (DESIGN.md 4). Each model reads the
// fields it needs; when a spring-type model is given a line description it derives
// its parameters from it (tension_only_spring / cable_path: k = EA / L, L0 = L), so
// "elastic_catenary" -> "lumped_mass" -> "tension_only_spring" swaps need no other edit.
//
// Model words: tension_only_spring, cable_path, elastic_catenary, lumped_mass.

#include <moorsph/bodies/cable_path.hpp>
#include <moorsph/bodies/mooring_line.hpp>

#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace moorsph::bodies {

struct MooringLineParams {
  std::string model;  ///< one of mooringModelNames()
  // Spring description (tension_only_spring, cable_path), optional for line models.
  double stiffness = std::numeric_limits<double>::quiet_NaN();   ///< k, N/m
  double restLength = std::numeric_limits<double>::quiet_NaN();  ///< L0, m
  double pretension = std::numeric_limits<double>::quiet_NaN();  ///< N at the initial pose
  double damping = 0.0;       ///< tension_only_spring, N s/m
  double dissipation = 0.0;   ///< cable_path, s/m (Simbody CableSpring law)
  std::vector<CableViaPoint> viaPoints;  ///< cable_path
  // Line description (elastic_catenary, lumped_mass).
  double length = std::numeric_limits<double>::quiet_NaN();  ///< unstretched L, m
  double axialStiffness = std::numeric_limits<double>::quiet_NaN();  ///< EA, N
  double bendingStiffness = 0.0;  ///< EI, N m^2 (lumped_mass)
  double massPerLength = std::numeric_limits<double>::quiet_NaN();   ///< kg/m in air
  double diameter = 0.0;          ///< volumetric diameter, m
  double waterDensity = 1025.0;   ///< kg/m^3
  double waterSurfaceHeight = std::numeric_limits<double>::infinity();  ///< lumped_mass, m along up
  Eigen::Vector3d gravity{0.0, -9.81, 0.0};  ///< m/s^2
  double seabedFriction = 0.0;    ///< -
  bool anchorOnSeabed = true;     ///< elastic_catenary; lumped_mass seabed contact
  int segments = 20;              ///< lumped_mass
  double internalDampingRatio = 1.0;  ///< lumped_mass
  double cdNormal = 1.2, cdAxial = 0.0, caNormal = 1.0, caAxial = 0.0;  ///< lumped_mass
  double timeStep = 0.0;          ///< lumped_mass, s (0 = automatic)
  double relaxationTime = 0.0;    ///< lumped_mass, s
  double breakingLoad = std::numeric_limits<double>::infinity();  ///< N
};

/// The accepted model words.
std::vector<std::string> mooringModelNames();

/// Builds the named model; throws std::invalid_argument naming the valid words or the
/// missing parameter.
std::unique_ptr<MooringLine> makeMooringLine(const MooringLineParams& params);

}  // namespace moorsph::bodies
