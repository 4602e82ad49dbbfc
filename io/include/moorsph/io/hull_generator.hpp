#pragma once
// A parametric ship hull as a closed triangle mesh (METHOD.md section 6.5; docs/ship-hull.md).
//
// Hull frame: x from the bow (x = 0) aft to the stern (x = L), y up from the keel (y = 0),
// z across from the mid-plane (z = 0). The bow faces -x, as the ship of section 6.5 faces
// the piston; a point given "x toward the bow from the centre of mass" is x_hull = x_G - x.
//
// Shape (half-breadth = B/2 * waterline(x) * section):
//  - waterline: w(x) = 1 - (1 - xi)^p_e over the entrance (xi = x / L_e from the bow),
//    w(x) = t + (1 - t) (1 - (1 - xi)^p_r) over the run (xi = (L - x) / L_r from the stern,
//    t the transom's width fraction), 1 in between (parallel middle body). p = 1 is a
//    wedge, 2 a parabola, large p a blunt end; a transom (t > 0) or an entrance or run of
//    length 0 gives a flat end, closed by a cap.
//  - sections below the draught T: a superellipse |z/(B w/2)|^n + |(T - y)/T|^n = 1
//    (n = 1 a V, 2 an ellipse, large n a box with a sharp bilge); its area coefficient is
//    Gamma(1 + 1/n)^2 / Gamma(1 + 2/n). Above T the sides are vertical up to the flat
//    deck at y = D. Because the shape is separable, displaced volume at draught T is
//    C_s T A_wp and the centre of buoyancy lies above the centre of floatation.
// The stems are vertical. A station whose waterline width is zero collapses onto the
// centreline, so the pointed ends are closed without caps.
#include <optional>
#include <vector>

#include <Eigen/Core>

#include <moorsph/io/triangle_mesh.hpp>

namespace moorsph::io {

struct HullParameters {
  double length = 259.2;            ///< L [m], bow to stern
  double beam = 31.6;               ///< B [m]
  double depth = 23.5;              ///< moulded depth D [m], keel to deck
  double draught = 12.0;            ///< T [m]: height of the curved part of the sections
  double section_exponent = 2.0;    ///< n >= 1
  double entrance_length = 0.0;     ///< L_e [m]
  double run_length = 0.0;          ///< L_r [m]
  double entrance_exponent = 2.0;   ///< p_e >= 1
  double run_exponent = 2.0;        ///< p_r >= 1
  double transom_fraction = 0.0;    ///< t in [0, 1]: stern width / B (0 a pointed stern)
};

/// Throws std::invalid_argument naming the offending parameter.
void validate(const HullParameters& p);

/// w(x) in [0, 1]: half-breadth of the waterline over B/2 at x (0 outside [0, L]).
double waterlineFraction(const HullParameters& p, double x);

/// Area coefficient of the superellipse section, Gamma(1 + 1/n)^2 / Gamma(1 + 2/n).
double sectionCoefficient(double n);

/// The closed, outward-wound hull mesh; stations, section points and deck points are at
/// most max_edge [m] apart (the stations include the ends of the entrance and the run).
TriangleMesh makeHullMesh(const HullParameters& p, double max_edge);

/// The deck edge at y = D as a closed polygon (starboard z > 0 from bow to stern, then
/// port back), at the mesh's stations: what green water on deck is measured inside.
std::vector<Eigen::Vector3d> deckOutline(const HullParameters& p, double max_edge);

/// What a fitted hull must match at its draught T.
struct HullTargets {
  double displaced_volume = 0.0;      ///< [m^3]
  double waterplane_area = 0.0;       ///< [m^2]
  std::optional<double> lcb_from_bow; ///< x of the centre of buoyancy [m]; absent: p_e = p_r
};

/// Solves the mesh's own figures (at this max_edge) for the targets: the waterline for A_wp
/// (without lcb_from_bow: one exponent p_e = p_r; with it: the transom fraction t found by
/// bisection so that the centre of floatation, which is the LCB of this separable shape,
/// lies there, with p_e solved for the area inside and p_r kept), then the section exponent
/// n for the volume. Throws std::invalid_argument when a target cannot be reached with the
/// given L_e, L_r (exponents searched in [1, 1000], t in [0, 1]).
HullParameters fitHull(HullParameters p, const HullTargets& targets, double max_edge);

/// METHOD.md section 6.5 ship, in the hull frame.
struct ShipPreset {
  HullParameters hull;
  HullTargets targets;
  double water_density = 1025.0;   ///< [kg/m^3], seawater: it closes the 13.6 MN cable figure
  double mass = 52196e3;           ///< [kg]
  Eigen::Vector3d centre_of_mass{152.1, 12.6, 0.0};  ///< [m] 152.1 m aft of the bow, 12.6 m above the keel
  Eigen::Vector3d inertia;         ///< principal moments about the CoM [kg m^2]: (roll, yaw, pitch)
  double fairlead_from_bow = 40.0; ///< cables' keel fairleads [m]
  double max_edge = 2.5;           ///< mesh resolution used for the fit [m]
};

/// The section 6.5 targets: displaced volume 55,000 m^3 (weight plus the cables' pull);
/// A_wp = 1000 t / (rho 0.137 m) from the sinkage figure; LCB where buoyancy balances the
/// weight at x_G and the cables' vertical pull (the buoyancy surplus) at the fairleads, so
/// the ship floats without trim. Entrance 0.40 L, parabolic run 0.15 L; p_e, t and n fitted.
/// Inertia from the usual radii of gyration k_roll = 0.35 B, k_pitch = k_yaw = 0.25 L.
ShipPreset section65Ship(double max_edge = 2.5);

}  // namespace moorsph::io
