#include <moorsph/fluid/pressure_probe.hpp>
#include <moorsph/fluid/fluid_near_point.hpp>

#include <cmath>
#include <stdexcept>

namespace moorsph::fluid {
namespace {

// A patch particle carries a normal within 30 degrees of the sensor's: the angle within
// which the mesh sampler joins face normals into one (io/src/mesh_sampling.cpp), so a
// sensor on a curved hull finds its face at any spacing; faces of a box (90 degrees
// apart) stay separate.
constexpr double kFaceCosine = 0.8660254037844386;

}  // namespace

template <int D>
PressureProbe<D>::PressureProbe(PressureProbeSpec<D> spec, const Walls<D>& walls) : spec_(std::move(spec)) {
  if (!(spec_.normal.norm() > 0.0)) throw std::invalid_argument("pressure probe: the wall normal must be non-zero");
  spec_.normal.normalize();
  if (!(spec_.boundary_spacing > 0.0)) throw std::invalid_argument("pressure probe: boundary spacing must be positive");
  if (spec_.surface >= walls.surfaces().size()) throw std::invalid_argument("pressure probe: unknown surface");
  if (!walls.surfaces()[spec_.surface].track_reaction)
    throw std::invalid_argument("pressure probe: surface '" + walls.surfaces()[spec_.surface].name +
                                "' does not track reactions");
  if (spec_.body_frame) {  // placed by the surface's motion now
    if (!walls.surfaces()[spec_.surface].movable)
      throw std::invalid_argument("pressure probe: a body-frame point needs a movable surface");
    const RigidMotion<D>& m = walls.surfaceMotion(spec_.surface);
    spec_.point = m.position + m.rotation * spec_.point;
    spec_.normal = m.rotation * spec_.normal;
    spec_.body_frame = false;
  }
  const BoundaryParticles<D>& b = walls.particles();
  for (std::size_t k = 0; k < b.size(); ++k) {
    if (b.surface[k] != spec_.surface) continue;
    if ((b.r[k] - spec_.point).norm() > spec_.radius) continue;
    bool on_face = false;
    for (std::uint32_t a = b.normal_begin[k]; a < b.normal_begin[k + 1]; ++a)
      on_face = on_face || b.normals[a].dot(spec_.normal) > kFaceCosine;
    if (on_face) patch_.push_back(static_cast<std::uint32_t>(k));
  }
  if (patch_.empty()) throw std::invalid_argument("pressure probe: no boundary particle of the face within the radius");
  patch_area_ = static_cast<double>(patch_.size()) * std::pow(spec_.boundary_spacing, D - 1);
  if (walls.surfaces()[spec_.surface].movable) {
    const RigidMotion<D>& m = walls.surfaceMotion(spec_.surface);
    moving_ = true;
    body_point_ = m.rotation.transpose() * (spec_.point - m.position);
    body_normal_ = m.rotation.transpose() * spec_.normal;
  }
}

template <int D>
Vec<D> PressureProbe<D>::currentPoint(const Walls<D>& walls) const {
  if (!moving_) return spec_.point;
  const RigidMotion<D>& m = walls.surfaceMotion(spec_.surface);
  return m.position + m.rotation * body_point_;
}

template <int D>
Vec<D> PressureProbe<D>::currentNormal(const Walls<D>& walls) const {
  if (!moving_) return spec_.normal;
  return walls.surfaceMotion(spec_.surface).rotation * body_normal_;
}

template <int D>
double PressureProbe<D>::readReaction(const Walls<D>& walls) const {
  const BoundaryParticles<D>& b = walls.particles();
  const Vec<D> normal = currentNormal(walls);
  double push = 0.0;  // force of the fluid into the wall [N]
  for (const std::uint32_t k : patch_) push -= b.reaction[k].dot(normal);
  return push / patch_area_;
}

template <int D>
double PressureProbe<D>::readReaction(const FluidSimulation<D>& sim) const {
  if (!sim.walls()) throw std::invalid_argument("pressure probe: the simulation has no walls");
  return readReaction(*sim.walls());
}

template <int D>
double PressureProbe<D>::readInterpolated(const FluidSimulation<D>& sim) const {
  if (!sim.walls()) throw std::invalid_argument("pressure probe: the simulation has no walls");
  const Vec<D> point = currentPoint(*sim.walls());
  const Vec<D> r0 = point + spec_.interpolation_offset * currentNormal(*sim.walls());
  const FluidParticles<D>& f = sim.fluid();
  const TaitEos& eos = sim.eos();
  double weighted = 0.0, weight = 0.0;
  forEachFluidNear(sim, r0, [&](std::size_t j, double w) {
    weighted += w * eos.pressure(f.rho[j]);
    weight += w;
  });
  if (weight <= 0.0) return 0.0;
  const Vec<D> g = sim.setup().has("gravity") ? sim.setup().gravity : Vec<D>::Zero();
  return weighted / weight - eos.rho0() * g.dot(r0 - point);
}

template class PressureProbe<2>;
template class PressureProbe<3>;

}  // namespace moorsph::fluid
