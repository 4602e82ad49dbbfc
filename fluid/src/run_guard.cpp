#include <moorsph/fluid/run_guard.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <moorsph/fluid/outflow.hpp>

namespace moorsph::fluid {
namespace {

// The design speed of the weakly-compressible method: c_s >= 10 x the largest flow
// speed keeps density variations near 1% (METHOD.md section 1).
constexpr double kDesignMach = 0.1;

template <int D>
bool finiteState(const FluidParticles<D>& f, std::size_t i) {
  return f.r[i].allFinite() && f.v[i].allFinite() && std::isfinite(f.rho[i]);
}

/// The boundary surface nearest to r (brute force: only called when a run fails).
/// `behind`: r lies behind every normal of the nearest boundary particle, so inside a
/// body or beyond a wall (in front of any one of an edge particle's faces is outside).
struct NearestSurface {
  std::string name;
  double distance = std::numeric_limits<double>::infinity();
  bool behind = false;
};

template <int D>
NearestSurface nearestSurface(const Walls<D>* walls, const Vec<D>& r) {
  NearestSurface out;
  if (!walls || !r.allFinite()) return out;
  const BoundaryParticles<D>& b = walls->particles();
  std::size_t best = b.size();
  for (std::size_t k = 0; k < b.size(); ++k) {
    const double d = (b.r[k] - r).norm();
    if (d < out.distance) {
      out.distance = d;
      best = k;
    }
  }
  if (best == b.size()) return out;
  out.name = walls->surfaces()[b.surface[best]].name;
  out.behind = true;
  for (std::uint32_t n = b.normal_begin[best]; n < b.normal_begin[best + 1]; ++n)
    if ((r - b.r[best]).dot(b.normals[n]) >= 0.0) out.behind = false;
  return out;
}

template <int D>
double maxSpeed(const std::vector<Vec<D>>& velocities) {
  double v2 = 0.0;
  for (const Vec<D>& v : velocities)
    if (v.allFinite()) v2 = std::max(v2, v.squaredNorm());
  return std::sqrt(v2);
}

template <int D>
std::size_t densest(const FluidParticles<D>& f) {
  std::size_t best = 0;
  for (std::size_t i = 1; i < f.size(); ++i)
    if (f.rho[i] > f.rho[best]) best = i;
  return best;
}

template <int D>
void describeParticle(std::ostream& os, const FluidParticles<D>& f, std::size_t i, const GuardContext<D>& ctx) {
  const double speed = f.v[i].norm();
  os << " at t = " << ctx.time << " s (step " << ctx.step << "): particle id " << f.id[i] << " at r = ("
     << f.r[i].transpose() << ") m, v = (" << f.v[i].transpose() << ") m/s (|v| = " << speed << " m/s = "
     << speed / ctx.setup.sound_speed << " c_s), rho = " << f.rho[i] << " kg/m^3";
  const NearestSurface s = nearestSurface(ctx.walls, f.r[i]);
  if (!s.name.empty()) os << "; nearest boundary surface '" << s.name << "' at " << s.distance << " m";
}

/// Names a body or piston moving faster than c_s/10 as the cause; false if none does.
template <int D>
bool movingSurfaceTooFast(std::ostream& os, const GuardContext<D>& ctx) {
  const double limit = kDesignMach * ctx.setup.sound_speed;
  const double wall_speed = ctx.walls ? ctx.walls->maxMovingSpeed() : 0.0;
  if (wall_speed <= limit) return false;
  os << "a moving surface (a body or piston) moves at " << wall_speed << " m/s, faster than c_s/10 = " << limit
     << " m/s; raise sound_speed or slow the body";
  return true;
}

/// What lets a particle through a wall: its own speed, a moving surface's, or the
/// sampling of the surface (the remaining cause when neither is too fast).
template <int D>
void causeOfCrossing(std::ostream& os, const FluidParticles<D>& f, std::size_t i, const GuardContext<D>& ctx) {
  const double c = ctx.setup.sound_speed;
  const double speed = f.v[i].norm();
  if (speed > kDesignMach * c)
    os << "its speed " << speed << " m/s exceeds c_s/10 = " << kDesignMach * c
       << " m/s, beyond what the wall force (scaled by c_s^2) can stop; raise sound_speed to at least 10x the "
          "largest flow speed";
  else if (!movingSurfaceTooFast(os, ctx))
    os << "a gap in the surface's boundary particles (a sharp edge with no particle carrying both faces' normals, a "
          "face narrower than the boundary spacing, a spacing coarser than dx = "
       << ctx.setup.dx << " m, or a thin wall crossed at a corner); check the surface's sampling there or refine dx";
}

/// Likely cause of a particle found behind or beyond a wall.
template <int D>
void causeOfEscape(std::ostream& os, const FluidParticles<D>& f, std::size_t i, const GuardContext<D>& ctx) {
  const double c = ctx.setup.sound_speed;
  const double speed = f.v[i].norm();
  const NearestSurface s = nearestSurface(ctx.walls, f.r[i]);
  const std::string wall = s.name.empty() ? "a wall" : "surface '" + s.name + "'";
  // Over the walls (above the top of the static wall on the side it left by, or above
  // the domain's top clear of every wall): a splash thrown out of an open tank, not a
  // leak (a leak is below the wall's top). The outflow effect's own test decides.
  const bool over_top = f.r[i][1] >= ctx.setup.domain.upper[1] && s.distance > 2.0 * ctx.setup.h();
  bool over_walls = over_top;
  if (ctx.walls && !over_walls) {
    const WallExtent<D> extent = ctx.walls->staticExtent(0.5 * ctx.setup.dx);
    over_walls = !extent.empty() &&
                 Outflow<D>(extent, std::numeric_limits<double>::infinity()).qualifies(f, i, ctx.setup.domain);
  }
  if (over_walls) {
    os << ". Likely cause: a splash thrown out of an open tank " << (over_top ? "above the domain's top" : "over its walls")
       << " (it left at y = " << f.r[i][1] << " m)";
    if (ctx.setup.has("outflow"))
      os << "; the outflow effect did not take it because it moves at " << speed << " m/s, at least c_s/2 = "
         << 0.5 * c << " m/s: flung by a numerical fault (raise sound_speed, enable density_diffusion or lower the CFL)";
    else
      os << "; list the 'outflow' effect to let such spray leave the run, or make the tank (and with it the domain) "
            "taller or close it with a lid";
    return;
  }
  os << ". Likely cause: the particle passed through " << wall << ": ";
  causeOfCrossing(os, f, i, ctx);
}

/// Likely cause of a particle faster than the guard's limit. The position at the start
/// of the step is tested too: a particle thrown out from behind a surface may already be
/// back in front of it.
template <int D>
void causeOfSpeed(std::ostream& os, const FluidParticles<D>& f, std::size_t i, const GuardContext<D>& ctx) {
  const double c = ctx.setup.sound_speed;
  const NearestSurface now = nearestSurface(ctx.walls, f.r[i]);
  const NearestSurface before =
      f.r_start.size() == f.size() ? nearestSurface(ctx.walls, f.r_start[i]) : NearestSurface{};
  os << ". Likely cause: ";
  if (now.behind || before.behind) {
    const NearestSurface& s = now.behind ? now : before;
    os << "the particle " << (now.behind ? "is" : "was, at the start of the step,") << " behind surface '" << s.name
       << "' (" << s.distance / ctx.setup.dx
       << " dx from its nearest boundary particle): it got through a gap in that surface's boundary particles (a "
          "sharp edge with no particle carrying both faces' normals, a face narrower than the boundary spacing, or a "
          "spacing coarser than dx) and the wall force threw it out; check the surface's sampling there or refine dx";
  } else if (!movingSurfaceTooFast(os, ctx)) {
    os << "the flow is far beyond the weakly-compressible range (built for c_s/10 = " << kDesignMach * c
       << " m/s): raise sound_speed to at least 10x the largest physical flow speed, enable density_diffusion or "
          "lower the cfl";
  }
}

}  // namespace

template <int D>
std::size_t findUnhealthyParticle(const FluidParticles<D>& f, const Domain<D>& domain, double max_speed) {
  const std::size_t n = f.size();
  // 0 disables the speed limit; the squared limit keeps the loop free of square roots.
  const double v2_max = max_speed > 0.0 ? max_speed * max_speed : std::numeric_limits<double>::infinity();
  std::size_t bad = n;
#pragma omp parallel for schedule(static) reduction(min : bad)
  for (std::size_t i = 0; i < n; ++i) {
    if (!finiteState(f, i) || !domain.contains(f.r[i]) || !(f.rho[i] > 0.0) || f.v[i].squaredNorm() > v2_max)
      bad = std::min(bad, i);
  }
  return bad;
}

template <int D>
std::size_t findLargestAcceleration(const FluidParticles<D>& f) {
  std::size_t best = 0;
  double a2 = -1.0;
  for (std::size_t i = 0; i < f.size(); ++i) {
    const double x = f.dvdt[i].squaredNorm();
    if (x > a2) {
      a2 = x;
      best = i;
    }
  }
  return best;
}

template <int D>
std::string describeUnhealthyParticle(const FluidParticles<D>& f, std::size_t i, const GuardContext<D>& ctx) {
  std::ostringstream os;
  const Domain<D>& domain = ctx.setup.domain;
  if (!finiteState(f, i)) {
    os << "non-finite fluid state";
    describeParticle(os, f, i, ctx);
    const double vmax = maxSpeed<D>(f.v);
    os << ". Likely cause: a blow-up that grew over the previous steps; the fastest finite particle moves at "
       << vmax << " m/s (c_s/10 = " << kDesignMach * ctx.setup.sound_speed
       << " m/s): if it exceeds c_s/10 raise sound_speed, otherwise a splash in tension (enable density_diffusion)";
  } else if (!domain.contains(f.r[i])) {
    os << "fluid particle left the domain";
    describeParticle(os, f, i, ctx);
    os << "; domain (" << domain.lower.transpose() << ") .. (" << domain.upper.transpose() << ") m";
    causeOfEscape(os, f, i, ctx);
  } else if (!(f.rho[i] > 0.0)) {
    os << "non-positive fluid density";
    describeParticle(os, f, i, ctx);
    os << ". Likely cause: the fluid there is in tension (a splash sheet or a free surface pulled apart): the "
          "continuity equation drove rho through zero. Enable density_diffusion (method option), which removes the "
          "density noise that starts it, or refine dx";
  } else {
    os << "fluid particle faster than method.max_speed_fraction = " << ctx.setup.method.max_speed_fraction
       << " of c_s";
    describeParticle(os, f, i, ctx);
    causeOfSpeed(os, f, i, ctx);
  }
  return os.str();
}

template <int D>
LeakedParticle findLeakedParticle(const FluidParticles<D>& f, const Walls<D>& walls, const NeighbourList& list,
                                  const Domain<D>& domain, double depth, double dx) {
  const BoundaryParticles<D>& b = walls.particles();
  const std::vector<SurfaceInfo>& surfaces = walls.surfaces();
  const std::size_t n = f.size();
  if (list.begin.size() != n + 1) return {n, 0, 0.0};  // a stale list (outflow removed particles): next step
  const MinimumImage<D> image(domain);
  // How far r_ik lies behind particle k's faces: behind all of an edge particle's
  // normals (in front of any one is outside), by the least of them; negative in front.
  auto depthBehind = [&](std::size_t i, std::uint32_t k) {
    const Vec<D> r_ik = image(f.r[i] - b.r[k]);
    double front = -std::numeric_limits<double>::infinity();
    for (std::uint32_t a = b.normal_begin[k]; a < b.normal_begin[k + 1]; ++a) front = std::max(front, r_ik.dot(b.normals[a]));
    return -front;
  };
  auto nearest = [&](std::size_t i) {
    std::uint32_t best = 0;
    double d2 = std::numeric_limits<double>::infinity();
    for (std::uint64_t s = list.begin[i]; s < list.begin[i + 1]; ++s) {
      const std::uint32_t k = list.index[s];
      const double r2 = image(f.r[i] - b.r[k]).squaredNorm();
      if (r2 < d2) {
        d2 = r2;
        best = k;
      }
    }
    return best;
  };
  // Behind the surface's patch round i: every particle of it within half a spacing
  // beyond the nearest (farther ones may lie past a concave turn of the surface: in the
  // 6 m ship's bow a particle 0.17 dx inside had an edge particle 1.5 dx away in front).
  auto behindPatch = [&](std::size_t i, std::uint32_t nearest_k) {
    const double reach = image(f.r[i] - b.r[nearest_k]).norm() + 0.5 * dx;
    for (std::uint64_t s = list.begin[i]; s < list.begin[i + 1]; ++s) {
      const std::uint32_t k = list.index[s];
      if (b.surface[k] != b.surface[nearest_k] || image(f.r[i] - b.r[k]).squaredNorm() > reach * reach)
        continue;
      if (depthBehind(i, k) <= 0.0) return false;
    }
    return true;
  };
  auto leaked = [&](std::size_t i, std::uint32_t k) {
    return surfaces[b.surface[k]].closed && depthBehind(i, k) > depth && behindPatch(i, k);
  };
  std::size_t bad = n;
#pragma omp parallel for schedule(static) reduction(min : bad)
  for (std::size_t i = 0; i < n; ++i) {
    if (list.begin[i] == list.begin[i + 1]) continue;
    if (leaked(i, nearest(i))) bad = std::min(bad, i);
  }
  if (bad == n) return {n, 0, 0.0};
  const std::uint32_t k = nearest(bad);
  return {bad, k, depthBehind(bad, k)};
}

template <int D>
std::string describeLeakedParticle(const FluidParticles<D>& f, const LeakedParticle& leak, const GuardContext<D>& ctx) {
  const BoundaryParticles<D>& b = ctx.walls->particles();
  const std::string name = ctx.walls->surfaces()[b.surface[leak.boundary]].name;
  const double dx = ctx.setup.dx;
  std::ostringstream os;
  os << "fluid particle inside closed surface '" << name << "'";
  describeParticle(os, f, leak.fluid, ctx);
  os << "; it is " << leak.depth << " m = " << leak.depth / dx
     << " dx behind the faces of its nearest boundary particle, at (" << b.r[leak.boundary].transpose()
     << ") m, and behind every particle of that surface up to half a spacing farther away (method.max_leak_depth = "
     << ctx.setup.method.max_leak_depth << " dx). Likely cause: the particle got through surface '" << name << "': ";
  causeOfCrossing(os, f, leak.fluid, ctx);
  return os.str();
}

template <int D>
std::string describeDtCollapse(const FluidParticles<D>& f, double dt, double cfl_dt, const GuardContext<D>& ctx) {
  const std::size_t i = findLargestAcceleration(f);
  const std::size_t j = densest(f);
  const double c = ctx.setup.sound_speed;
  // The flow speed before the collapsing step (the step itself can fling particles).
  const double vmax = maxSpeed<D>(f.v_start.size() == f.size() ? f.v_start : f.v);
  std::ostringstream os;
  os << "time step collapsed: dt = " << dt << " s is below min_dt_fraction = " << ctx.setup.method.min_dt_fraction
     << " of the CFL step " << cfl_dt << " s; largest acceleration |a| = " << f.dvdt[i].norm() << " m/s^2";
  describeParticle(os, f, i, ctx);
  os << "; densest particle id " << f.id[j] << " at r = (" << f.r[j].transpose() << ") m, rho = " << f.rho[j]
     << " kg/m^3 = " << f.rho[j] / ctx.setup.rho0 << " rho0. Likely cause: ";
  if (vmax > kDesignMach * c) {
    os << "the flow speed before the step, " << vmax << " m/s, exceeds c_s/10 = " << kDesignMach * c
       << " m/s, so the fluid is compressed far beyond the weakly-compressible range; raise sound_speed to at least "
       << 10.0 * vmax << " m/s";
  } else {
    const NearestSurface s = nearestSurface(ctx.walls, f.r[j]);
    if (!s.name.empty() && s.distance < 2.0 * ctx.setup.h())
      os << "the densest particle is squeezed against surface '" << s.name << "' (" << s.distance / ctx.setup.dx
         << " dx away): a body or wall closing on the fluid faster than it can escape, or boundary particles "
            "sparser than dx";
    else
      os << "the densest particle is over-compressed inside the fluid (colliding jets or a trapped pocket), "
            "beyond the weakly-compressible range; raise sound_speed or enable density_diffusion";
  }
  return os.str();
}

template std::size_t findUnhealthyParticle<2>(const FluidParticles<2>&, const Domain<2>&, double);
template std::size_t findUnhealthyParticle<3>(const FluidParticles<3>&, const Domain<3>&, double);
template std::size_t findLargestAcceleration<2>(const FluidParticles<2>&);
template std::size_t findLargestAcceleration<3>(const FluidParticles<3>&);
template std::string describeUnhealthyParticle<2>(const FluidParticles<2>&, std::size_t, const GuardContext<2>&);
template std::string describeUnhealthyParticle<3>(const FluidParticles<3>&, std::size_t, const GuardContext<3>&);
template LeakedParticle findLeakedParticle<2>(const FluidParticles<2>&, const Walls<2>&, const NeighbourList&,
                                             const Domain<2>&, double, double);
template LeakedParticle findLeakedParticle<3>(const FluidParticles<3>&, const Walls<3>&, const NeighbourList&,
                                             const Domain<3>&, double, double);
template std::string describeLeakedParticle<2>(const FluidParticles<2>&, const LeakedParticle&, const GuardContext<2>&);
template std::string describeLeakedParticle<3>(const FluidParticles<3>&, const LeakedParticle&, const GuardContext<3>&);
template std::string describeDtCollapse<2>(const FluidParticles<2>&, double, double, const GuardContext<2>&);
template std::string describeDtCollapse<3>(const FluidParticles<3>&, double, double, const GuardContext<3>&);

}  // namespace moorsph::fluid
