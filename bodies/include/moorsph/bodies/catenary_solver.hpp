#pragma once
// Elastic catenary with seabed contact and friction in the line's vertical plane
// (Irvine 1981, "Cable Structures"; seabed/friction form of Jonkman 2007, NREL/TP-500-
// 41958, section 4.1.1, as also used by FAST v7, MAP++ and MoorPy). Units: N, m.
//
// Inputs: horizontal span x and vertical span z (upper end = fairlead above the lower
// end = anchor), unstretched length L, axial stiffness EA, submerged weight per unit
// length w > 0, seabed friction coefficient cb (only if the anchor lies on the seabed).
// Unknowns: fairlead horizontal and vertical line tension components HF, VF.
//
// Fully suspended (VF >= wL, or the lower end is not on a seabed), VA = VF - wL:
//   x = HF/w [asinh(VF/HF) - asinh(VA/HF)] + HF L/EA
//   z = HF/w [sqrt(1+(VF/HF)^2) - sqrt(1+(VA/HF)^2)] + (VF L - w L^2/2)/EA
// Resting on the seabed over LB = L - VF/w:
//   x = LB + HF/w asinh(VF/HF) + HF L/EA
//         + cb w/(2EA) [ -LB^2 + (LB - HF/(cb w)) max(LB - HF/(cb w), 0) ]
//   z = HF/w [sqrt(1+(VF/HF)^2) - 1] + VF^2/(2 EA w)
//   HA = max(HF - cb w LB, 0), VA = 0.
// Solved by Newton's method on (HF, VF) with an analytic Jacobian, started from the
// Peyrot & Goulois (1979) estimate; converged to a relative residual of 1e-12.

#include <Eigen/Core>

#include <vector>

namespace moorsph::bodies {

struct CatenaryInput {
  double horizontalSpan = 0.0;  ///< x >= 0, m
  double verticalSpan = 0.0;    ///< z (fairlead above anchor) >= 0, m
  double length = 0.0;          ///< unstretched L, m
  double axialStiffness = 0.0;  ///< EA, N
  double weightPerLength = 0.0; ///< w, submerged weight per unstretched metre, N/m (> 0)
  double seabedFriction = 0.0;  ///< cb >= 0
  bool anchorOnSeabed = true;   ///< false: the lower end hangs free (no contact)
};

struct CatenarySolution {
  double fairleadHorizontal = 0.0;  ///< HF, N
  double fairleadVertical = 0.0;    ///< VF, N (upward pull on the line at the fairlead)
  double anchorHorizontal = 0.0;    ///< HA, N
  double anchorVertical = 0.0;      ///< VA, N
  double seabedLength = 0.0;        ///< LB, m (unstretched length lying on the seabed)
  int iterations = 0;
  double fairleadTension() const;
  double anchorTension() const;
};

/// Solves the catenary; throws std::runtime_error if Newton does not converge or the
/// geometry is impossible (e.g. the span exceeds what any tension can stretch to).
CatenarySolution solveCatenary(const CatenaryInput& in);

/// Point of the line at unstretched arc length s from the anchor, as
/// (horizontal, vertical) offsets from the anchor, m.
Eigen::Vector2d catenaryPoint(const CatenaryInput& in, const CatenarySolution& sol, double s);

/// Line tension at unstretched arc length s from the anchor, N.
double catenaryTension(const CatenaryInput& in, const CatenarySolution& sol, double s);

}  // namespace moorsph::bodies
