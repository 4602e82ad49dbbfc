#pragma once
// What a scene says about the fluid: resolution, properties, domain, the method and
// the list of effects to build (DESIGN.md section 5).
#include <string>
#include <vector>
#include <moorsph/fluid/domain.hpp>
#include <moorsph/fluid/method_parameters.hpp>

namespace moorsph::fluid {

/// An axis-aligned plane of mirror images (the mirror_floor and mirror_walls effects,
/// MirrorTerm in pair_terms.hpp): the water lies on the side `inside` of it (+1: at
/// coordinates above `position` along `axis`, -1: below).
struct MirrorPlane {
  int axis = 1;
  double position = 0.0;
  int inside = 1;

  /// True where coordinate x (along `axis`) lies on the dry side of the plane.
  bool outside(double x) const { return inside * (x - position) < 0.0; }
  /// The mirror image of coordinate x across the plane.
  double mirrored(double x) const { return 2.0 * position - x; }
};

template <int D>
struct FluidSetup {
  double dx = 0.01;            ///< mean particle spacing [m]
  double rho0 = 1000.0;        ///< reference density [kg/m^3]
  double mu = 1.0e-3;          ///< dynamic viscosity [Pa s]
  double sound_speed = 20.0;   ///< c_s [m/s], >= 10 x the largest expected flow speed
  Vec<D> gravity = gravityDown();  ///< [m/s^2]
  Domain<D> domain;
  MethodParameters method = MethodParameters::reference();
  std::vector<std::string> effects{"pressure", "gravity", "walls"};
  double mirror_floor_height = 0.0;  ///< the floor plane y of the "mirror_floor" effect [m]
  /// The "mirror_walls" effect's planes: a tank's side faces (normal to x, and z in 3D)
  /// as mirror images instead of boundary particles, set by the tank builder.
  std::vector<MirrorPlane> mirror_walls;

  double h() const { return method.h_factor * dx; }
  bool has(const std::string& effect) const {
    for (const auto& e : effects) if (e == effect) return true;
    return false;
  }
  /// Every mirror plane the scene's effects name: the floor's and the side walls'.
  std::vector<MirrorPlane> mirrorPlanes() const {
    std::vector<MirrorPlane> planes;
    if (has("mirror_floor")) planes.push_back(MirrorPlane{1, mirror_floor_height, +1});
    if (has("mirror_walls")) planes.insert(planes.end(), mirror_walls.begin(), mirror_walls.end());
    return planes;
  }
  static Vec<D> gravityDown() {
    Vec<D> g = Vec<D>::Zero();
    g[1] = -9.81;
    return g;
  }
};

}  // namespace moorsph::fluid
