#pragma once
// The fluid particles within the kernel's reach (2h) of a point, for sensors that
// interpolate the fluid there (pressure_probe.hpp, velocity_probe.hpp).
//
// The block of cells around the point holds every particle within 2h of it (cells are
// 2h + skin wide; particles moved less than skin/2 since the last re-sort). Before the
// first step nothing is sorted by cell yet: every particle is scanned.
#include <cmath>
#include <cstdint>
#include <moorsph/fluid/fluid_simulation.hpp>

namespace moorsph::fluid {

/// Calls visit(j, w) for every fluid particle j within 2h of `point`, with its kernel
/// weight w = W(|point - r_j|, h) m_j / rho_j [-] (the Shepard sum of the w is the
/// particle density xi of METHOD.md section 3).
template <int D, class Visit>
void forEachFluidNear(const FluidSimulation<D>& sim, const Vec<D>& point, Visit&& visit) {
  const NeighbourSearch<D>& search = sim.neighbours();
  const FluidParticles<D>& f = sim.fluid();
  const Domain<D>& domain = sim.setup().domain;
  const WendlandKernel<D>& kernel = sim.kernel();
  const double support2 = kernel.supportSquared();
  const auto one = [&](std::size_t j) {
    const double r2 = domain.minimumImage(f.r[j] - point).squaredNorm();
    if (r2 < support2) visit(j, kernel.value(std::sqrt(r2)) * f.m[j] / f.rho[j]);
  };
  if (search.rebuildCount() == 0) {
    for (std::size_t j = 0; j < f.size(); ++j) one(j);
    return;
  }
  const CellGrid<D>& grid = search.grid();
  const int cell = grid.cellOf(domain.wrap(point));
  for (const std::uint32_t* c = grid.neighbourCellsBegin(cell); c != grid.neighbourCellsEnd(cell); ++c)
    for (std::uint32_t j = search.cellStart(static_cast<int>(*c)); j < search.cellStart(static_cast<int>(*c) + 1); ++j)
      one(j);
}

}  // namespace moorsph::fluid
