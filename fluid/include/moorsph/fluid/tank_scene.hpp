#pragma once
// A box tank from a few parameters: inner size, optional lid, one block of water,
// resolution and method. Used by the built-in dam-break scene, tests and benchmarks.
// The walls' boundary particles lie on the tank's inner faces (the physical wall);
// the water's particles start a half spacing inside them.
#include <moorsph/fluid/box_geometry.hpp>
#include <moorsph/fluid/fluid_setup.hpp>
#include <moorsph/fluid/walls.hpp>

namespace moorsph::fluid {

template <int D>
struct TankSpec {
  Vec<D> size = Vec<D>::Ones();          ///< inner size of the tank [m]; x along, y up
  bool lid = false;                      ///< closed top
  Vec<D> water_lower = Vec<D>::Zero();   ///< water block [m]
  Vec<D> water_upper = Vec<D>::Ones();
  double dx = 0.01;                      ///< fluid spacing [m]
  double boundary_spacing = 0.0;         ///< [m]; 0 means dx
  bool hydrostatic_start = true;         ///< start at hydrostatic density (else uniform rho0)
  FluidSetup<D> fluid;                   ///< properties, method, effects (dx and domain are set here)
};

template <int D>
struct Scene {
  FluidSetup<D> setup;
  FluidParticles<D> fluid;
  BoundaryGeometry<D> boundary;
};

template <int D>
Scene<D> buildTankScene(const TankSpec<D>& spec);

}  // namespace moorsph::fluid
