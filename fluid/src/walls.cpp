#include <moorsph/fluid/walls.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>

namespace moorsph::fluid {
namespace {

/// The wall law's length: its own factor of dx if the method sets one, else the kernel's h.
template <int D>
double wallLength(const FluidSetup<D>& s) {
  const double h_w = s.method.boundary_h_factor > 0.0 ? s.method.boundary_h_factor * s.dx : s.h();
  // The fluid-boundary lists reach 2h: a longer wall law would miss pairs.
  if (h_w > s.h() * (1.0 + 1e-12)) throw std::invalid_argument("boundary_h_factor must not exceed h_factor");
  return h_w;
}

/// A D-vector in 3D (zero z in 2D), for moments.
template <int D>
Eigen::Vector3d to3(const Vec<D>& v) {
  Eigen::Vector3d out = Eigen::Vector3d::Zero();
  out.template head<D>() = v;
  return out;
}

}  // namespace

template <int D>
Walls<D>::Walls(BoundaryGeometry<D> geometry, const FluidSetup<D>& setup)
    : geometry_(std::move(geometry)),
      law_(setup.method.boundary_strength, setup.sound_speed, wallLength(setup), setup.dx, setup.method.boundary_offset,
           setup.method.boundary_force_form == BoundaryForceForm::Conservative) {
  if (geometry_.empty()) throw std::invalid_argument("effects: 'walls' is named but the scene has no boundary surfaces");
  tracked_.assign(geometry_.particles.size(), 0);
  for (std::size_t k = 0; k < tracked_.size(); ++k) {
    const auto s = geometry_.particles.surface[k];
    if (s >= geometry_.surfaces.size()) throw std::invalid_argument("boundary particle refers to an unknown surface");
    tracked_[k] = geometry_.surfaces[s].track_reaction ? 1 : 0;
    any_tracked_ = any_tracked_ || tracked_[k];
  }
  findSurfaceRanges();
  findFeatureParticles(4.0 * setup.h());
  const BoundaryParticles<D>& b = geometry_.particles;
  for (std::size_t s = 0; s < geometry_.surfaces.size(); ++s) {
    if (!geometry_.surfaces[s].movable) continue;
    MovableSurface m;
    m.surface = s;
    const Vec<D> origin = geometry_.surfaces[s].reference_point.template head<D>();
    m.motion.position = origin;
    for (std::size_t k = ranges_[s].first; k < ranges_[s].second; ++k) {
      m.reference_r.push_back(b.r[k] - origin);
      m.radius = std::max(m.radius, m.reference_r.back().norm());
      for (std::uint32_t a = b.normal_begin[k]; a < b.normal_begin[k + 1]; ++a) m.reference_normals.push_back(b.normals[a]);
    }
    movable_.push_back(std::move(m));
  }
}

// Surfaces are appended whole (BoundaryGeometry::addSurface), so each is one range.
template <int D>
void Walls<D>::findSurfaceRanges() {
  const auto& surface = geometry_.particles.surface;
  ranges_.assign(geometry_.surfaces.size(), {0, 0});
  std::vector<char> seen(geometry_.surfaces.size(), 0);
  for (std::size_t k = 0; k < surface.size();) {
    const std::size_t s = surface[k];
    if (seen[s]) throw std::invalid_argument("boundary particles of surface '" + geometry_.surfaces[s].name + "' are not contiguous");
    seen[s] = 1;
    std::size_t end = k;
    while (end < surface.size() && surface[end] == s) ++end;
    ranges_[s] = {k, end};
    k = end;
  }
}

// A particle needs the beyond-edge test only if a particle of its surface within `reach`
// (4h: both within 2h of one fluid particle) meets its face convexly or back to back; a
// tank (concave everywhere) and flat stretches need none. Hash grid of cells `reach` wide.
// Across a periodic seam nothing is found: such a particle keeps the plain law.
template <int D>
void Walls<D>::findFeatureParticles(double reach) {
  const BoundaryParticles<D>& b = geometry_.particles;
  near_feature_.assign(b.size(), 0);
  auto cellOf = [reach](const Vec<D>& r) {
    std::array<std::int64_t, 3> c{0, 0, 0};
    for (int d = 0; d < D; ++d) c[d] = static_cast<std::int64_t>(std::floor(r[d] / reach));
    return c;
  };
  std::map<std::array<std::int64_t, 3>, std::vector<std::uint32_t>> cells;
  for (std::size_t k = 0; k < b.size(); ++k) cells[cellOf(b.r[k])].push_back(static_cast<std::uint32_t>(k));
  const int span = D == 3 ? 1 : 0;
  for (std::size_t k = 0; k < b.size(); ++k) {
    if (b.normalCount(k) != 1) continue;
    const Vec<D>& n = b.normals[b.normal_begin[k]];
    const auto c = cellOf(b.r[k]);
    bool found = false;
    for (int dx = -1; dx <= 1 && !found; ++dx)
      for (int dy = -1; dy <= 1 && !found; ++dy)
        for (int dz = -span; dz <= span && !found; ++dz) {
          const auto it = cells.find({c[0] + dx, c[1] + dy, c[2] + dz});
          if (it == cells.end()) continue;
          for (const std::uint32_t k2 : it->second) {
            if (b.surface[k2] != b.surface[k] || (b.r[k2] - b.r[k]).norm() > reach) continue;
            for (std::uint32_t a = b.normal_begin[k2]; a < b.normal_begin[k2 + 1]; ++a) {
              const auto m = BoundaryForceLaw<D>::meeting(n, b.normals[a], b.r[k] - b.r[k2]);
              found = found || m == BoundaryForceLaw<D>::Meeting::Convex || m == BoundaryForceLaw<D>::Meeting::Thin;
            }
          }
        }
    near_feature_[k] = found;
  }
}

template <int D>
void Walls<D>::setSurfaceMotion(std::size_t surface, const RigidMotion<D>& motion) {
  for (MovableSurface& m : movable_) {
    if (m.surface != surface) continue;
    m.motion = motion;
    BoundaryParticles<D>& b = geometry_.particles;
    const auto [first, last] = ranges_[surface];
    std::size_t normal = 0;
    for (std::size_t k = first; k < last; ++k) {
      b.r[k] = motion.position + motion.rotation * m.reference_r[k - first];
      for (std::uint32_t a = b.normal_begin[k]; a < b.normal_begin[k + 1]; ++a)
        b.normals[a] = motion.rotation * m.reference_normals[normal++];
    }
    return;
  }
  throw std::invalid_argument("surface " + std::to_string(surface) + " is not movable");
}

template <int D>
const RigidMotion<D>& Walls<D>::surfaceMotion(std::size_t surface) const {
  for (const MovableSurface& m : movable_)
    if (m.surface == surface) return m.motion;
  throw std::invalid_argument("surface " + std::to_string(surface) + " is not movable");
}

template <int D>
double Walls<D>::maxMovingSpeed() const {
  double speed = 0.0;
  for (const MovableSurface& m : movable_)
    speed = std::max(speed, m.motion.velocity.norm() + m.motion.angular_velocity.norm() * m.radius);
  return speed;
}

template <int D>
WallExtent<D> Walls<D>::staticExtent(double tolerance) const {
  const BoundaryParticles<D>& b = geometry_.particles;
  auto isStatic = [&](std::size_t k) { return !geometry_.surfaces[b.surface[k]].movable; };
  WallExtent<D> e;
  for (std::size_t k = 0; k < b.size(); ++k) {
    if (!isStatic(k)) continue;
    e.lower = e.lower.cwiseMin(b.r[k]);
    e.upper = e.upper.cwiseMax(b.r[k]);
  }
  // The walls on each side: the particles on the box's face planes (a tank's walls lie
  // exactly on them; anything further inside than `tolerance` belongs to something else).
  for (std::size_t k = 0; k < b.size(); ++k) {
    if (!isStatic(k)) continue;
    for (int a = 0; a < D; ++a) {
      if (a == 1) continue;
      if (b.r[k][a] < e.lower[a] + tolerance) e.lower_side_top[a] = std::max(e.lower_side_top[a], b.r[k][1]);
      if (b.r[k][a] > e.upper[a] - tolerance) e.upper_side_top[a] = std::max(e.upper_side_top[a], b.r[k][1]);
    }
  }
  return e;
}

template <int D>
bool Walls<D>::beyondAnEdge(const FluidContext<D>& ctx, const MinimumImage<D>& image, std::size_t i, std::size_t k,
                            const Vec<D>& r_ik) const {
  const BoundaryParticles<D>& b = geometry_.particles;
  const NeighbourList& list = ctx.neighbours.fluidBoundary();
  for (std::uint64_t s = list.begin[i]; s < list.begin[i + 1]; ++s) {
    const std::uint32_t k2 = list.index[s];
    if (law_.beyondEdge(r_ik, k, image(ctx.fluid.r[i] - b.r[k2]), k2, b)) return true;
  }
  return false;
}

template <int D>
void Walls<D>::addRates(FluidContext<D>& ctx) {
  FluidParticles<D>& f = ctx.fluid;
  const NeighbourList& list = ctx.neighbours.fluidBoundary();
  const MinimumImage<D> image(ctx.setup.domain);
  const std::size_t n = f.size();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    Vec<D> acc = Vec<D>::Zero();
    for (std::uint64_t s = list.begin[i]; s < list.begin[i + 1]; ++s) {
      const std::uint32_t k = list.index[s];
      acc += push(ctx, image, i, k);
    }
    f.dvdt[i] += acc;
  }
  if (any_tracked_) addReactions(ctx);
}

// Reactions by a second gather over the tracked boundary particles: -m_i a_ik for
// each fluid neighbour, with the same law, so no atomics are needed.
template <int D>
void Walls<D>::addReactions(FluidContext<D>& ctx) {
  const FluidParticles<D>& f = ctx.fluid;
  const NeighbourList& list = ctx.neighbours.boundaryFluid();
  const auto& tracked = ctx.neighbours.trackedBoundary();
  const MinimumImage<D> image(ctx.setup.domain);
  BoundaryParticles<D>& b = geometry_.particles;
  const std::size_t n = tracked.size();
  const bool couples = law_.conservative();
  if (couples) couples_.resize(b.size(), Eigen::Vector3d::Zero());
#pragma omp parallel for schedule(static)
  for (std::size_t t = 0; t < n; ++t) {
    const std::uint32_t k = tracked[t];
    Vec<D> force = Vec<D>::Zero();
    Eigen::Vector3d couple = Eigen::Vector3d::Zero();
    for (std::uint64_t s = list.begin[t]; s < list.begin[t + 1]; ++s) {
      const std::uint32_t i = list.index[s];
      const Vec<D> reaction = -f.m[i] * push(ctx, image, i, k);
      force += reaction;
      if (couples) couple += to3(image(f.r[i] - b.r[k])).cross(to3(reaction));
    }
    b.reaction[k] = force;
    if (couples) couples_[k] = couple;
  }
}

template <int D>
SurfaceWrench Walls<D>::calcSurfaceWrench(std::size_t surface, const Vec<D>& point) const {
  SurfaceWrench w;
  const BoundaryParticles<D>& b = geometry_.particles;
  const auto [first, last] = ranges_.at(surface);  // a surface is one contiguous range
  for (std::size_t k = first; k < last; ++k) {
    if (!tracked_[k]) continue;
    const Eigen::Vector3d f = to3(b.reaction[k]);
    w.force += f;
    w.torque += to3(Vec<D>(b.r[k] - point)).cross(f);
    if (!couples_.empty()) w.torque += couples_[k];
  }
  return w;
}

template class Walls<2>;
template class Walls<3>;

}  // namespace moorsph::fluid
