#include <moorsph/fluid/neighbour_search.hpp>

#include <omp.h>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace moorsph::fluid {

template <int D>
NeighbourSearch<D>::NeighbourSearch(const Domain<D>& domain, double support, double skin)
    : domain_(domain), support_(support), skin_(skin) {
  grid_.configure(domain, support + skin);
}

template <int D>
bool NeighbourSearch<D>::needsRebuild(const FluidParticles<D>& fluid, const BoundaryParticles<D>* boundary,
                                      double max_step_travel) const {
  if (rebuild_count_ == 0 || fluid_at_build_.size() != fluid.size()) return true;
  double max2 = 0.0;
  const std::size_t n = fluid.size();
#pragma omp parallel for schedule(static) reduction(max : max2)
  for (std::size_t i = 0; i < n; ++i) {
    max2 = std::max(max2, domain_.minimumImage(fluid.r[i] - fluid_at_build_[i]).squaredNorm());
  }
  double max_boundary2 = 0.0;
  if (boundary) {
    if (boundary_at_build_.size() != boundary->size()) return true;
    const std::size_t nb = boundary->size();
#pragma omp parallel for schedule(static) reduction(max : max_boundary2)
    for (std::size_t k = 0; k < nb; ++k)
      max_boundary2 = std::max(max_boundary2, domain_.minimumImage(boundary->r[k] - boundary_at_build_[k]).squaredNorm());
  }
  // Two particles approach each other by at most the sum of their travels.
  const double travel = std::sqrt(max2) + std::max(std::sqrt(max2), std::sqrt(max_boundary2)) + 2.0 * max_step_travel;
  return travel >= skin_;
}

template <int D>
void NeighbourSearch<D>::countCells(const std::vector<Vec<D>>& r) {
  const std::size_t n = r.size();
  const int cells = grid_.cellCount();
  cell_of_.resize(n);
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) cell_of_[i] = grid_.cellOf(r[i]);
  cell_start_.assign(cells + 1, 0);
  for (std::size_t i = 0; i < n; ++i) ++cell_start_[cell_of_[i] + 1];
  for (int c = 0; c < cells; ++c) cell_start_[c + 1] += cell_start_[c];
}

template <int D>
void NeighbourSearch<D>::sortFluidByCell(FluidParticles<D>& fluid) {
  const std::size_t n = fluid.size();
  countCells(fluid.r);
  // Counting sort: stable, O(n + cells).
  counts_.assign(cell_start_.begin(), cell_start_.end() - 1);
  order_.resize(n);
  for (std::size_t i = 0; i < n; ++i) order_[counts_[cell_of_[i]]++] = static_cast<std::uint32_t>(i);
  fluid.permute(order_, scratch_);
}

template <int D>
void NeighbourSearch<D>::indexBoundary(const std::vector<Vec<D>>& rb) {
  const std::size_t n = rb.size();
  const int cells = grid_.cellCount();
  boundary_cell_start_.assign(cells + 1, 0);
  cell_of_.resize(std::max(cell_of_.size(), n));
  for (std::size_t k = 0; k < n; ++k) {
    cell_of_[k] = grid_.cellOf(rb[k]);
    ++boundary_cell_start_[cell_of_[k] + 1];
  }
  for (int c = 0; c < cells; ++c) boundary_cell_start_[c + 1] += boundary_cell_start_[c];
  counts_.assign(boundary_cell_start_.begin(), boundary_cell_start_.end() - 1);
  boundary_sorted_.resize(n);
  for (std::size_t k = 0; k < n; ++k) boundary_sorted_[counts_[cell_of_[k]]++] = static_cast<std::uint32_t>(k);
}

// One pass: each thread fills its own buffer for a contiguous block of owners (the
// particles are sorted by cell, so blocks are balanced), then the blocks are copied
// into the compact list at their offsets. The buffers persist between rebuilds, so a
// rebuild allocates only when a list outgrows its capacity. `candidates(owner, visit)`
// calls visit(j) for every j within the list radius.
template <int D>
template <class Candidates>
void NeighbourSearch<D>::buildList(std::size_t owners, NeighbourList& list, Candidates&& candidates) {
  list.begin.resize(owners + 1);
  list.begin[0] = 0;
  thread_buffers_.resize(static_cast<std::size_t>(omp_get_max_threads()));
  thread_offsets_.resize(thread_buffers_.size() + 1);
#pragma omp parallel
  {
    const std::size_t t = static_cast<std::size_t>(omp_get_thread_num());
    const std::size_t nt = static_cast<std::size_t>(omp_get_num_threads());
    const std::size_t first = owners * t / nt, last = owners * (t + 1) / nt;
    std::vector<std::uint32_t>& local = thread_buffers_[t];
    local.clear();
    for (std::size_t i = first; i < last; ++i) {
      candidates(i, [&](std::uint32_t j) { local.push_back(j); });
      list.begin[i + 1] = local.size();  // cumulative within the block for now
    }
#pragma omp barrier
#pragma omp single
    {
      thread_offsets_[0] = 0;
      for (std::size_t k = 0; k < nt; ++k) thread_offsets_[k + 1] = thread_offsets_[k] + thread_buffers_[k].size();
      list.index.resize(thread_offsets_[nt]);
    }
    const std::uint64_t offset = thread_offsets_[t];
    std::copy(local.begin(), local.end(), list.index.begin() + static_cast<std::ptrdiff_t>(offset));
    for (std::size_t i = first; i < last; ++i) list.begin[i + 1] += offset;
  }
}

namespace {

/// Calls visit(j) for each j in [first, last) with within(j), in order. Most candidates
/// of a cell block are out of reach (about 15% of a 3x3x3 block lies within the list
/// radius in 3D), so a branch per candidate mispredicts on every hit: each candidate
/// is written to a chunk and the count advanced by the test's outcome, no branch.
template <class Within, class Visit>
void visitWithin(std::uint32_t first, std::uint32_t last, Within&& within, Visit&& visit) {
  constexpr std::uint32_t kChunk = 64;
  std::uint32_t hits[kChunk];
  for (std::uint32_t start = first; start < last; start += kChunk) {
    const std::uint32_t end = std::min(last, start + kChunk);
    std::uint32_t count = 0;
    for (std::uint32_t j = start; j < end; ++j) {
      hits[count] = j;
      count += within(j) ? 1u : 0u;
    }
    for (std::uint32_t q = 0; q < count; ++q) visit(hits[q]);
  }
}

}  // namespace

template <int D>
void NeighbourSearch<D>::rebuild(FluidParticles<D>& fluid, const BoundaryParticles<D>* boundary,
                                 const std::vector<char>& tracked) {
  sortFluidByCell(fluid);
  buildLists(fluid.r, boundary ? &boundary->r : nullptr, tracked);
}

template <int D>
void NeighbourSearch<D>::restore(const FluidParticles<D>& fluid, const std::vector<Vec<D>>& fluid_at_build,
                                 const BoundaryParticles<D>* boundary, const std::vector<Vec<D>>& boundary_at_build,
                                 const std::vector<char>& tracked) {
  if (fluid_at_build.size() != fluid.size())
    throw std::invalid_argument("neighbour lists: " + std::to_string(fluid_at_build.size()) + " build positions for " +
                                std::to_string(fluid.size()) + " fluid particles");
  if (boundary && boundary_at_build.size() != boundary->size())
    throw std::invalid_argument("neighbour lists: " + std::to_string(boundary_at_build.size()) +
                                " boundary build positions for " + std::to_string(boundary->size()) +
                                " boundary particles");
  // The particles must be in the cell order of their build positions, as the build
  // that produced those positions left them: then the lists come out the same.
  countCells(fluid_at_build);
  for (std::size_t i = 1; i < fluid_at_build.size(); ++i)
    if (cell_of_[i] < cell_of_[i - 1])
      throw std::invalid_argument("neighbour lists: the particles are not in the cell order of their build positions");
  buildLists(fluid_at_build, boundary ? &boundary_at_build : nullptr, tracked);
}

template <int D>
void NeighbourSearch<D>::buildLists(const std::vector<Vec<D>>& r, const std::vector<Vec<D>>* boundary_r,
                                    const std::vector<char>& tracked) {
  const double radius2 = listRadius() * listRadius();
  const auto& grid = grid_;
  const MinimumImage<D> image(domain_);

  // Fluid-fluid: every j != i of the fluid within the list radius.
  buildList(r.size(), fluid_fluid_, [&](std::size_t i, auto&& visit) {
    const Vec<D> ri = r[i];
    const int cell = grid.cellOf(ri);
    auto within = [&](std::uint32_t j) { return (image(ri - r[j]).squaredNorm() < radius2) & (j != i); };
    for (auto c = grid.neighbourCellsBegin(cell); c != grid.neighbourCellsEnd(cell); ++c)
      visitWithin(cell_start_[*c], cell_start_[*c + 1], within, visit);
  });

  if (boundary_r) {
    indexBoundary(*boundary_r);
    const auto& rb = *boundary_r;
    buildList(r.size(), fluid_boundary_, [&](std::size_t i, auto&& visit) {
      const Vec<D> ri = r[i];
      const int cell = grid.cellOf(ri);
      auto within = [&](std::uint32_t s) { return image(ri - rb[boundary_sorted_[s]]).squaredNorm() < radius2; };
      auto visitSorted = [&](std::uint32_t s) { visit(boundary_sorted_[s]); };
      for (auto c = grid.neighbourCellsBegin(cell); c != grid.neighbourCellsEnd(cell); ++c)
        visitWithin(boundary_cell_start_[*c], boundary_cell_start_[*c + 1], within, visitSorted);
    });
    tracked_index_.clear();
    for (std::size_t k = 0; k < tracked.size(); ++k)
      if (tracked[k]) tracked_index_.push_back(static_cast<std::uint32_t>(k));
    buildList(tracked_index_.size(), boundary_fluid_, [&](std::size_t t, auto&& visit) {
      const Vec<D> x = rb[tracked_index_[t]];
      const int cell = grid.cellOf(x);
      auto within = [&](std::uint32_t j) { return image(x - r[j]).squaredNorm() < radius2; };
      for (auto c = grid.neighbourCellsBegin(cell); c != grid.neighbourCellsEnd(cell); ++c)
        visitWithin(cell_start_[*c], cell_start_[*c + 1], within, visit);
    });
    boundary_at_build_ = rb;
  }
  fluid_at_build_ = r;
  ++rebuild_count_;
}

template class NeighbourSearch<2>;
template class NeighbourSearch<3>;

}  // namespace moorsph::fluid
