#pragma once
// The "walls" effect: every boundary surface (tank walls, obstacles, bodies) as one
// layer of boundary particles pushing the fluid along their normals
// (BoundaryForceLaw, METHOD.md section 2). For surfaces that track reactions it also
// sums, per boundary particle, the equal and opposite force of the fluid on it; these
// give a body's hydrodynamic wrench and the load on pressure sensors.
#include <vector>
#include <Eigen/Geometry>
#include <moorsph/fluid/boundary_force_law.hpp>
#include <moorsph/fluid/counted.hpp>
#include <moorsph/fluid/fluid_effect.hpp>
#include <moorsph/fluid/rigid_motion.hpp>
#include <moorsph/fluid/wall_extent.hpp>

namespace moorsph::fluid {

/// Boundary particles with the surfaces they belong to.
template <int D>
struct BoundaryGeometry {
  BoundaryParticles<D> particles;
  std::vector<SurfaceInfo> surfaces;

  /// Append `part` as a new surface and return its index.
  std::uint16_t addSurface(const BoundaryParticles<D>& part, SurfaceInfo info) {
    const auto index = static_cast<std::uint16_t>(surfaces.size());
    surfaces.push_back(std::move(info));
    particles.append(part, index);
    return index;
  }
  bool empty() const { return particles.size() == 0; }
};

/// Net force [N] and torque [N m] about a reference point. In 2D the torque is the
/// z component (about the axis normal to the x-y plane).
struct SurfaceWrench {
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  Eigen::Vector3d torque = Eigen::Vector3d::Zero();
};

template <int D>
class Walls final : public FluidEffect<D>, public Counted<Walls<D>> {
 public:
  Walls(BoundaryGeometry<D> geometry, const FluidSetup<D>& setup);

  const char* name() const override { return "walls"; }
  void addRates(FluidContext<D>& ctx) override;

  const BoundaryParticles<D>& particles() const { return geometry_.particles; }
  BoundaryParticles<D>& updParticles() { return geometry_.particles; }
  const std::vector<SurfaceInfo>& surfaces() const { return geometry_.surfaces; }
  /// 1 for boundary particles whose reactions are computed.
  const std::vector<char>& trackedMask() const { return tracked_; }
  const BoundaryForceLaw<D>& law() const { return law_; }

  /// Sum of the reactions of `surface` and their moments about `point` (tracked surfaces
  /// only). The moments are taken at the boundary particles; with the conservative wall
  /// law at the fluid particles (the torque that keeps the pair's angular momentum).
  SurfaceWrench calcSurfaceWrench(std::size_t surface, const Vec<D>& point) const;

  /// Place a movable surface: every particle is rebuilt from its body-frame reference
  /// coordinates and normals (r = position + R r_ref, n = R n_ref), so nothing drifts.
  /// Throws std::invalid_argument for a surface that is not movable.
  void setSurfaceMotion(std::size_t surface, const RigidMotion<D>& motion);
  const RigidMotion<D>& surfaceMotion(std::size_t surface) const;
  /// Largest speed of any particle of a movable surface at its current motion [m/s].
  double maxMovingSpeed() const;
  /// Bounding box of the particles of the static (not movable) surfaces [m] and the top
  /// of those within `tolerance` [m] of each of its vertical faces; empty if there are none.
  WallExtent<D> staticExtent(double tolerance) const;
  /// Particle index range [first, second) of a surface.
  std::pair<std::size_t, std::size_t> surfaceRange(std::size_t surface) const { return ranges_.at(surface); }

 private:
  void addReactions(FluidContext<D>& ctx);
  void findSurfaceRanges();
  /// The push of boundary particle k on fluid particle i: the force law, cancelled when
  /// i is beyond an edge of k's surface. Inline: it is the walls' inner loop.
  Vec<D> push(const FluidContext<D>& ctx, const MinimumImage<D>& image, std::size_t i, std::size_t k) const {
    const BoundaryParticles<D>& b = geometry_.particles;
    const Vec<D> r_ik = image(ctx.fluid.r[i] - b.r[k]);
    const Vec<D> a = law_.acceleration(r_ik, b, k);
    // Only near a convex edge or a thin part can i be beyond an edge of k's surface.
    if (near_feature_[k] && !a.isZero() && beyondAnEdge(ctx, image, i, k, r_ik)) return Vec<D>::Zero();
    return a;
  }
  /// BoundaryForceLaw::beyondEdge against each of i's boundary neighbours.
  bool beyondAnEdge(const FluidContext<D>& ctx, const MinimumImage<D>& image, std::size_t i, std::size_t k,
                    const Vec<D>& r_ik) const;
  void findFeatureParticles(double reach);

  /// Body-frame copy of a movable surface.
  struct MovableSurface {
    std::size_t surface;
    std::vector<Vec<D>> reference_r;        ///< relative to the reference point
    std::vector<Vec<D>> reference_normals;  ///< in the order of BoundaryParticles::normals
    double radius = 0.0;                    ///< largest |reference_r|
    RigidMotion<D> motion;
  };

  BoundaryGeometry<D> geometry_;
  std::vector<std::pair<std::size_t, std::size_t>> ranges_;
  std::vector<MovableSurface> movable_;
  BoundaryForceLaw<D> law_;
  std::vector<char> tracked_;
  bool any_tracked_ = false;
  /// Conservative law only: per tracked boundary particle k, sum_i r_ik x (-F_ik), which
  /// moves each reaction's moment from r_k to the fluid particle r_i.
  std::vector<Eigen::Vector3d> couples_;
  /// Per boundary particle: one normal, and a particle of its own surface within 4h
  /// meets its face convexly or back to back (BoundaryForceLaw::meeting), so the
  /// beyond-edge test can apply. Rigid motion keeps it; tanks and flat stretches skip it.
  std::vector<char> near_feature_;
};

}  // namespace moorsph::fluid
