#pragma once
// Where a scene's static walls stand (Walls::staticExtent): what the outflow effect and
// the run guard use to tell water that went over a wall from water that went through it.
#include <limits>
#include <moorsph/fluid/vec.hpp>

namespace moorsph::fluid {

/// Where the static walls are: the bounding box of their particles and, per side of it
/// across the horizontal directions, the top of the wall standing there.
template <int D>
struct WallExtent {
  Vec<D> lower = Vec<D>::Constant(std::numeric_limits<double>::infinity());
  Vec<D> upper = Vec<D>::Constant(-std::numeric_limits<double>::infinity());
  /// top of the particles on the plane r[a] = lower[a] (resp. upper[a]); entry 1 unused
  Vec<D> lower_side_top = Vec<D>::Constant(-std::numeric_limits<double>::infinity());
  Vec<D> upper_side_top = Vec<D>::Constant(-std::numeric_limits<double>::infinity());
  double top() const { return upper[1]; }
  bool empty() const { return !(upper[1] >= lower[1]); }
};

}  // namespace moorsph::fluid
