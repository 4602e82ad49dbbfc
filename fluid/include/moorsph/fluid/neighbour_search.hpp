#pragma once
// Neighbour search with Verlet lists over a cell grid.
//
// Lists are built with radius 2h + skin from positions sorted by cell, and reused
// while no two particles can have closed the skin: the owner checks
// `needsRebuild()` at the start of every step (maximum displacement since the build,
// plus the largest distance a particle can travel within the coming step). Every
// rebuild also re-sorts the fluid particles by cell (counting sort), which keeps the
// pair loops cache friendly. Pair loops must still test r < 2h themselves.
//
// Three lists: fluid-fluid, fluid-boundary (for the wall force on fluid) and, for
// boundary particles whose reactions are tracked (bodies, sensors), boundary-fluid.
#include <cstdint>
#include <vector>
#include <moorsph/fluid/boundary_particles.hpp>
#include <moorsph/fluid/cell_grid.hpp>
#include <moorsph/fluid/fluid_particles.hpp>
#include <moorsph/fluid/neighbour_list.hpp>

namespace moorsph::fluid {

template <int D>
class NeighbourSearch {
 public:
  NeighbourSearch(const Domain<D>& domain, double support, double skin);

  double listRadius() const { return support_ + skin_; }
  double skin() const { return skin_; }
  const CellGrid<D>& grid() const { return grid_; }

  /// True if the lists may miss a pair within `support` after particles move at
  /// most `max_step_travel` more (fluid and moving boundaries together).
  bool needsRebuild(const FluidParticles<D>& fluid, const BoundaryParticles<D>* boundary,
                    double max_step_travel) const;

  /// Re-sort the fluid by cell (permuting its state arrays) and rebuild every list.
  /// `boundary` may be null (no walls); `tracked` flags boundary particles whose
  /// reactions are needed (may be empty: none).
  void rebuild(FluidParticles<D>& fluid, const BoundaryParticles<D>* boundary,
               const std::vector<char>& tracked);

  /// Rebuild the lists a run had, from the positions its last rebuild saw (fluidAtBuild()
  /// and boundaryAtBuild() of that run, saved in a checkpoint), without re-sorting: the
  /// lists, and with them every later rebuild decision, come out the same as the run's.
  /// So a run needs no extra rebuild before a checkpoint to restart bit-identically.
  /// Throws std::invalid_argument if the sizes differ or the fluid is not in the cell
  /// order of `fluid_at_build` (positions from another run).
  void restore(const FluidParticles<D>& fluid, const std::vector<Vec<D>>& fluid_at_build,
               const BoundaryParticles<D>* boundary, const std::vector<Vec<D>>& boundary_at_build,
               const std::vector<char>& tracked);
  /// The positions the lists were last built from (empty before the first build).
  const std::vector<Vec<D>>& fluidAtBuild() const { return fluid_at_build_; }
  const std::vector<Vec<D>>& boundaryAtBuild() const { return boundary_at_build_; }

  const NeighbourList& fluidFluid() const { return fluid_fluid_; }
  const NeighbourList& fluidBoundary() const { return fluid_boundary_; }
  const NeighbourList& boundaryFluid() const { return boundary_fluid_; }
  /// Indices of the tracked boundary particles, in the order of boundaryFluid().
  const std::vector<std::uint32_t>& trackedBoundary() const { return tracked_index_; }

  /// Fluid particles sorted by cell: cell c holds indices [cellStart(c), cellStart(c+1)).
  std::uint32_t cellStart(int c) const { return cell_start_[c]; }
  std::size_t rebuildCount() const { return rebuild_count_; }

 private:
  void countCells(const std::vector<Vec<D>>& r);  // cell_of_ and cell_start_ for r
  void sortFluidByCell(FluidParticles<D>& fluid);
  void indexBoundary(const std::vector<Vec<D>>& rb);
  void buildLists(const std::vector<Vec<D>>& r, const std::vector<Vec<D>>* boundary_r,
                  const std::vector<char>& tracked);
  template <class Candidates>
  void buildList(std::size_t owners, NeighbourList& list, Candidates&& candidates);

  Domain<D> domain_;
  double support_;
  double skin_;
  CellGrid<D> grid_;
  std::vector<std::uint32_t> cell_start_;      // fluid, size cells+1
  std::vector<std::uint32_t> boundary_cell_start_;
  std::vector<std::uint32_t> boundary_sorted_;  // boundary indices sorted by cell
  std::vector<int> cell_of_;                    // scratch
  std::vector<std::uint32_t> order_;            // scratch
  std::vector<std::uint32_t> counts_;           // scratch
  FluidParticles<D> scratch_;
  std::vector<Vec<D>> fluid_at_build_;
  std::vector<Vec<D>> boundary_at_build_;
  NeighbourList fluid_fluid_, fluid_boundary_, boundary_fluid_;
  std::vector<std::uint32_t> tracked_index_;
  std::vector<std::vector<std::uint32_t>> thread_buffers_;  // per-thread list blocks (buildList)
  std::vector<std::uint64_t> thread_offsets_;
  std::size_t rebuild_count_ = 0;
};

}  // namespace moorsph::fluid
