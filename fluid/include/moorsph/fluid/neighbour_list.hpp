#pragma once
// Compressed neighbour lists: the neighbours of particle i are
// index[begin[i] .. begin[i+1]).
#include <cstdint>
#include <vector>

namespace moorsph::fluid {

struct NeighbourList {
  std::vector<std::uint64_t> begin{0};
  std::vector<std::uint32_t> index;

  std::size_t owners() const { return begin.size() - 1; }
  std::size_t pairs() const { return index.size(); }
};

}  // namespace moorsph::fluid
