#pragma once
// SPHERIC Test 2: a 3-D dam break hitting a box obstacle (Kleefsman, Fekken, Veldman,
// Iwanowski & Buchner 2005, J. Comput. Phys. 206:363-393; test-case description by
// Issa & Violeau 2006). MARIN measured water heights at four vertical gauges and
// pressures on the box face that the water hits.
//
// Geometry in moorsph's frame (x along the tank, y up, z across; metres). The
// benchmark's documents use z up and y across: their (x, y, z) is our (x, z, y).
//   tank      3.22 (x) x 1.0 (y, height) x 1.0 (z), open top
//   water     x in [1.992, 3.22], 0.55 deep, full width, at rest behind a gate at t = 0
//   box       x in [0.6635, 0.8245], y in [0, 0.161], z in [0.2955, 0.6985], on the floor;
//             the water hits its face x = 0.8245
//   gauges    vertical lines at z = 0.5 and x = 1.488, 0.992, 0.496, 2.638, named
//             H1..H4 after the columns of the data file they compare with (the file's
//             "H1" is the gauge nearest the gate, x = 1.488, its "H3" the one behind the
//             box, x = 0.496; see refdata README and docs/validation/spheric-test2.md)
//   pressure  P1..P4 on the face x = 0.8245 at z = 0.471 and heights 0.021, 0.061,
//             0.101, 0.141 (the documents' "y = 0.471" is across, their "z" height)
//
// Method: the reference preset of METHOD.md (pressure, Cleary viscosity, XSPH, gravity,
// boundary-normal walls) with an option for density diffusion. The sound speed is
// 10 x the Ritter front speed 2 sqrt(g H), H = 0.55 m: 46.5 m/s.
#include <array>
#include <string>
#include <vector>
#include <moorsph/fluid/pressure_probe.hpp>
#include <moorsph/fluid/tank_scene.hpp>
#include <moorsph/fluid/wave_gauge.hpp>

namespace moorsph::cases::spheric_test2 {

constexpr double kTankLength = 3.22;    ///< [m]
constexpr double kTankHeight = 1.0;     ///< [m]
constexpr double kTankWidth = 1.0;      ///< [m]
constexpr double kGateX = 1.992;        ///< water column starts here [m]
constexpr double kWaterDepth = 0.55;    ///< [m]
constexpr double kBoxLowerX = 0.6635, kBoxUpperX = 0.8245;  ///< [m]
constexpr double kBoxLowerZ = 0.2955, kBoxUpperZ = 0.6985;  ///< [m]
constexpr double kBoxHeight = 0.161;    ///< [m]
constexpr double kGravity = 9.81;       ///< [m/s^2]

struct NamedPoint {
  const char* name;
  double x, y, z;  ///< [m], moorsph frame
};
/// Gauges in the data file's column order (y unused).
constexpr std::array<NamedPoint, 4> kGauges{{{"H1", 1.488, 0.0, 0.5},
                                             {"H2", 0.992, 0.0, 0.5},
                                             {"H3", 0.496, 0.0, 0.5},
                                             {"H4", 2.638, 0.0, 0.5}}};
/// Pressure sensors on the box face x = 0.8245.
constexpr std::array<NamedPoint, 4> kPressureSensors{{{"P1", kBoxUpperX, 0.021, 0.471},
                                                      {"P2", kBoxUpperX, 0.061, 0.471},
                                                      {"P3", kBoxUpperX, 0.101, 0.471},
                                                      {"P4", kBoxUpperX, 0.141, 0.471}}};

/// Ritter's dam-break front speed 2 sqrt(g H) [m/s], the largest flow speed expected.
double ritterFrontSpeed();

struct Spec {
  /// Fluid spacing asked for [m]. Unless `exact_depth` is off it is adjusted to
  /// 0.55 m / round(0.55 m / dx), so the lattice holds the column's depth exactly
  /// (fillBox fills whole layers: dx = 0.04 would lose 3 cm of depth, 5% of the water).
  double dx = 0.04;
  bool exact_depth = true;
  double boundary_spacing = 0.0;   ///< [m]; 0 means dx
  bool density_diffusion = false;  ///< add the density-diffusion term (off in the reference method)
  /// Monaghan's XSPH form instead of METHOD.md's (which slows particles where the kernel
  /// is truncated, e.g. the surge front: sum_j V_j W_ij < 1 there).
  bool xsph_monaghan = false;
  double sound_speed = 0.0;        ///< [m/s]; 0 means 10 x ritterFrontSpeed()
};

struct Built {
  fluid::Scene<3> scene;
  std::size_t tank_surface = 0;
  std::size_t box_surface = 0;
  double boundary_spacing = 0.0;   ///< the spacing asked for [m] (faces use the largest lattice step <= it)
};

Built build(const Spec& spec);

/// The spacing build() uses for a requested one [m].
double adjustedSpacing(const Spec& spec);

/// The four gauges (kGauges order), lines from the floor to the top of the tank, with
/// particle-density threshold xi_t (METHOD.md section 3 uses 0.8).
std::vector<fluid::WaveGauge<3>> makeGauges(double threshold = 0.8);

/// The four probes (kPressureSensors order) on the box's tracked surface: patch radius
/// one fluid spacing, interpolation point 1.5 spacings in front of the face (nearer,
/// the over-compressed first fluid row next to a wall biases it high: see test_fluid_sensors). The face's
/// lattice steps along y and z differ a little (each divides its edge exactly): the
/// probes' tile is their geometric mean, so |P| tiles have the patch's true area.
std::vector<fluid::PressureProbe<3>> makeProbes(const fluid::FluidSimulation<3>& sim, const Built& built);

}  // namespace moorsph::cases::spheric_test2
