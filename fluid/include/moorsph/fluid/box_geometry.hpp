#pragma once
// Geometry builders for boxes: a box tank's walls, a box obstacle's surface, and a
// block of fluid particles on a lattice.
#include <algorithm>
#include <array>
#include <vector>
#include <moorsph/fluid/boundary_particles.hpp>
#include <moorsph/fluid/fluid_particles.hpp>
#include <moorsph/fluid/fluid_setup.hpp>
#include <moorsph/fluid/tait_eos.hpp>

namespace moorsph::fluid {

/// Which faces of a box exist: face 2k is the lower face along axis k, 2k+1 the upper.
template <int D>
using BoxFaces = std::array<bool, 2 * D>;

template <int D>
BoxFaces<D> allFaces() {
  BoxFaces<D> f;
  f.fill(true);
  return f;
}

/// A tank open at the top (no upper face along y).
template <int D>
BoxFaces<D> openTopTank() {
  BoxFaces<D> f = allFaces<D>();
  f[2 * 1 + 1] = false;
  return f;
}

/// A box tank's faces: open at the top unless it has a lid, without its floor (-y)
/// face when the mirror_floor effect's plane takes its place, and without its side
/// faces (normal to x, and z in 3D) when the mirror_walls effect's planes do.
template <int D>
BoxFaces<D> tankFaces(bool lid, bool mirror_floor, bool mirror_walls = false) {
  BoxFaces<D> f = lid ? allFaces<D>() : openTopTank<D>();
  if (mirror_floor) f[2 * 1] = false;
  if (mirror_walls)
    for (int k = 0; k < D; ++k)
      if (k != 1) f[2 * k] = f[2 * k + 1] = false;
  return f;
}

/// The mirror_walls effect's planes for the side faces of the box [lower, upper].
template <int D>
std::vector<MirrorPlane> sideMirrorPlanes(const Vec<D>& lower, const Vec<D>& upper) {
  std::vector<MirrorPlane> planes;
  for (int k = 0; k < D; ++k) {
    if (k == 1) continue;
    planes.push_back(MirrorPlane{k, lower[k], +1});
    planes.push_back(MirrorPlane{k, upper[k], -1});
  }
  return planes;
}

enum class NormalSide { Inward, Outward };

/// Boundary particles on the present faces of the box [lower, upper], on a lattice
/// whose spacing is the largest not exceeding `spacing` that divides each edge
/// exactly. Particles on an edge or corner where several present faces meet carry
/// one normal per face. Inward normals make a tank; outward normals an obstacle.
template <int D>
BoundaryParticles<D> sampleBoxSurface(const Vec<D>& lower, const Vec<D>& upper, double spacing,
                                      const BoxFaces<D>& faces, NormalSide side);

/// The density at height y under a free surface at `surface_height` in still water:
/// hydrostatic through the equation of state, rho0 above the surface or without gravity.
inline double hydrostaticDensity(const TaitEos& eos, double gravity, double surface_height, double y) {
  const double depth = std::max(0.0, surface_height - y);
  return gravity != 0.0 ? eos.density(eos.rho0() * gravity * depth) : eos.rho0();
}

/// Fluid particles filling [lower, upper] on a lattice of spacing dx, each a half
/// spacing inside the faces, mass rho0 dx^D. With `gravity` non-zero the density is
/// hydrostatic under the free surface at `surface_height` (y), so the block starts
/// near equilibrium; pass zero gravity for uniform rho0.
template <int D>
void fillBox(FluidParticles<D>& fluid, const Vec<D>& lower, const Vec<D>& upper, double dx, const TaitEos& eos,
             double gravity, double surface_height);

}  // namespace moorsph::fluid
