#pragma once
// Fluid particles in structure-of-arrays storage: one contiguous array per field,
// so the pair loops stream through memory. Particles are periodically re-sorted by
// cell (see NeighbourSearch), which keeps neighbours close in memory; `id` keeps
// each particle's original identity for output.
#include <cstdint>
#include <vector>
#include <moorsph/fluid/vec.hpp>

namespace moorsph::fluid {

template <int D>
struct FluidParticles {
  // State (SI): position [m], velocity [m/s], density [kg/m^3], mass [kg].
  std::vector<Vec<D>> r, v;
  std::vector<double> rho, m;
  std::vector<std::int64_t> id;

  // Derived each evaluation: pressure [Pa].
  std::vector<double> p;

  // Rates: dv/dt [m/s^2], dr/dt [m/s] (XSPH-corrected velocity), drho/dt [kg/m^3/s].
  std::vector<Vec<D>> dvdt, drdt;
  std::vector<double> drhodt;

  // Start-of-step copies used by the predictor-corrector.
  std::vector<Vec<D>> r_start, v_start;
  std::vector<double> rho_start;

  std::size_t size() const { return r.size(); }

  void add(const Vec<D>& position, const Vec<D>& velocity, double density, double mass) {
    id.push_back(static_cast<std::int64_t>(r.size()));
    r.push_back(position);
    v.push_back(velocity);
    rho.push_back(density);
    m.push_back(mass);
  }

  /// Size every derived/rate/scratch array to the particle count. Called once
  /// before stepping so that no step allocates.
  void allocateWorkArrays() {
    const std::size_t n = size();
    p.assign(n, 0.0);
    dvdt.assign(n, Vec<D>::Zero());
    drdt.assign(n, Vec<D>::Zero());
    drhodt.assign(n, 0.0);
    r_start.assign(n, Vec<D>::Zero());
    v_start.assign(n, Vec<D>::Zero());
    rho_start.assign(n, 0.0);
  }

  /// Reorder the state arrays: new index k holds old particle order[k]. The work
  /// arrays are not carried over (they are recomputed after every re-sort).
  void permute(const std::vector<std::uint32_t>& order, FluidParticles& scratch) {
    const std::size_t n = size();
    scratch.r.resize(n);
    scratch.v.resize(n);
    scratch.rho.resize(n);
    scratch.m.resize(n);
    scratch.id.resize(n);
#pragma omp parallel for schedule(static)
    for (std::size_t k = 0; k < n; ++k) {
      const std::uint32_t o = order[k];
      scratch.r[k] = r[o];
      scratch.v[k] = v[o];
      scratch.rho[k] = rho[o];
      scratch.m[k] = m[o];
      scratch.id[k] = id[o];
    }
    r.swap(scratch.r);
    v.swap(scratch.v);
    rho.swap(scratch.rho);
    m.swap(scratch.m);
    id.swap(scratch.id);
  }
};

}  // namespace moorsph::fluid
