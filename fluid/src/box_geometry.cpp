#include <moorsph/fluid/box_geometry.hpp>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace moorsph::fluid {

template <int D>
BoundaryParticles<D> sampleBoxSurface(const Vec<D>& lower, const Vec<D>& upper, double spacing,
                                      const BoxFaces<D>& faces, NormalSide side) {
  if (!(spacing > 0.0)) throw std::invalid_argument("boundary spacing must be positive");
  std::array<int, D> n{};
  Vec<D> step;
  long total = 1;
  for (int k = 0; k < D; ++k) {
    const double L = upper[k] - lower[k];
    if (!(L > 0.0)) throw std::invalid_argument("box has non-positive size");
    n[k] = std::max(1, static_cast<int>(std::ceil(L / spacing - 1e-9)));
    step[k] = L / n[k];
    total *= (n[k] + 1);
  }
  const double sign = (side == NormalSide::Inward) ? 1.0 : -1.0;
  BoundaryParticles<D> out;
  std::vector<Vec<D>> normals;
  for (long code = 0; code < total; ++code) {
    std::array<int, D> idx{};
    long rest = code;
    for (int k = 0; k < D; ++k) {
      idx[k] = static_cast<int>(rest % (n[k] + 1));
      rest /= (n[k] + 1);
    }
    normals.clear();
    bool on_missing_face_only = false;
    for (int k = 0; k < D; ++k) {
      for (int s = 0; s < 2; ++s) {
        const bool on_face = (s == 0) ? idx[k] == 0 : idx[k] == n[k];
        if (!on_face) continue;
        if (faces[2 * k + s]) {
          Vec<D> nrm = Vec<D>::Zero();
          nrm[k] = sign * (s == 0 ? 1.0 : -1.0);
          normals.push_back(nrm);
        } else {
          on_missing_face_only = true;
        }
      }
    }
    (void)on_missing_face_only;
    if (normals.empty()) continue;  // interior lattice point, or only on absent faces
    Vec<D> r;
    for (int k = 0; k < D; ++k) r[k] = (idx[k] == n[k]) ? upper[k] : lower[k] + idx[k] * step[k];
    out.add(r, normals, 0);
  }
  return out;
}

template <int D>
void fillBox(FluidParticles<D>& fluid, const Vec<D>& lower, const Vec<D>& upper, double dx, const TaitEos& eos,
             double gravity, double surface_height) {
  std::array<int, D> n{};
  long total = 1;
  for (int k = 0; k < D; ++k) {
    n[k] = static_cast<int>(std::floor((upper[k] - lower[k]) / dx + 1e-9));
    if (n[k] < 1) throw std::invalid_argument("fluid block thinner than one particle spacing");
    total *= n[k];
  }
  const double mass = eos.rho0() * std::pow(dx, D);
  for (long code = 0; code < total; ++code) {
    Vec<D> r;
    long rest = code;
    for (int k = 0; k < D; ++k) {
      r[k] = lower[k] + (static_cast<double>(rest % n[k]) + 0.5) * dx;
      rest /= n[k];
    }
    fluid.add(r, Vec<D>::Zero(), hydrostaticDensity(eos, gravity, surface_height, r[1]), mass);
  }
}

template BoundaryParticles<2> sampleBoxSurface<2>(const Vec<2>&, const Vec<2>&, double, const BoxFaces<2>&, NormalSide);
template BoundaryParticles<3> sampleBoxSurface<3>(const Vec<3>&, const Vec<3>&, double, const BoxFaces<3>&, NormalSide);
template void fillBox<2>(FluidParticles<2>&, const Vec<2>&, const Vec<2>&, double, const TaitEos&, double, double);
template void fillBox<3>(FluidParticles<3>&, const Vec<3>&, const Vec<3>&, double, const TaitEos&, double, double);

}  // namespace moorsph::fluid
