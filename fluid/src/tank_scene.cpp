#include <moorsph/fluid/tank_scene.hpp>

#include <stdexcept>

namespace moorsph::fluid {

template <int D>
Scene<D> buildTankScene(const TankSpec<D>& spec) {
  Scene<D> scene;
  scene.setup = spec.fluid;
  scene.setup.dx = spec.dx;
  const double spacing = spec.boundary_spacing > 0.0 ? spec.boundary_spacing : spec.dx;
  if (spacing > spec.dx * (1.0 + 1e-9))
    throw std::invalid_argument("boundary spacing coarser than the fluid spacing lets fluid leak through walls");
  for (int k = 0; k < D; ++k)
    if (spec.water_lower[k] < 0.0 || spec.water_upper[k] > spec.size[k] + 1e-12)
      throw std::invalid_argument("the water block must lie inside the tank");

  // The domain: the tank plus a margin of one interaction radius; an open tank gets
  // headroom above its walls for splashes.
  const double margin = 4.0 * scene.setup.h();
  Domain<D> domain;
  domain.lower = Vec<D>::Constant(-margin);
  domain.upper = spec.size + Vec<D>::Constant(margin);
  if (!spec.lid) domain.upper[1] = spec.size[1] + std::max(spec.size[1], 1.0);
  scene.setup.domain = domain;

  const TaitEos eos(scene.setup.rho0, scene.setup.sound_speed, scene.setup.method.gamma);
  const double g = spec.hydrostatic_start ? -scene.setup.gravity[1] : 0.0;
  fillBox<D>(scene.fluid, spec.water_lower, spec.water_upper, spec.dx, eos, g, spec.water_upper[1]);

  const bool mirror_floor = scene.setup.has("mirror_floor");
  const bool mirror_walls = scene.setup.has("mirror_walls");
  const BoxFaces<D> faces = tankFaces<D>(spec.lid, mirror_floor, mirror_walls);
  if (mirror_floor) scene.setup.mirror_floor_height = 0.0;  // the images close the floor
  if (mirror_walls) scene.setup.mirror_walls = sideMirrorPlanes<D>(Vec<D>::Zero(), spec.size);
  scene.boundary.addSurface(sampleBoxSurface<D>(Vec<D>::Zero(), spec.size, spacing, faces, NormalSide::Inward),
                            SurfaceInfo{"tank", false});
  return scene;
}

template Scene<2> buildTankScene<2>(const TankSpec<2>&);
template Scene<3> buildTankScene<3>(const TankSpec<3>&);

}  // namespace moorsph::fluid
