#include <moorsph/cases/dam_break.hpp>

#include <algorithm>
#include <cmath>

namespace moorsph::cases {

template <int D>
fluid::Scene<D> buildDamBreak(const DamBreakSpec<D>& spec) {
  fluid::TankSpec<D> tank;
  const double a = spec.column_width;
  tank.size = fluid::Vec<D>::Constant(spec.tank_width);
  tank.size[0] = spec.tank_length;
  tank.size[1] = spec.tank_height;
  tank.lid = spec.lid;
  tank.water_lower = fluid::Vec<D>::Zero();
  tank.water_upper = tank.size;
  tank.water_upper[0] = a;
  tank.water_upper[1] = 2.0 * a;
  tank.dx = spec.dx;
  tank.fluid.effects = spec.effects;
  tank.fluid.method = spec.method;
  tank.fluid.sound_speed = 10.0 * 2.0 * std::sqrt(9.81 * 2.0 * a);
  return fluid::buildTankScene<D>(tank);
}

template <int D>
double measureFront(const fluid::FluidParticles<D>& fluid, double dx) {
  double front = 0.0;
  for (std::size_t i = 0; i < fluid.size(); ++i)
    if (fluid.r[i][1] < 2.0 * dx) front = std::max(front, fluid.r[i][0]);
  return front;
}

template fluid::Scene<2> buildDamBreak<2>(const DamBreakSpec<2>&);
template fluid::Scene<3> buildDamBreak<3>(const DamBreakSpec<3>&);
template double measureFront<2>(const fluid::FluidParticles<2>&, double);
template double measureFront<3>(const fluid::FluidParticles<3>&, double);

}  // namespace moorsph::cases
