#include <moorsph/io/scene_builder.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <moorsph/fluid/box_geometry.hpp>
#include <moorsph/fluid/lattice_packing.hpp>
#include <moorsph/io/body_geometry.hpp>
#include <moorsph/io/mesh_sampling.hpp>
#include <moorsph/io/primitive_shapes.hpp>


namespace moorsph::io {
namespace {

template <int D>
fluid::Vec<D> toVec(const Triple& t) {
  fluid::Vec<D> v;
  for (int k = 0; k < D; ++k) v[k] = t[k];
  return v;
}

// The step sampleBoxSurface uses along an edge: the largest not above `spacing`
// that divides the edge exactly.
int latticeCells(double length, double spacing) {
  return std::max(1, static_cast<int>(std::ceil(length / spacing - 1e-9)));
}

int fluidCells(double length, double dx) { return static_cast<int>(std::floor(length / dx + 1e-9)); }

// fillBox fills whole spacings from a water block's lower corner, so a block whose size
// is not a whole number of dx along some axis stops short of its upper face there. In y
// the still level is then lower than the scene says (and everything set relative to it:
// a floating body's rest, a tether's pretension, a forcing region's wave); along x or z a
// gap is left at the upper side, into which the water flows at the start, which lowers the
// level too. Measured on the 6.2c buoy scene at dx = 40.3 mm: a 0.8 m deep block filled to
// 0.7649 m, and a 1 m wide one left a 34 mm gap at its far wall that took the level down
// another 24 mm in the first 2 s (docs/validation/buoy-in-waves.md).
template <int D>
void noteWaterBlock(const WaterConfig& w, double dx, std::size_t index, std::vector<std::string>& notes) {
  const char* const axis = "xyz";
  for (int k = 0; k < D; ++k) {
    const double size = w.box.upper[k] - w.box.lower[k];
    const double filled = fluidCells(size, dx) * dx;
    if (size - filled <= 0.05 * dx) continue;
    char text[320];
    std::snprintf(text, sizeof text,
                  "water block %zu: its %c size %g m is %.3f spacings, so the water stops at %c = %g m, %.4g m short of "
                  "the block's upper face%s (make the size a multiple of dx)",
                  index, axis[k], size, size / dx, axis[k], w.box.lower[k] + filled, size - filled,
                  k == 1 ? "" : ": the water flows into the gap and the still level falls");
    notes.emplace_back(text);
  }
}

/// The packed start of one water block (fluid/lattice_packing.hpp): packed inside the
/// lattice's own extent, then given the hydrostatic density at its new heights.
template <int D>
void packWaterBlock(const WaterConfig& w, std::size_t index, const SceneConfig& c, const fluid::FluidSetup<D>& setup,
                    const fluid::TaitEos& eos, double g, fluid::FluidParticles<D>& block, std::vector<std::string>& notes) {
  fluid::Vec<D> lower, upper;
  for (int k = 0; k < D; ++k) {
    lower[k] = w.box.lower[k];
    upper[k] = w.box.lower[k] + fluidCells(w.box.upper[k] - w.box.lower[k], c.dx) * c.dx;
  }
  fluid::PackingSpec spec;
  spec.iterations = w.packing_iterations;
  spec.seed = 1 + index;
  const fluid::PackingReport r = fluid::packBlock<D>(block, lower, upper, setup.domain, c.dx, setup.h(), spec);
  for (std::size_t i = 0; i < block.size(); ++i) block.rho[i] = fluid::hydrostaticDensity(eos, g, w.box.upper[1], block.r[i][1]);
  char text[320];
  std::snprintf(text, sizeof text,
                "water block %zu packed (%d iterations): kernel sum dx^%d sum W %.4f +- %.4f on the lattice, %.4f +- "
                "%.4f packed (particles 2h or more from its faces); last rms move %.2e dx",
                index, r.iterations, D, r.mean_before, r.spread_before, r.mean_after, r.spread_after, r.last_rms_shift);
  notes.emplace_back(text);
}

/// Where water must not start: inside an obstacle mesh, or closer than `gap` to its
/// surface (a particle there would be thrown off by the wall force). Cost: the
/// particles within `gap` of a mesh's bounding box times its triangles.
class MeshExclusion {
 public:
  void addObstacle(const TriangleMesh& mesh, double gap) {
    meshes_.push_back(&mesh);
    gap_ = gap;
  }
  template <int D>
  bool inside(const fluid::Vec<D>& r) const {
    if constexpr (D != 3) {
      return false;
    } else {
      for (const TriangleMesh* m : meshes_) {
        const Eigen::Vector3d lo = m->lower().array() - gap_, hi = m->upper().array() + gap_;
        if ((r.array() < lo.array()).any() || (r.array() > hi.array()).any()) continue;
        if (meshContains(*m, r) || distanceToMesh(*m, r) < gap_) return true;
      }
      return false;
    }
  }

 private:
  std::vector<const TriangleMesh*> meshes_;
  double gap_ = 0.0;
};

/// Mesh particles as a D-dimensional surface (meshes are 3D only; the loader rejects them in 2D).
template <int D>
fluid::BoundaryParticles<D> meshParticles(const fluid::BoundaryParticles<3>& p) {
  if constexpr (D == 3) {
    return p;
  } else {
    throw std::invalid_argument("mesh geometry is 3D only");
  }
}

template <int D>
fluid::BoxFaces<D> boxFaces(const BoxObstacleConfig& b) {
  fluid::BoxFaces<D> faces = fluid::allFaces<D>();
  for (const auto& f : b.open_faces) faces[2 * (f[1] - 'x') + (f[0] == '+' ? 1 : 0)] = false;
  return faces;
}

// On a periodic axis a face sampled over the whole period has a row at each end, and the
// upper row is the periodic image of the lower one: two particles in one place. Drop the
// upper row, so the rows continue evenly across the seam at any spacing and a scene can
// give such a face the full period ([0, L]) whatever its dx.
template <int D>
fluid::BoundaryParticles<D> withoutPeriodicImages(const fluid::BoundaryParticles<D>& p, const fluid::Domain<D>& domain,
                                                 double spacing) {
  std::array<bool, D> spans{};
  for (int a = 0; a < D; ++a) {
    if (!domain.periodic[a]) continue;
    bool at_lower = false, at_upper = false;
    for (const auto& r : p.r) {
      at_lower = at_lower || r[a] < domain.lower[a] + 0.25 * spacing;
      at_upper = at_upper || r[a] > domain.upper[a] - 0.25 * spacing;
    }
    spans[a] = at_lower && at_upper;
  }
  fluid::BoundaryParticles<D> out;
  for (std::size_t k = 0; k < p.size(); ++k) {
    bool image = false;
    for (int a = 0; a < D; ++a) image = image || (spans[a] && p.r[k][a] > domain.upper[a] - 0.25 * spacing);
    if (image) continue;
    out.add(p.r[k], std::vector<fluid::Vec<D>>(p.normals.begin() + p.normal_begin[k], p.normals.begin() + p.normal_begin[k + 1]),
            p.surface[k]);
  }
  return out;
}

}  // namespace

template <int D>
fluid::FluidSetup<D> makeSetup(const SceneConfig& c) {
  if (c.dim != D) throw std::invalid_argument("buildScene: the scene is " + std::to_string(c.dim) + "D");
  fluid::FluidSetup<D> s;
  s.dx = c.dx;
  s.rho0 = c.rho0;
  s.mu = c.mu;
  s.sound_speed = c.sound_speed;
  s.gravity = toVec<D>(c.gravity);
  s.method = c.method;
  // The wave makers are added by addSceneEffects, not built from the list.
  s.effects.clear();
  for (const auto& e : c.effects)
    if (e != "piston" && e != "damping_zone" && e != "forcing_region" && e != "bodies") s.effects.push_back(e);
  if (c.domain_given) {
    s.domain.lower = toVec<D>(c.domain.lower);
    s.domain.upper = toVec<D>(c.domain.upper);
    for (int k = 0; k < D; ++k) s.domain.periodic[k] = c.periodic[k];
    return s;
  }
  // Default domain: everything in the scene plus a margin of 4h; unless every tank
  // has a lid, headroom above for splashes (as buildTankScene does).
  fluid::Vec<D> lo = toVec<D>(c.water.front().box.lower), hi = toVec<D>(c.water.front().box.upper);
  auto grow = [&](const BoxExtent& b) {
    lo = lo.cwiseMin(toVec<D>(b.lower));
    hi = hi.cwiseMax(toVec<D>(b.upper));
  };
  for (const auto& w : c.water) grow(w.box);
  for (const auto& t : c.tanks) grow(t.box);
  for (const auto& b : c.boxes) grow(b.box);
  for (const auto& k : c.circles) grow(BoxExtent{{k.x - k.radius, k.y - k.radius, 0.0}, {k.x + k.radius, k.y + k.radius, 0.0}});
  for (const auto& g : c.meshes) {
    BoxExtent e;
    for (int k = 0; k < 3; ++k) {
      e.lower[k] = g.mesh.lower()[k];
      e.upper[k] = g.mesh.upper()[k];
    }
    grow(e);
  }
  for (const auto& b : c.bodies) {  // a sphere around the shape's centre holding it
    const Triple at = b.start();
    const auto& sh = b.shape;
    double reach = std::max({sh.radius, 0.5 * std::hypot(sh.size[0], sh.size[1], sh.size[2]), 0.5 * sh.length});
    if (sh.kind == "mesh" || (sh.kind == "cylinder" && D == 3)) reach = std::max(reach, (sh.mesh.upper() - sh.mesh.lower()).norm());
    reach += std::hypot(sh.centre[0], sh.centre[1], sh.centre[2]);
    grow(BoxExtent{{at[0] - reach, at[1] - reach, at[2] - reach}, {at[0] + reach, at[1] + reach, at[2] + reach}});
  }
  const double margin = 4.0 * s.h();
  s.domain.lower = lo - fluid::Vec<D>::Constant(margin);
  s.domain.upper = hi + fluid::Vec<D>::Constant(margin);
  const bool closed = !c.tanks.empty() && std::all_of(c.tanks.begin(), c.tanks.end(), [](const TankConfig& t) { return t.lid; });
  if (!closed) s.domain.upper[1] = hi[1] + std::max(hi[1] - lo[1], 1.0);
  return s;
}

template <int D>
BuiltScene<D> buildScene(const SceneConfig& c, WaterBuild water) {
  BuiltScene<D> out;
  auto& scene = out.scene;
  scene.setup = makeSetup<D>(c);
  const fluid::TaitEos eos(c.rho0, c.sound_speed, c.method.gamma);
  const double g = c.hydrostatic_start ? -c.gravity[1] : 0.0;

  const double spacing = c.spacing();
  std::vector<const BoxExtent*> extents;  // per surface, for the probes' tile size
  std::vector<double> mesh_tiles;         // per surface: sqrt(area per particle) of meshes [m]
  MeshExclusion near_mesh;
  for (const auto& t : c.tanks) {
    fluid::BoxFaces<D> faces = fluid::tankFaces<D>(t.lid, t.mirror_floor, t.mirror_sides);
    // A tank spanning a periodic axis has no faces normal to it: the wrap closes the water
    // there, and a face would put a wall across the seam.
    for (int a = 0; a < D; ++a)
      if (c.spansPeriod(t.box, a)) faces[2 * a] = faces[2 * a + 1] = false;
    if (t.mirror_floor) scene.setup.mirror_floor_height = t.box.lower[1];  // its plane replaces the -y face
    if (t.mirror_sides) scene.setup.mirror_walls = fluid::sideMirrorPlanes<D>(toVec<D>(t.box.lower), toVec<D>(t.box.upper));
    scene.boundary.addSurface(withoutPeriodicImages<D>(fluid::sampleBoxSurface<D>(toVec<D>(t.box.lower), toVec<D>(t.box.upper),
                                                                                  spacing, faces, fluid::NormalSide::Inward),
                                                       scene.setup.domain, spacing),
                              fluid::SurfaceInfo{t.name, t.track_reaction});
    extents.push_back(&t.box);
  }
  for (const auto& b : c.boxes) {
    scene.boundary.addSurface(withoutPeriodicImages<D>(fluid::sampleBoxSurface<D>(toVec<D>(b.box.lower), toVec<D>(b.box.upper),
                                                                                  spacing, boxFaces<D>(b), fluid::NormalSide::Outward),
                                                       scene.setup.domain, spacing),
                              fluid::SurfaceInfo{b.name, b.track_reaction, false, Eigen::Vector3d::Zero(), b.open_faces.empty()});
    extents.push_back(&b.box);
  }

  for (const auto& m : c.meshes) {
    const auto particles = sampleMeshSurface(m.mesh, spacing, m.inward ? fluid::NormalSide::Inward : fluid::NormalSide::Outward);
    const auto index = scene.boundary.addSurface(meshParticles<D>(particles), fluid::SurfaceInfo{m.name, m.track_reaction});
    extents.push_back(nullptr);
    mesh_tiles.resize(index + 1, 0.0);
    mesh_tiles[index] = std::sqrt(m.mesh.area() / static_cast<double>(particles.size()));
    if (!m.inward) near_mesh.addObstacle(m.mesh, 0.45 * c.dx);
  }

  for (const auto& k : c.circles) {
    if constexpr (D == 2) {
      const auto index = scene.boundary.addSurface(
          sampleCircle(Eigen::Vector2d(k.x, k.y), k.radius, spacing, fluid::NormalSide::Outward),
          fluid::SurfaceInfo{k.name, k.track_reaction, false, Eigen::Vector3d::Zero(), true});
      extents.push_back(nullptr);
      mesh_tiles.resize(index + 1, 0.0);
      mesh_tiles[index] = 2.0 * M_PI * k.radius / std::ceil(2.0 * M_PI * k.radius / spacing - 1e-9);
    }
  }

  if (c.piston.present) {
    // The plate: the +x face of a box 2 spacings thick behind x, normals toward the water.
    const auto& p = c.piston;
    fluid::Vec<D> lo = fluid::Vec<D>::Zero(), hi = fluid::Vec<D>::Zero();
    lo[0] = p.x - 2.0 * spacing;
    hi[0] = p.x;
    lo[1] = p.bottom;
    hi[1] = p.top;
    if constexpr (D == 3) {
      lo[2] = p.z_lower;
      hi[2] = p.z_upper;
    }
    fluid::BoxFaces<D> faces{};
    faces[1] = true;
    // Reaction-tracking so the plate's force (and the work it does on the water) can be read.
    fluid::SurfaceInfo info{p.name, true, true, Eigen::Vector3d(p.x, 0.0, 0.0)};
    out.piston_surface = scene.boundary.addSurface(
        withoutPeriodicImages<D>(fluid::sampleBoxSurface<D>(lo, hi, spacing, faces, fluid::NormalSide::Outward),
                                 scene.setup.domain, spacing),
        info);
    extents.push_back(nullptr);
  }

  for (const auto& b : c.bodies) {
    const Triple at = b.start();
    // A body is a closed solid (its mass properties need one): the leak guard watches it.
    fluid::SurfaceInfo info{b.name, true, true, Eigen::Vector3d(at[0], at[1], D == 3 ? at[2] : 0.0), true};
    out.body_surfaces.push_back(scene.boundary.addSurface(sampleBodySurface<D>(b, spacing), info));
    extents.push_back(nullptr);
  }

  for (std::size_t wi = 0; wi < c.water.size(); ++wi) {
    const auto& w = c.water[wi];
    noteWaterBlock<D>(w, c.dx, wi, out.notes);
    if (water == WaterBuild::Skip) continue;
    fluid::FluidParticles<D> block;
    fluid::fillBox<D>(block, toVec<D>(w.box.lower), toVec<D>(w.box.upper), c.dx, eos, g, w.box.upper[1]);
    if (w.packed) packWaterBlock<D>(w, wi, c, scene.setup, eos, g, block, out.notes);
    // Obstacle boxes are solid: water is not placed inside them (a particle half a
    // spacing outside a face stays).
    for (std::size_t i = 0; i < block.size(); ++i) {
      bool solid = false;
      for (const auto& b : c.boxes) {
        bool in = true;
        for (int k = 0; k < D; ++k)
          in = in && block.r[i][k] > b.box.lower[k] - 0.25 * c.dx && block.r[i][k] < b.box.upper[k] + 0.25 * c.dx;
        solid = solid || in;
      }
      solid = solid || near_mesh.inside(block.r[i]);
      for (const auto& k : c.circles)  // 2D obstacles: inside, or within 0.45 dx of the circle
        solid = solid || std::hypot(block.r[i][0] - k.x, block.r[i][1] - k.y) < k.radius + 0.45 * c.dx;
      for (const auto& b : c.bodies) solid = solid || insideBody<D>(b, block.r[i], 0.45 * c.dx);
      if (!solid) scene.fluid.add(block.r[i], block.v[i], block.rho[i], block.m[i]);
    }
  }
  if (water == WaterBuild::Particles && scene.fluid.size() == 0)
    throw std::invalid_argument("the scene's water blocks hold no particle outside its boxes");

  for (const auto& gc : c.gauges) {
    fluid::WaveGaugeSpec<D> g;
    g.position = fluid::Vec<D>::Zero();
    g.position[0] = gc.x;
    if (D == 3) g.position[D - 1] = gc.z;
    g.bottom = gc.bottom;
    g.top = gc.top;
    g.threshold = gc.threshold;
    g.volume_edge = gc.volume_edge;
    out.gauge_names.push_back(gc.name);
    out.gauges.push_back(g);
  }
  for (const auto& pc : c.probes) {
    fluid::PressureProbeSpec<D> p;
    for (std::size_t s = 0; s < scene.boundary.surfaces.size(); ++s)
      if (scene.boundary.surfaces[s].name == pc.surface) p.surface = s;
    p.point = toVec<D>(pc.point);
    p.normal = toVec<D>(pc.normal).normalized();
    p.radius = pc.radius;
    p.interpolation_offset = pc.interpolation_offset;
    if (pc.on_body) {  // placed by the body's motion when the probe is made (pressure_probe.hpp)
      p.body_frame = true;
      p.boundary_spacing = spacing;
      out.probe_names.push_back(pc.name);
      out.probe_means.push_back(pc.moving_mean);
      out.probes.push_back(p);
      continue;
    }
    // Each boundary particle stands for a tile of the lattice steps along the face.
    int normal_axis = 0;
    p.normal.cwiseAbs().maxCoeff(&normal_axis);
    if (extents[p.surface]) {
      const BoxExtent& box = *extents[p.surface];
      double tile = 1.0;
      for (int k = 0; k < D; ++k) {
        if (k == normal_axis) continue;
        const double edge = box.upper[k] - box.lower[k];
        tile *= edge / latticeCells(edge, spacing);
      }
      p.boundary_spacing = std::pow(tile, 1.0 / (D - 1));
    } else {
      p.boundary_spacing = mesh_tiles[p.surface];
    }
    out.probe_names.push_back(pc.name);
    out.probe_means.push_back(pc.moving_mean);
    out.probes.push_back(p);
  }
  for (const auto& vc : c.velocity_probes) {
    fluid::VelocityProbeSpec<D> v;
    v.point = toVec<D>(vc.point);
    v.min_fill = vc.min_fill;
    out.velocity_probe_names.push_back(vc.name);
    out.velocity_probes.push_back(v);
  }
  for (const auto& pc : c.packing_probes) {
    fluid::PackingProbeSpec<D> p;
    p.lower = toVec<D>(pc.lower);
    p.upper = toVec<D>(pc.upper);
    p.spacing = pc.spacing > 0.0 ? pc.spacing : fluid::kPackingSpacingPerDx * c.dx;
    p.min_fill = pc.min_fill;
    out.packing_probe_names.push_back(pc.name);
    out.packing_probes.push_back(p);
    out.packing_warn_rises.push_back(pc.warn_rise);
  }
  return out;
}

ParticleCounts countParticles(const SceneConfig& c) {
  ParticleCounts n;
  for (const auto& w : c.water) {
    std::size_t count = 1;
    for (int k = 0; k < c.dim; ++k) count *= static_cast<std::size_t>(fluidCells(w.box.upper[k] - w.box.lower[k], c.dx));
    n.fluid += count;
  }
  // Lattice points of the box, minus the interior, minus points only on open faces:
  // counted exactly by building the surfaces would allocate; this is the closed-box
  // count, exact for closed surfaces and an upper bound for open ones.
  auto surface = [&](const BoxExtent& b) {
    std::size_t all = 1, inner = 1;
    for (int k = 0; k < c.dim; ++k) {
      const int cells = latticeCells(b.upper[k] - b.lower[k], c.spacing());
      all *= static_cast<std::size_t>(cells + 1);
      inner *= static_cast<std::size_t>(std::max(cells - 1, 0));
    }
    return all - inner;
  };
  for (const auto& t : c.tanks) n.boundary += surface(t.box);
  for (const auto& b : c.boxes) n.boundary += surface(b.box);
  return n;
}

template BuiltScene<2> buildScene<2>(const SceneConfig&, WaterBuild);
template BuiltScene<3> buildScene<3>(const SceneConfig&, WaterBuild);
template fluid::FluidSetup<2> makeSetup<2>(const SceneConfig&);
template fluid::FluidSetup<3> makeSetup<3>(const SceneConfig&);

}  // namespace moorsph::io
