#pragma once
// A uniform grid of cells at least as wide as the interaction radius (METHOD.md
// section 1): a particle's neighbours all lie in the 3x3 (2D) or 3x3x3 (3D) block of
// cells around its own. Periodic directions wrap (they need at least 3 cells so a
// cell is never counted twice); bounded directions clamp, so a particle just outside
// the box is still found (the escape check reports it separately).
#include <array>
#include <cstdint>
#include <vector>
#include <moorsph/fluid/domain.hpp>

namespace moorsph::fluid {

template <int D>
class CellGrid {
 public:
  /// Throws std::invalid_argument if a periodic direction holds fewer than 3 cells.
  void configure(const Domain<D>& domain, double min_cell_size);

  int cellCount() const { return cell_count_; }
  const std::array<int, D>& dims() const { return dims_; }
  const Vec<D>& cellSize() const { return cell_size_; }

  /// Linear index of the cell holding r.
  int cellOf(const Vec<D>& r) const {
    int index = 0;
    for (int k = D - 1; k >= 0; --k) {
      int c = static_cast<int>((r[k] - lower_[k]) * inv_cell_size_[k]);
      if (c < 0) c = periodic_[k] ? c % dims_[k] + dims_[k] : 0;
      if (c >= dims_[k]) c = periodic_[k] ? c % dims_[k] : dims_[k] - 1;
      index = index * dims_[k] + c;
    }
    return index;
  }

  /// The cells of the block around `cell` (itself included), each once.
  const std::uint32_t* neighbourCellsBegin(int cell) const { return &neighbour_cells_[neighbour_begin_[cell]]; }
  const std::uint32_t* neighbourCellsEnd(int cell) const { return &neighbour_cells_[neighbour_begin_[cell + 1]]; }

 private:
  Vec<D> lower_ = Vec<D>::Zero();
  Vec<D> cell_size_ = Vec<D>::Zero();
  Vec<D> inv_cell_size_ = Vec<D>::Zero();
  std::array<int, D> dims_{};
  std::array<bool, D> periodic_{};
  int cell_count_ = 0;
  std::vector<std::uint32_t> neighbour_begin_;
  std::vector<std::uint32_t> neighbour_cells_;
};

}  // namespace moorsph::fluid
