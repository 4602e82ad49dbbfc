#pragma once
// What a scene file says, as plain data (docs/scene-reference.md). The loader fills
// and validates these structs before anything is allocated; the builder turns them
// into the fluid scene. Vectors are stored with three entries whatever the dimension
// (the third is unused in 2D), so one struct serves 2D and 3D scenes. SI units.
#include <array>
#include <limits>
#include <string>
#include <utility>
#include <vector>
#include <moorsph/fluid/method_parameters.hpp>
#include <moorsph/io/triangle_mesh.hpp>

namespace moorsph::io {

using Triple = std::array<double, 3>;

/// An axis-aligned box [lower, upper] [m].
struct BoxExtent {
  Triple lower{0.0, 0.0, 0.0};
  Triple upper{0.0, 0.0, 0.0};
};

/// Where a YAML entry came from, for messages after loading ("file:line:column").
struct SourceLocation {
  std::string text;
};

/// A box tank: boundary particles on its inner faces, normals pointing in.
struct TankConfig {
  std::string name = "tank";
  BoxExtent box;
  bool lid = false;          ///< closed top (face +y)
  /// floor: mirror: no floor particles; the "mirror_floor" effect's images close it.
  bool mirror_floor = false;
  /// sides: mirror: no side-wall particles (faces normal to x, and z in 3D); the
  /// "mirror_walls" effect's images close them.
  bool mirror_sides = false;
  bool track_reaction = false;  ///< set when a pressure probe sits on it
  SourceLocation where;
};

/// A box obstacle: boundary particles on its outer faces, normals pointing out.
struct BoxObstacleConfig {
  std::string name = "box";
  BoxExtent box;
  std::vector<std::string> open_faces;  ///< faces left out: "-x", "+x", "-y", "+y", "-z", "+z"
  bool track_reaction = false;
  SourceLocation where;
};

/// A closed triangle mesh (STL/OBJ, 3D only) sampled into boundary particles.
struct MeshConfig {
  std::string name = "mesh";
  std::string shape = "file";   ///< "file", or "sphere" / "cylinder" generated in 3D
  Triple centre{0.0, 0.0, 0.0}; ///< sphere, cylinder [m]
  double radius = 0.0;          ///< sphere, cylinder [m]
  double length = 0.0;          ///< cylinder [m]
  int axis = 2;                 ///< cylinder: 0, 1, 2 for x, y, z
  std::string file;             ///< as written in the scene
  std::string path;             ///< resolved against the scene file's folder
  double scale = 1.0;           ///< file units -> m
  Triple translate{0.0, 0.0, 0.0};  ///< [m], applied after scaling
  bool inward = false;          ///< normals into the enclosed volume (a container)
  bool track_reaction = false;
  TriangleMesh mesh;            ///< scaled and translated [m]
};

/// A cylinder in a 2D scene: a circle in the x-y plane (an obstacle).
struct CircleConfig {
  std::string name = "circle";
  double x = 0.0, y = 0.0;  ///< centre [m]
  double radius = 0.0;      ///< [m]
  bool track_reaction = false;
};

/// A block of water on the fluid lattice.
struct WaterConfig {
  BoxExtent box;
  /// Packed start (fluid/lattice_packing.hpp): the block's lattice relaxed into an even,
  /// disordered arrangement before the run, so a 3D column does not pack down as the
  /// lattice breaks up. Off: the simple cubic lattice.
  bool packed = false;
  int packing_iterations = 400;
  SourceLocation where;
};

/// The piston wave maker (METHOD.md section 4b): a vertical plate at x (its face,
/// water on its +x side) translated by X(t).
struct PistonConfig {
  bool present = false;
  std::string name = "piston";
  double x = 0.0;                 ///< rest position of the face [m]
  double bottom = 0.0, top = 0.0; ///< vertical extent [m]
  double z_lower = 0.0, z_upper = 0.0;  ///< across, 3D only [m]
  std::string signal = "regular"; ///< "regular", "breather" or "table"
  double wave_height = 0.0;       ///< H [m] (regular)
  double period = 0.0;            ///< T [s] (regular)
  double depth = 0.0;             ///< still depth d [m] (regular, breather)
  double ramp_up = 0.0;           ///< [s] (regular, breather)
  /// Peregrine breather (METHOD.md 4c, fluid::waves::BreatherMakerSpec): order, carrier
  /// a0 [m] and k0 [rad/m], focus distance from the face [m] and time [s], rest before
  /// the waves [s], ramp-down at the record's end [s], the record's duration [s].
  int order = 1;
  double a0 = 0.0, k0 = 0.0, focus_distance = 0.0, focus_time = 0.0, still = 0.0, ramp_down = 0.0, duration = 0.0;
  bool finite_depth_correction = false;  ///< pre-compensate the depth's linear dispersion (piston_transfer.hpp)
  std::string table;              ///< CSV t [s], X [m] (table), resolved path
  std::vector<double> table_t, table_x;
};

struct DampingZoneConfig {
  double x_start = 0.0, x_end = 0.0;  ///< [m]
  double k_max = 0.0;                 ///< [1/s]
};

/// The forcing region wave maker (METHOD.md section 4a).
struct ForcingRegionConfig {
  bool present = false;
  double x_start = 0.0, length = 0.0;  ///< [m]
  double floor = 0.0;                  ///< y of the floor [m]
  double bottom_gap = 0.0;             ///< [m]
  double still_level = 0.0;            ///< y of the still surface [m]
  double kappa = 7.0;
  double ramp_up = 0.0;                ///< half-cosine ramp of the target [s]; 0: none (METHOD.md)
  double end_time = std::numeric_limits<double>::infinity();  ///< the forcing stops here [s]
  double gain = 1.0;                   ///< multiplies the target (amplitude calibration)
  std::string theory = "airy";         ///< "airy" or "stokes2"
  double amplitude = 0.0, period = 0.0;  ///< [m], [s]
};

struct GaugeConfig {
  std::string name;
  double x = 0.0;       ///< [m]
  double z = 0.0;       ///< [m], 3D only
  double bottom = 0.0;  ///< [m]
  double top = 1.0;     ///< [m]
  double threshold = 0.8;
  bool volume_edge = true;  ///< add s(xi_t) to the crossing (wave_gauge.hpp); false: the plain crossing
};

struct ProbeConfig {
  std::string name;
  std::string surface;          ///< name of a tank, box, mesh, sphere, cylinder or body
  bool on_body = false;         ///< surface names a body: point and normal in its body frame
  Triple point{0.0, 0.0, 0.0};  ///< [m]
  Triple normal{0.0, 0.0, 0.0}; ///< into the fluid
  double radius = 0.0;          ///< [m]; 0: dx
  double interpolation_offset = 0.0;  ///< [m]; 0: 1.5 dx
  double moving_mean = 0.0;     ///< [s]; > 0 adds trailing means over this window (recorded outputs)
};

/// A velocity probe: the SPH-interpolated fluid velocity at a fixed point
/// (fluid/velocity_probe.hpp).
struct VelocityProbeConfig {
  std::string name;
  Triple point{0.0, 0.0, 0.0};  ///< [m]
  double min_fill = 0.5;        ///< particle density xi below which the point reads dry (NaN)
};

/// A packing probe: the mean particle density xi over a box's grid of points, to watch
/// the particles pack closer than their densities say (fluid/packing_probe.hpp).
struct PackingProbeConfig {
  std::string name;
  Triple lower{0.0, 0.0, 0.0};  ///< [m]
  Triple upper{0.0, 0.0, 0.0};  ///< [m]
  double spacing = 0.0;         ///< grid spacing [m]; 0: 0.618 dx (off the start lattice)
  double min_fill = 0.5;        ///< xi below which a point is dry (left out)
  double warn_rise = 0.005;     ///< the run's log notes the mean rising this far above its first reading; 0: never
};

/// A rigid body's surface, in the body frame (origin = the body's reference point).
struct BodyShapeConfig {
  std::string kind;                 ///< "sphere", "box", "cylinder" or "mesh"
  Triple centre{0.0, 0.0, 0.0};     ///< sphere, box, cylinder: centre in the body frame [m]
  double radius = 0.0;              ///< sphere, cylinder [m]
  /// 3D sphere: "fibonacci" (a Fibonacci lattice) or "rings" (latitude rings, mirror
  /// symmetric: no sideways hydrostatic force; fluid/shape_sampling.hpp).
  std::string sampling = "fibonacci";
  Triple size{0.0, 0.0, 0.0};       ///< box: edge lengths [m]
  double length = 0.0;              ///< cylinder (3D) [m]
  int axis = 2;                     ///< cylinder (3D): 0, 1, 2 for x, y, z
  std::string file, path;           ///< mesh: as written, resolved
  double scale = 1.0;               ///< mesh: file units -> m
  Triple translate{0.0, 0.0, 0.0};  ///< mesh: [m] after scaling, body frame
  TriangleMesh mesh;                ///< mesh, and cylinder in 3D: body frame [m]
};

/// A rigid body (docs/scene-reference.md "bodies"): 2D bodies move in the x-y plane
/// (3 DOF, mass and inertia per metre of span), 3D bodies are free (6 DOF).
struct BodyConfig {
  std::string name;
  double mass = 0.0;                       ///< [kg] (2D: kg/m)
  Triple centre_of_mass{0.0, 0.0, 0.0};    ///< body frame [m]
  /// About the centre of mass, body axes [kg m^2] (2D: only [2][2] = Izz, kg m).
  std::array<Triple, 3> inertia{};
  std::array<bool, 6> fixed{};             ///< x, y, z, rx, ry, rz held
  Triple position{0.0, 0.0, 0.0};          ///< reference point in ground at rest [m]
  Triple orientation{0.0, 0.0, 0.0};       ///< roll (about x), pitch (about z), yaw (about y, up) [rad]; 2D: pitch only; body -> ground R = Ry(yaw) Rz(pitch) Rx(roll)
  Triple offset{0.0, 0.0, 0.0};            ///< initial displacement from `position` [m]
  Triple velocity{0.0, 0.0, 0.0};          ///< initial velocity [m/s]
  BodyShapeConfig shape;
  /// Named body-frame points whose ground positions are recorded (e.g. bow, stern) [m].
  std::vector<std::pair<std::string, Triple>> points;
  /// Green water on the deck (coupling/green_water.hpp): off unless the scene gives it.
  bool green_water = false;
  double deck_height = 0.0;                        ///< body-frame y of the deck [m]
  std::string deck_outline_file;                   ///< resolved path, or "" when given inline
  std::vector<std::array<double, 2>> deck_outline; ///< 3D: (x, z) polygon; 2D: x_min, x_max [m]
  SourceLocation where;
  /// Reference point at t = 0: position + offset.
  Triple start() const { return {position[0] + offset[0], position[1] + offset[1], position[2] + offset[2]}; }
};

/// One end of a mooring line: a point on a body (body frame) or fixed in ground.
struct LineEndConfig {
  std::string body;                 ///< "" = ground
  Triple point{0.0, 0.0, 0.0};      ///< body frame, or ground [m]
};

/// A mooring line (docs/scene-reference.md "moorings"); the fields mirror
/// bodies::MooringLineParams. NaN = not given.
struct MooringConfig {
  std::string name;
  std::string model;  ///< tension_only_spring, cable_path, elastic_catenary, lumped_mass
  LineEndConfig fairlead, anchor;
  static constexpr double kUnset = std::numeric_limits<double>::quiet_NaN();
  double stiffness = kUnset, rest_length = kUnset, pretension = kUnset;  ///< [N/m], [m], [N]
  double damping = 0.0;       ///< [N s/m]
  double dissipation = 0.0;   ///< cable_path [s/m]
  std::vector<LineEndConfig> via_points;  ///< cable_path
  double length = kUnset, axial_stiffness = kUnset, mass_per_length = kUnset;  ///< [m], EA [N], [kg/m]
  double bending_stiffness = 0.0;  ///< EI [N m^2]
  double diameter = 0.0;           ///< [m]
  double seabed_friction = 0.0;
  bool anchor_on_seabed = true;
  int segments = 20;
  double internal_damping_ratio = 1.0;
  double cd_normal = 1.2, cd_axial = 0.0, ca_normal = 1.0, ca_axial = 0.0;
  double time_step = 0.0, relaxation_time = 0.0;  ///< lumped_mass [s]
  double breaking_load = std::numeric_limits<double>::infinity();  ///< [N]; infinity = unbreakable
  SourceLocation where;
};

/// How bodies and fluid exchange loads (coupling/body_coupling.hpp).
struct CouplingConfig {
  double release_time = 0.0;  ///< bodies held while the fluid settles [s]
  double ramp_time = 0.0;     ///< fluid wrench ramped in over this time after release [s]
  double max_step = 1.0e-3;   ///< largest internal step of the body integrator [s]
};

struct OutputConfig {
  double interval = 0.01;            ///< time-series interval [s]
  double particles_interval = 0.0;   ///< particle snapshot interval [s]; 0: none
  double checkpoint_minutes = 30.0;  ///< wall-time interval of checkpoints [min]; 0: at the end only
};

struct SceneConfig {
  std::string file;  ///< where it was read from
  std::string name;
  int dim = 2;
  double end_time = 0.0;  ///< [s]

  // resolution
  double dx = 0.0;                ///< [m]
  double boundary_spacing = 0.0;  ///< [m]; 0: dx

  // fluid
  double rho0 = 1000.0;       ///< [kg/m^3]
  double mu = 1.0e-3;         ///< [Pa s]
  double sound_speed = 0.0;   ///< [m/s]; 0: 10 sqrt(2 g H)
  Triple gravity{0.0, -9.81, 0.0};
  bool hydrostatic_start = true;

  fluid::MethodParameters method = fluid::MethodParameters::reference();
  std::vector<std::string> effects{"pressure", "viscosity", "xsph", "gravity", "walls"};

  bool domain_given = false;
  BoxExtent domain;
  std::array<bool, 3> periodic{false, false, false};

  std::vector<TankConfig> tanks;
  std::vector<BoxObstacleConfig> boxes;
  std::vector<MeshConfig> meshes;
  std::vector<CircleConfig> circles;
  std::vector<WaterConfig> water;
  PistonConfig piston;
  std::vector<DampingZoneConfig> damping_zones;
  ForcingRegionConfig forcing;
  std::vector<GaugeConfig> gauges;
  std::vector<ProbeConfig> probes;
  std::vector<VelocityProbeConfig> velocity_probes;
  std::vector<PackingProbeConfig> packing_probes;
  std::vector<BodyConfig> bodies;
  std::vector<MooringConfig> moorings;
  CouplingConfig coupling;
  OutputConfig output;

  double spacing() const { return boundary_spacing > 0.0 ? boundary_spacing : dx; }
  /// Height of the water column H [m]: highest water top minus lowest water bottom.
  double waterHeight() const;
  /// |gravity| [m/s^2].
  double gravityMagnitude() const;
  /// The speed the scene's water may reach, sqrt(2 g H) [m/s].
  double expectedSpeed() const;
  /// The CFL time step the fluid will take at most [s].
  double cflDt() const;
  bool hasEffect(const std::string& e) const;
  /// True when `box` spans the domain's period along `axis` (a periodic axis).
  bool spansPeriod(const BoxExtent& box, int axis) const;
  /// True when tank `t` has wall particles: a face that is neither a mirror plane nor
  /// dropped because the tank spans a periodic axis normal to it.
  bool hasWallParticles(const TankConfig& t) const;
  /// Index of the named body, or -1.
  int bodyIndex(const std::string& name) const;
};

}  // namespace moorsph::io
