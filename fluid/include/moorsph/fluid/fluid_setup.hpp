#pragma once
// What a scene says about the fluid: resolution, properties, domain, the method and
// the list of effects to build (DESIGN.md section 5).
#include <string>
#include <vector>
#include <moorsph/fluid/domain.hpp>
#include <moorsph/fluid/method_parameters.hpp>

namespace moorsph::fluid {

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

  double h() const { return method.h_factor * dx; }
  bool has(const std::string& effect) const {
    for (const auto& e : effects) if (e == effect) return true;
    return false;
  }
  static Vec<D> gravityDown() {
    Vec<D> g = Vec<D>::Zero();
    g[1] = -9.81;
    return g;
  }
};

}  // namespace moorsph::fluid
