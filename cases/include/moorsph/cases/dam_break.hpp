#pragma once
// Dam break: a water column of width a and height 2a at the left end of a closed
// tank (Martin & Moyce 1952 geometry). Used by the built-in demo scene, the tests and
// the benchmarks, in 2D and 3D.
#include <moorsph/fluid/tank_scene.hpp>

namespace moorsph::cases {

template <int D>
struct DamBreakSpec {
  double column_width = 0.1;    ///< a [m]
  double tank_length = 0.4;     ///< [m] (4a by default)
  double tank_height = 0.3;     ///< [m]
  double tank_width = 0.1;      ///< [m], 3D only (z)
  double dx = 0.005;            ///< fluid spacing [m]
  bool lid = true;
  std::vector<std::string> effects{"pressure", "viscosity", "xsph", "gravity", "walls"};
  fluid::MethodParameters method = fluid::MethodParameters::reference();
};

/// The scene. c_s = 10 x the Ritter front speed 2 sqrt(g 2a), the largest flow speed.
template <int D>
fluid::Scene<D> buildDamBreak(const DamBreakSpec<D>& spec);

/// Surge front: the largest x of fluid particles on the floor (y < 2 dx) [m].
template <int D>
double measureFront(const fluid::FluidParticles<D>& fluid, double dx);

}  // namespace moorsph::cases
