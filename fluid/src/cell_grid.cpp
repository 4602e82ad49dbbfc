#include <moorsph/fluid/cell_grid.hpp>

#include <cmath>
#include <stdexcept>
#include <string>

namespace moorsph::fluid {

template <int D>
void CellGrid<D>::configure(const Domain<D>& domain, double min_cell_size) {
  lower_ = domain.lower;
  periodic_ = domain.periodic;
  cell_count_ = 1;
  for (int k = 0; k < D; ++k) {
    const double L = domain.upper[k] - domain.lower[k];
    if (!(L > 0.0)) throw std::invalid_argument("domain has non-positive length along axis " + std::to_string(k));
    if (periodic_[k]) {
      // Whole number of cells no narrower than min_cell_size, so wrapping is exact.
      dims_[k] = static_cast<int>(std::floor(L / min_cell_size));
      if (dims_[k] < 3)
        throw std::invalid_argument("periodic axis " + std::to_string(k) + " is " + std::to_string(L) +
                                    " m long: it must hold at least 3 cells of " + std::to_string(min_cell_size) +
                                    " m (3 x interaction radius)");
    } else {
      dims_[k] = std::max(1, static_cast<int>(std::ceil(L / min_cell_size)));
    }
    cell_size_[k] = periodic_[k] ? L / dims_[k] : min_cell_size;
    inv_cell_size_[k] = 1.0 / cell_size_[k];
    cell_count_ *= dims_[k];
  }

  // Precompute each cell's block of neighbour cells (3^D at most, fewer at bounded edges).
  neighbour_begin_.assign(1, 0);
  neighbour_cells_.clear();
  for (int cell = 0; cell < cell_count_; ++cell) {
    std::array<int, D> c{};
    int rest = cell;
    for (int k = 0; k < D; ++k) {
      c[k] = rest % dims_[k];
      rest /= dims_[k];
    }
    const int block = (D == 2) ? 9 : 27;
    for (int b = 0; b < block; ++b) {
      int code = b;
      int index = 0;
      int stride = 1;
      bool inside = true;
      for (int k = 0; k < D; ++k) {
        int ck = c[k] + (code % 3) - 1;
        code /= 3;
        if (ck < 0 || ck >= dims_[k]) {
          if (!periodic_[k]) { inside = false; break; }
          ck = (ck + dims_[k]) % dims_[k];
        }
        index += ck * stride;
        stride *= dims_[k];
      }
      if (inside) neighbour_cells_.push_back(static_cast<std::uint32_t>(index));
    }
    neighbour_begin_.push_back(static_cast<std::uint32_t>(neighbour_cells_.size()));
  }
}

template class CellGrid<2>;
template class CellGrid<3>;

}  // namespace moorsph::fluid
