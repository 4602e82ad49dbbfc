#include "spheric_test2.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <moorsph/fluid/box_geometry.hpp>

namespace moorsph::cases::spheric_test2 {
namespace {

// The step sampleBoxSurface uses along an edge of length L: the largest that does
// not exceed `spacing` and divides L exactly.
double latticeStep(double length, double spacing) {
  const int n = std::max(1, static_cast<int>(std::ceil(length / spacing - 1e-9)));
  return length / n;
}

}  // namespace

double ritterFrontSpeed() { return 2.0 * std::sqrt(kGravity * kWaterDepth); }

double adjustedSpacing(const Spec& spec) {
  if (!(spec.dx > 0.0)) throw std::invalid_argument("SPHERIC test 2: dx must be positive");
  if (!spec.exact_depth) return spec.dx;
  const double layers = std::max(1.0, std::round(kWaterDepth / spec.dx));
  return kWaterDepth / layers;
}

Built build(const Spec& spec) {
  const double dx = adjustedSpacing(spec);
  fluid::TankSpec<3> tank;
  tank.size = fluid::Vec<3>(kTankLength, kTankHeight, kTankWidth);
  tank.lid = false;
  // The column against the far wall, round(1.228 / dx) particles long: its front is
  // within dx/2 of the gate and its volume within dx/2 x 0.55 x 1 of the experiment's.
  const double column = std::round((kTankLength - kGateX) / dx) * dx;
  tank.water_lower = fluid::Vec<3>(kTankLength - column, 0.0, 0.0);
  tank.water_upper = fluid::Vec<3>(kTankLength, kWaterDepth, kTankWidth);
  tank.dx = dx;
  tank.boundary_spacing = spec.boundary_spacing;
  tank.hydrostatic_start = true;
  tank.fluid.effects = {"pressure", "viscosity", "xsph", "gravity", "walls"};
  if (spec.density_diffusion) tank.fluid.effects.emplace_back("density_diffusion");
  tank.fluid.method = fluid::MethodParameters::reference();
  if (spec.density_diffusion) tank.fluid.method.name = "reference+density_diffusion";
  if (spec.xsph_monaghan) {
    tank.fluid.method.xsph_form = fluid::XsphForm::Monaghan;
    tank.fluid.method.name += "+xsph_monaghan";
  }
  tank.fluid.sound_speed = spec.sound_speed > 0.0 ? spec.sound_speed : 10.0 * ritterFrontSpeed();
  tank.fluid.gravity = fluid::Vec<3>(0.0, -kGravity, 0.0);

  Built built;
  built.scene = fluid::buildTankScene<3>(tank);
  built.tank_surface = 0;
  built.boundary_spacing = spec.boundary_spacing > 0.0 ? spec.boundary_spacing : dx;

  // The box: five faces (none on the floor), normals pointing out into the water.
  // Its reactions are tracked for the pressure sensors.
  fluid::BoxFaces<3> faces = fluid::allFaces<3>();
  faces[2 * 1 + 0] = false;
  const fluid::Vec<3> lower(kBoxLowerX, 0.0, kBoxLowerZ), upper(kBoxUpperX, kBoxHeight, kBoxUpperZ);
  built.box_surface = built.scene.boundary.addSurface(
      fluid::sampleBoxSurface<3>(lower, upper, built.boundary_spacing, faces, fluid::NormalSide::Outward),
      fluid::SurfaceInfo{"box", true});
  return built;
}

std::vector<fluid::WaveGauge<3>> makeGauges(double threshold) {
  std::vector<fluid::WaveGauge<3>> gauges;
  for (const NamedPoint& g : kGauges) {
    fluid::WaveGaugeSpec<3> s;
    s.position = fluid::Vec<3>(g.x, 0.0, g.z);
    s.bottom = 0.0;
    s.top = kTankHeight;
    s.threshold = threshold;
    gauges.emplace_back(s);
  }
  return gauges;
}

std::vector<fluid::PressureProbe<3>> makeProbes(const fluid::FluidSimulation<3>& sim, const Built& built) {
  if (!sim.walls()) throw std::invalid_argument("SPHERIC test 2: the simulation has no walls");
  const double dx = sim.setup().dx;
  const double tile = std::sqrt(latticeStep(kBoxHeight, built.boundary_spacing) *
                                latticeStep(kBoxUpperZ - kBoxLowerZ, built.boundary_spacing));
  std::vector<fluid::PressureProbe<3>> probes;
  for (const NamedPoint& p : kPressureSensors) {
    fluid::PressureProbeSpec<3> s;
    s.surface = built.box_surface;
    s.point = fluid::Vec<3>(p.x, p.y, p.z);
    s.normal = fluid::Vec<3>(1.0, 0.0, 0.0);
    s.radius = dx;
    s.boundary_spacing = tile;
    s.interpolation_offset = 1.5 * dx;
    probes.emplace_back(s, *sim.walls());
  }
  return probes;
}

}  // namespace moorsph::cases::spheric_test2
