#pragma once
// Small vector types shared by the 2D and 3D instantiations of the fluid code.
#include <Eigen/Core>

namespace moorsph::fluid {

/// A point or vector in D dimensions (D = 2 or 3), SI units.
template <int D>
using Vec = Eigen::Matrix<double, D, 1>;

/// Index of the vertical axis: x along the tank, y up, z across (METHOD.md).
inline constexpr int kVertical = 1;

}  // namespace moorsph::fluid
