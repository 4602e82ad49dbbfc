#include <moorsph/fluid/shape_sampling.hpp>

#include <cmath>
#include <stdexcept>

namespace moorsph::fluid {
namespace {
constexpr double kPi = 3.14159265358979323846;

void checkSize(double radius, double spacing) {
  if (!(radius > 0.0) || !(spacing > 0.0)) throw std::invalid_argument("shape radius and spacing must be positive");
}
}  // namespace

template <>
BoundaryParticles<2> sampleSphere<2>(const Vec<2>& centre, double radius, double spacing) {
  checkSize(radius, spacing);
  BoundaryParticles<2> out;
  const int n = std::max(8, static_cast<int>(std::ceil(2.0 * kPi * radius / spacing)));
  for (int k = 0; k < n; ++k) {
    const double a = 2.0 * kPi * k / n;
    const Vec<2> normal(std::cos(a), std::sin(a));
    out.add(centre + radius * normal, {normal}, 0);
  }
  return out;
}

// Fibonacci lattice: point k at height z_k = 1 - (2k+1)/N and azimuth k times the
// golden angle; each point represents an equal area 4 pi R^2 / N.
template <>
BoundaryParticles<3> sampleSphere<3>(const Vec<3>& centre, double radius, double spacing) {
  checkSize(radius, spacing);
  BoundaryParticles<3> out;
  const int n = std::max(12, static_cast<int>(std::ceil(4.0 * kPi * radius * radius / (spacing * spacing))));
  const double golden = kPi * (3.0 - std::sqrt(5.0));
  for (int k = 0; k < n; ++k) {
    const double z = 1.0 - (2.0 * k + 1.0) / n;
    const double rho = std::sqrt(std::max(0.0, 1.0 - z * z));
    const double a = golden * k;
    // y is up in moorsph: map the lattice's pole axis to y.
    const Vec<3> normal(rho * std::cos(a), z, rho * std::sin(a));
    out.add(centre + radius * normal, {normal}, 0);
  }
  return out;
}

// Latitude rings about the vertical (y) axis: a point at each pole, rings at polar
// angles j pi / n, each with a multiple of 4 points at half-step azimuths. Every ring
// is mirror-symmetric in x and in z about the centre, so a pressure field that
// depends on height alone (hydrostatics, a flat free surface) sums to exactly zero
// sideways force and zero torque about the centre; the Fibonacci lattice leaves a
// residual of order 1e-3 of the buoyancy, enough to push a softly moored buoy
// sideways by centimetres.
BoundaryParticles<3> sampleSphereRings(const Vec<3>& centre, double radius, double spacing) {
  checkSize(radius, spacing);
  BoundaryParticles<3> out;
  const int rings = std::max(2, static_cast<int>(std::ceil(kPi * radius / spacing)));
  out.add(centre + Vec<3>(0.0, radius, 0.0), {Vec<3>(0.0, 1.0, 0.0)}, 0);
  for (int j = 1; j < rings; ++j) {
    const double polar = kPi * j / rings, ring_radius = std::sin(polar);
    const int m = 4 * std::max(1, static_cast<int>(std::ceil(2.0 * kPi * radius * ring_radius / (4.0 * spacing))));
    for (int k = 0; k < m; ++k) {
      const double a = 2.0 * kPi * (k + 0.5) / m;
      const Vec<3> normal(ring_radius * std::cos(a), std::cos(polar), ring_radius * std::sin(a));
      out.add(centre + radius * normal, {normal}, 0);
    }
  }
  out.add(centre + Vec<3>(0.0, -radius, 0.0), {Vec<3>(0.0, -1.0, 0.0)}, 0);
  return out;
}

BoundaryParticles<3> sampleCylinder(const Vec<3>& axis_point, double radius, double z0, double z1, double spacing) {
  checkSize(radius, spacing);
  if (!(z1 > z0)) throw std::invalid_argument("cylinder length must be positive");
  BoundaryParticles<3> out;
  const int around = std::max(8, static_cast<int>(std::ceil(2.0 * kPi * radius / spacing)));
  const int along = std::max(1, static_cast<int>(std::ceil((z1 - z0) / spacing)));
  for (int j = 0; j <= along; ++j) {
    const double z = z0 + (z1 - z0) * j / along;
    for (int k = 0; k < around; ++k) {
      const double a = 2.0 * kPi * k / around;
      const Vec<3> radial(std::cos(a), std::sin(a), 0.0);
      std::vector<Vec<3>> normals{radial};
      if (j == 0) normals.push_back(Vec<3>(0, 0, -1));  // rim: mantle and end normals
      if (j == along) normals.push_back(Vec<3>(0, 0, 1));
      out.add(Vec<3>(axis_point[0], axis_point[1], 0.0) + radius * radial + Vec<3>(0, 0, z), normals, 0);
    }
  }
  // End discs: rings inside the rim, spaced radially by about `spacing`.
  const int rings = static_cast<int>(std::ceil(radius / spacing));
  for (int end = 0; end < 2; ++end) {
    const double z = end == 0 ? z0 : z1;
    const Vec<3> normal(0, 0, end == 0 ? -1.0 : 1.0);
    out.add(Vec<3>(axis_point[0], axis_point[1], z), {normal}, 0);
    for (int ring = 1; ring < rings; ++ring) {
      const double r = radius * ring / rings;
      const int m = std::max(6, static_cast<int>(std::ceil(2.0 * kPi * r / spacing)));
      for (int k = 0; k < m; ++k) {
        const double a = 2.0 * kPi * k / m;
        out.add(Vec<3>(axis_point[0] + r * std::cos(a), axis_point[1] + r * std::sin(a), z), {normal}, 0);
      }
    }
  }
  return out;
}

}  // namespace moorsph::fluid
