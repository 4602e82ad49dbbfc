#pragma once
// A single layer of boundary particles with outward unit normals pointing into the
// fluid (METHOD.md section 2). A corner or edge particle carries several normals
// (one per face that meets there); `normal_begin[k] .. normal_begin[k+1]` indexes
// particle k's normals in `normals`.
//
// Each particle belongs to a surface (a tank, an obstacle, a body). Surfaces that
// are moved rigidly keep body-frame reference coordinates so nothing drifts.
#include <cstdint>
#include <string>
#include <vector>
#include <moorsph/fluid/vec.hpp>

namespace moorsph::fluid {

template <int D>
struct BoundaryParticles {
  std::vector<Vec<D>> r;                   ///< position [m]
  std::vector<std::uint32_t> normal_begin{0};  ///< size() + 1 offsets into `normals`
  std::vector<Vec<D>> normals;             ///< unit normals into the fluid
  std::vector<std::uint16_t> surface;      ///< owning surface index
  std::vector<Vec<D>> reaction;            ///< force the fluid exerts on particle k [N]

  std::size_t size() const { return r.size(); }
  std::uint32_t normalCount(std::size_t k) const { return normal_begin[k + 1] - normal_begin[k]; }

  /// Add one particle with one or more normals (each is normalised here).
  void add(const Vec<D>& position, const std::vector<Vec<D>>& particle_normals, std::uint16_t surface_index) {
    r.push_back(position);
    for (const Vec<D>& n : particle_normals) normals.push_back(n.normalized());
    normal_begin.push_back(static_cast<std::uint32_t>(normals.size()));
    surface.push_back(surface_index);
    reaction.push_back(Vec<D>::Zero());
  }

  /// Append every particle of `other`, assigning them to `surface_index`.
  void append(const BoundaryParticles& other, std::uint16_t surface_index) {
    for (std::size_t k = 0; k < other.size(); ++k) {
      std::vector<Vec<D>> ns;
      for (std::uint32_t a = other.normal_begin[k]; a < other.normal_begin[k + 1]; ++a) ns.push_back(other.normals[a]);
      add(other.r[k], ns, surface_index);
    }
  }
};

/// Metadata of one boundary surface.
struct SurfaceInfo {
  std::string name;
  bool track_reaction = false;  ///< compute per-particle reactions (bodies, sensors)
  /// Moved rigidly during the run (a piston, a body). Only movable surfaces keep
  /// body-frame reference coordinates; static walls cost nothing extra.
  bool movable = false;
  /// Reference point of a movable surface at t = 0 [m] (only the first D components are
  /// used): body-frame coordinates are measured from it, and motions place it.
  Eigen::Vector3d reference_point = Eigen::Vector3d::Zero();
  /// The particles sample a closed surface (a body, a closed obstacle): the water is
  /// outside it everywhere, so a fluid particle behind it has leaked in (the leak guard,
  /// run_guard.hpp). An open surface (a tank, a plate, a piston) has free edges that
  /// water may pass over; the guard leaves it alone.
  bool closed = false;
};

}  // namespace moorsph::fluid
