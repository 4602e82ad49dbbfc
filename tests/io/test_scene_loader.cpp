// Scene files: the examples load and build; each class of error is rejected before
// anything is allocated, with file:line:column, the key and what is expected.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <moorsph/fluid/waves/dispersion.hpp>
#include <moorsph/io/scene_builder.hpp>
#include "spheric_test2.hpp"
#include <moorsph/io/scene_loader.hpp>

using namespace moorsph;

namespace {

std::string sourceDir() {
  const char* dir = std::getenv("MOORSPH_SOURCE_DIR");
  return dir ? dir : ".";
}

const char* const kBase = R"(dim: 2
end_time: 0.1
resolution:
  dx: 0.01
fluid:
  sound_speed: 25
geometry:
  - tank: {lower: [0, 0], upper: [0.4, 0.3], lid: true}
  - water: {lower: [0, 0], upper: [0.1, 0.2]}
)";

/// The message of the SceneError that loading `text` raises ("" if none).
std::string errorOf(const std::string& text, const std::vector<std::string>& sets = {}) {
  try {
    io::loadSceneText(text, "s.yaml", sets);
  } catch (const io::SceneError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(SceneLoader, EveryCaseSceneLoads) {
  // Every scene shipped under cases/ passes the loader's validation (keys, units, ranges,
  // the files it names): a scene added or edited without being run cannot rot unnoticed.
  int scenes = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(sourceDir() + "/cases")) {
    if (entry.path().extension() != ".yaml") continue;
    SCOPED_TRACE(entry.path().string());
    EXPECT_NO_THROW(io::loadSceneFile(entry.path().string()));
    ++scenes;
  }
  EXPECT_GE(scenes, 30);
}

TEST(SceneLoader, ExamplesLoadAndBuild) {
  for (const char* name : {"dam_break_2d", "dam_break_3d", "hydrostatic_tank_2d", "cylinder_in_dam_break_3d",
                           "piston_flume_2d_low_dissipation"}) {
    SCOPED_TRACE(name);
    const auto c = io::loadSceneFile(sourceDir() + "/cases/" + name + ".yaml");
    EXPECT_EQ(c.name, name);
    const auto n = io::countParticles(c);
    if (c.dim == 2) {
      const auto built = io::buildScene<2>(c);
      EXPECT_LE(built.scene.fluid.size(), n.fluid);
      EXPECT_EQ(built.gauges.size(), c.gauges.size());
      EXPECT_EQ(built.probes.size(), c.probes.size());
    } else {
      const auto built = io::buildScene<3>(c);
      EXPECT_EQ(built.scene.fluid.size(), n.fluid);
      if (c.meshes.empty()) {
        EXPECT_EQ(built.scene.boundary.particles.size(), n.boundary);  // closed tank: exact
      }
    }
  }
}

TEST(SceneLoader, DamBreakMatchesTheBuiltInScene) {
  const auto c = io::loadSceneFile(sourceDir() + "/cases/dam_break_2d.yaml");
  const auto built = io::buildScene<2>(c);
  EXPECT_EQ(built.scene.fluid.size(), 20u * 40u);  // 0.1 x 0.2 m at dx = 5 mm
  EXPECT_DOUBLE_EQ(built.scene.setup.sound_speed, 28.0);
  EXPECT_EQ(built.scene.setup.method.name, "reference");
  EXPECT_TRUE(built.scene.boundary.surfaces[0].track_reaction);  // a probe sits on it
}

TEST(SceneLoader, ResolvedYamlLoadsToTheSameScene) {
  const auto a = io::loadSceneFile(sourceDir() + "/cases/hydrostatic_tank_2d.yaml");
  const std::string text = io::resolvedSceneYaml(a);
  const auto b = io::loadSceneText(text, "resolved.yaml");
  EXPECT_EQ(io::resolvedSceneYaml(b), text);
  EXPECT_EQ(b.sound_speed, a.sound_speed);
  EXPECT_EQ(b.method.xsph_form, fluid::XsphForm::Monaghan);
}

TEST(SceneLoader, UnknownKeySuggestsTheClosest) {
  const std::string msg = errorOf(std::string(kBase) + "output:\n  intervall: 0.1\n");
  EXPECT_NE(msg.find("s.yaml:11:3"), std::string::npos) << msg;
  EXPECT_NE(msg.find("'output.intervall'"), std::string::npos) << msg;
  EXPECT_NE(msg.find("did you mean 'interval'"), std::string::npos) << msg;
  const std::string top = errorOf(std::string(kBase) + "gauge: []\n");
  EXPECT_NE(top.find("did you mean 'gauges'"), std::string::npos) << top;
}

TEST(SceneLoader, WrongTypeNamesWhatIsExpected) {
  std::string text = kBase;
  text.replace(text.find("0.01"), 4, "fine");
  const std::string msg = errorOf(text);
  EXPECT_NE(msg.find("s.yaml:4:7"), std::string::npos) << msg;
  EXPECT_NE(msg.find("'resolution.dx': expected a number, got 'fine'"), std::string::npos) << msg;
  const std::string vec = errorOf(std::string(kBase) + "fluid2: 1\n");
  EXPECT_NE(vec.find("unknown key"), std::string::npos);
  std::string three = kBase;
  three.replace(three.find("[0.1, 0.2]"), 10, "[0.1, 0.2, 0.1]");
  EXPECT_NE(errorOf(three).find("expected a list of 2 numbers"), std::string::npos) << errorOf(three);
}

TEST(SceneLoader, MissingRequiredKey) {
  std::string text = kBase;
  text.erase(text.find("end_time: 0.1\n"), 14);
  const std::string msg = errorOf(text);
  EXPECT_NE(msg.find("'end_time': required key is missing"), std::string::npos) << msg;
  EXPECT_NE(msg.find("s.yaml:1:1"), std::string::npos) << msg;
}

TEST(SceneLoader, OutOfRangeValues) {
  std::string neg = kBase;
  neg.replace(neg.find("0.01"), 4, "-0.01");
  EXPECT_NE(errorOf(neg).find("'resolution.dx': expected a particle spacing > 0 [m]"), std::string::npos) << errorOf(neg);

  std::string coarse = kBase;
  coarse.replace(coarse.find("dx: 0.01"), 8, "dx: 0.01\n  boundary_spacing: 0.02");
  const std::string c = errorOf(coarse);
  EXPECT_NE(c.find("s.yaml:5:21"), std::string::npos) << c;
  EXPECT_NE(c.find("not be coarser than the fluid spacing"), std::string::npos) << c;

  std::string slow = kBase;
  slow.replace(slow.find("sound_speed: 25"), 15, "sound_speed: 12");
  const std::string s = errorOf(slow);
  EXPECT_NE(s.find("'fluid.sound_speed': c_s = 12 m/s is below 10 x sqrt(2 g H) = 19.8"), std::string::npos) << s;
  EXPECT_NE(s.find("s.yaml:6:16"), std::string::npos) << s;

  std::string feature = std::string(kBase) + "  - box: {name: pin, lower: [0.3, 0], upper: [0.315, 0.1]}\n";
  const std::string f = errorOf(feature);
  EXPECT_NE(f.find("the box is 0.015 m along x, finer than the resolution allows"), std::string::npos) << f;
  EXPECT_NE(f.find("s.yaml:10:"), std::string::npos) << f;

  const std::string probe = errorOf(std::string(kBase) +
                                    "pressure_probes:\n  - {surface: tank, point: [0.2, 0.1], normal: [0, 1]}\n");
  EXPECT_NE(probe.find("'pressure_probes[0].point': the point is 0.1 m from the surface 'tank'"), std::string::npos)
      << probe;

  std::string unpacked = kBase;
  unpacked.replace(unpacked.find("[0.1, 0.2]}"), 11, "[0.1, 0.2], packing_iterations: 10}");
  EXPECT_NE(errorOf(unpacked).find("'geometry[1].water.packing_iterations': set 'packed: true' as well"), std::string::npos)
      << errorOf(unpacked);
  std::string no_iterations = kBase;
  no_iterations.replace(no_iterations.find("[0.1, 0.2]}"), 11, "[0.1, 0.2], packed: true, packing_iterations: 0}");
  EXPECT_NE(errorOf(no_iterations).find("expected a positive number of iterations"), std::string::npos)
      << errorOf(no_iterations);

  std::string outside = kBase;
  outside.replace(outside.find("[0.1, 0.2]"), 10, "[0.5, 0.2]");
  EXPECT_NE(errorOf(outside).find("must lie inside a tank"), std::string::npos) << errorOf(outside);
}

TEST(SceneLoader, FeaturesThatDoNotExistYetAreRejected) {
  const std::string bodies = errorOf(std::string(kBase) + "bodies:\n  - {name: buoy}\n");
  EXPECT_NE(bodies.find("s.yaml:11:5: 'bodies[0].mass': required key is missing"), std::string::npos) << bodies;
  const std::string stl = errorOf(std::string(kBase) + "  - stl: {file: a.stl}\n");
  EXPECT_NE(stl.find("'geometry[2].stl': not supported yet"), std::string::npos) << stl;
  const std::string coupled = errorOf(std::string(kBase) + "effects: [pressure, gravity, walls, bodies]\n");
  EXPECT_NE(coupled.find("'bodies' is listed but the scene has no 'bodies' list"), std::string::npos) << coupled;
  const std::string typo = errorOf(std::string(kBase) + "effects: [pressure, gravty, walls]\n");
  EXPECT_NE(typo.find("did you mean 'gravity'"), std::string::npos) << typo;
}

TEST(SceneLoader, OutflowIsAnEffectThatNeedsWalls) {
  const auto c = io::loadSceneText(std::string(kBase) + "effects: [pressure, gravity, walls, outflow]\n", "s.yaml");
  EXPECT_TRUE(c.hasEffect("outflow"));
  const std::string wall_less = errorOf(R"(dim: 2
end_time: 0.1
resolution: {dx: 0.01}
domain: {lower: [-0.1, -0.1], upper: [0.5, 0.5]}
geometry:
  - water: {lower: [0, 0], upper: [0.1, 0.1]}
effects: [pressure, gravity, outflow]
)");
  EXPECT_NE(wall_less.find("s.yaml:7:"), std::string::npos) << wall_less;
  EXPECT_NE(wall_less.find("'walls' must be listed too"), std::string::npos) << wall_less;
}

TEST(SceneLoader, CommandLineOverrides) {
  const auto c = io::loadSceneText(kBase, "s.yaml", {"resolution.dx=0.005", "geometry[1].water.upper=[0.1, 0.1]",
                                                     "method.cfl=0.25", "output.interval=0.02"});
  EXPECT_EQ(c.dx, 0.005);
  EXPECT_EQ(c.water[0].box.upper[1], 0.1);
  EXPECT_EQ(c.method.cfl, 0.25);
  EXPECT_EQ(c.method.name, "reference+options");
  EXPECT_EQ(c.output.interval, 0.02);
  const std::string msg = errorOf(kBase, {"resolution.dx=-1"});
  EXPECT_NE(msg.find("--set resolution.dx: 'resolution.dx'"), std::string::npos) << msg;
  EXPECT_NE(errorOf(kBase, {"resolution.dx"}).find("expected key.path=value"), std::string::npos);
}

TEST(SceneLoader, MeshObstacle) {
  const auto c = io::loadSceneFile(sourceDir() + "/cases/cylinder_in_dam_break_3d.yaml");
  ASSERT_EQ(c.meshes.size(), 1u);
  EXPECT_TRUE(c.meshes[0].track_reaction);
  const auto built = io::buildScene<3>(c);
  ASSERT_EQ(built.scene.boundary.surfaces.size(), 2u);
  EXPECT_EQ(built.scene.boundary.surfaces[1].name, "cylinder");
  // Water 0.15 x 0.2 x 0.2 m at dx = 1 cm; the cylinder (x = 0.35 .. 0.45) lies outside it.
  EXPECT_EQ(built.scene.fluid.size(), 15u * 20u * 20u);
  // Its probe's tile is the mesh's area per particle, close to the spacing.
  ASSERT_EQ(built.probes.size(), 1u);
  EXPECT_GT(built.probes[0].boundary_spacing, 0.7 * c.dx);
  EXPECT_LT(built.probes[0].boundary_spacing, 1.0 * c.dx);

  // Water poured over the cylinder is kept out of it and off its surface.
  const auto flooded = io::loadSceneFile(sourceDir() + "/cases/cylinder_in_dam_break_3d.yaml",
                                         {"geometry[1].water.upper=[0.6, 0.2, 0.2]"});
  const auto wet = io::buildScene<3>(flooded);
  std::size_t inside = 0;
  double closest = 1.0;
  for (const auto& r : wet.scene.fluid.r) {
    const double radial = std::hypot(r.x() - 0.4, r.z() - 0.1) - 0.05;
    if (radial < 0.0 && r.y() < 0.15) ++inside;
    if (r.y() < 0.15) closest = std::min(closest, std::abs(radial));
  }
  EXPECT_EQ(inside, 0u);
  EXPECT_GT(closest, 0.45 * c.dx - 0.3e-3);  // the 32-gon lies within 0.3 mm inside the circle
  const double removed = 60.0 * 20.0 * 20.0 - static_cast<double>(wet.scene.fluid.size());
  const double cylinder = M_PI * 0.05 * 0.05 * 0.15 / 1e-6;  // particles in its volume
  EXPECT_GT(removed, cylinder);
  EXPECT_LT(removed, 1.6 * cylinder);
}

TEST(SceneLoader, MeshErrors) {
  const std::string mesh_item = "  - mesh: {name: m, file: " + sourceDir() + "/cases/meshes/cylinder.obj}\n";
  const std::string flat = errorOf(std::string(kBase) + mesh_item);
  EXPECT_NE(flat.find("'geometry[2].mesh.file': mesh geometry is 3D only"), std::string::npos) << flat;
  const std::string base3 = R"(dim: 3
end_time: 0.1
resolution: {dx: 0.01}
fluid: {sound_speed: 25}
geometry:
  - tank: {lower: [0, 0, 0], upper: [0.4, 0.3, 0.2]}
  - water: {lower: [0, 0, 0], upper: [0.1, 0.2, 0.2]}
)";
  const std::string missing = errorOf(base3 + "  - mesh: {file: nowhere.stl}\n");
  EXPECT_NE(missing.find("s.yaml:8:"), std::string::npos) << missing;
  EXPECT_NE(missing.find("cannot open the mesh file"), std::string::npos) << missing;
  const std::string tiny = errorOf(base3 + "  - mesh: {file: " + sourceDir() + "/cases/meshes/cylinder.obj, scale: 0.1}\n");
  EXPECT_NE(tiny.find("the mesh is 0.01 m along x, finer than the resolution allows"), std::string::npos) << tiny;
  const std::string side = errorOf(base3 + "  - mesh: {file: " + sourceDir() + "/cases/meshes/cylinder.obj, normals: out}\n");
  EXPECT_NE(side.find("expected 'outward'"), std::string::npos) << side;
  EXPECT_NE(errorOf(base3 + "  - sphere: {radius: 0.1}\n").find("'geometry[2].sphere.centre': required key is missing"),
            std::string::npos);
}

TEST(SceneLoader, SpheresAndCylinders) {
  // 2D: a cylinder is a circle of particles with radial normals; water keeps out of it.
  const std::string circle = std::string(kBase) +
                             "  - cylinder: {name: pile, centre: [0.05, 0.1], radius: 0.03}\n"
                             "pressure_probes:\n  - {name: P, surface: pile, point: [0.02, 0.1], normal: [-1, 0]}\n";
  const auto c2 = io::loadSceneText(circle, "c.yaml");
  ASSERT_EQ(c2.circles.size(), 1u);
  const auto b2 = io::buildScene<2>(c2);
  ASSERT_EQ(b2.scene.boundary.surfaces.size(), 2u);
  EXPECT_TRUE(b2.scene.boundary.surfaces[1].track_reaction);
  const auto& bp = b2.scene.boundary.particles;
  std::size_t on_circle = 0;
  for (std::size_t k = 0; k < bp.size(); ++k) {
    if (bp.surface[k] != 1) continue;
    ++on_circle;
    const Eigen::Vector2d radial = (bp.r[k] - Eigen::Vector2d(0.05, 0.1)) / 0.03;
    EXPECT_NEAR(radial.norm(), 1.0, 1e-12);
    EXPECT_NEAR(bp.normals[bp.normal_begin[k]].dot(radial), 1.0, 1e-12);
  }
  EXPECT_EQ(on_circle, 19u);  // ceil(2 pi 0.03 / 0.01)
  for (const auto& r : b2.scene.fluid.r) EXPECT_GE((r - Eigen::Vector2d(0.05, 0.1)).norm(), 0.03 + 0.45 * 0.01);
  EXPECT_LT(b2.scene.fluid.size(), 200u);
  EXPECT_NEAR(b2.probes[0].boundary_spacing, 2 * M_PI * 0.03 / 19, 1e-12);
  EXPECT_EQ(io::resolvedSceneYaml(io::loadSceneText(io::resolvedSceneYaml(c2), "r.yaml")), io::resolvedSceneYaml(c2));

  // 3D: a sphere and a cylinder along x become meshes; water keeps out of them.
  const std::string solids = R"(dim: 3
end_time: 0.1
resolution: {dx: 0.01}
fluid: {sound_speed: 25}
geometry:
  - tank: {lower: [0, 0, 0], upper: [0.4, 0.3, 0.2]}
  - water: {lower: [0, 0, 0], upper: [0.4, 0.2, 0.2]}
  - sphere: {name: ball, centre: [0.1, 0.1, 0.1], radius: 0.05}
  - cylinder: {name: bar, centre: [0.3, 0.1, 0.1], radius: 0.03, length: 0.1, axis: x}
)";
  const auto c3 = io::loadSceneText(solids, "s3.yaml");
  ASSERT_EQ(c3.meshes.size(), 2u);
  EXPECT_NEAR(c3.meshes[0].mesh.signedVolume(), 4.0 / 3.0 * M_PI * 0.05 * 0.05 * 0.05, 2e-6);
  EXPECT_NEAR(c3.meshes[1].mesh.signedVolume(), M_PI * 0.03 * 0.03 * 0.1, 2e-6);
  const auto b3 = io::buildScene<3>(c3);
  for (const auto& r : b3.scene.fluid.r) {
    EXPECT_GE((r - Eigen::Vector3d(0.1, 0.1, 0.1)).norm(), 0.05 + 0.4 * 0.01);
    const bool in_bar = std::abs(r.x() - 0.3) < 0.05 && std::hypot(r.y() - 0.1, r.z() - 0.1) < 0.03;
    EXPECT_FALSE(in_bar);
  }
  const std::string resolved = io::resolvedSceneYaml(c3);
  EXPECT_NE(resolved.find("sphere:"), std::string::npos);
  EXPECT_EQ(io::resolvedSceneYaml(io::loadSceneText(resolved, "r.yaml")), resolved);

  EXPECT_NE(errorOf(std::string(kBase) + "  - sphere: {centre: [0.2, 0.1], radius: 0.05}\n").find("a sphere is 3D only"),
            std::string::npos);
  EXPECT_NE(errorOf(std::string(kBase) + "  - cylinder: {centre: [0.2, 0.1], radius: 0.005}\n")
                .find("radius 0.005 m is finer than the resolution allows"),
            std::string::npos);
}

TEST(SceneLoader, SphericTest2MatchesTheCppBuilder) {
  const auto c = io::loadSceneFile(sourceDir() + "/cases/spheric_test2.yaml");
  const auto from_file = io::buildScene<3>(c);
  cases::spheric_test2::Spec spec;
  spec.dx = 0.025;
  spec.sound_speed = 46.5;  // the scene's round value (the builder's default is 46.454...)
  const auto by_hand = cases::spheric_test2::build(spec);
  const auto& a = from_file.scene;
  const auto& b = by_hand.scene;
  EXPECT_EQ(a.setup.sound_speed, b.setup.sound_speed);
  EXPECT_EQ(a.setup.effects, b.setup.effects);
  ASSERT_EQ(a.fluid.size(), b.fluid.size());
  double worst = 0.0;
  for (std::size_t i = 0; i < a.fluid.size(); ++i) {
    worst = std::max(worst, (a.fluid.r[i] - b.fluid.r[i]).norm());
    worst = std::max(worst, std::abs(a.fluid.rho[i] - b.fluid.rho[i]) / 1000.0);
  }
  EXPECT_LT(worst, 1e-12);
  ASSERT_EQ(a.boundary.particles.size(), b.boundary.particles.size());
  for (std::size_t k = 0; k < a.boundary.particles.size(); ++k) {
    ASSERT_LT((a.boundary.particles.r[k] - b.boundary.particles.r[k]).norm(), 1e-12) << k;
    ASSERT_EQ(a.boundary.particles.normalCount(k), b.boundary.particles.normalCount(k)) << k;
  }
  EXPECT_EQ(from_file.gauges.size(), 4u);
  ASSERT_EQ(from_file.probes.size(), 4u);
  EXPECT_EQ(from_file.probes[0].surface, by_hand.box_surface);
}

// method.particle_shifting and method.min_dt_fraction reach the fluid setup; the effect
// is built only when listed; bad values are rejected with the key and the line.
TEST(SceneLoader, ParticleShiftingAndTheStepGuard) {
  const std::string method =
      "method:\n  min_dt_fraction: 0.01\n  particle_shifting: {coefficient: 1.5, anti_clustering: 0.1, cap: 0.3}\n";
  const auto c = io::loadSceneText(std::string(kBase) + method +
                                       "effects: [pressure, xsph, density_diffusion, particle_shifting, gravity, walls]\n",
                                   "s.yaml");
  EXPECT_EQ(c.method.shifting.coefficient, 1.5);
  EXPECT_EQ(c.method.shifting.anti_clustering, 0.1);
  EXPECT_EQ(c.method.shifting.cap, 0.3);
  EXPECT_EQ(c.method.min_dt_fraction, 0.01);
  EXPECT_EQ(c.method.name, "reference+options");
  const auto again = io::loadSceneText(io::resolvedSceneYaml(c), "resolved.yaml");
  EXPECT_EQ(again.method.shifting.coefficient, 1.5);
  EXPECT_EQ(again.method.min_dt_fraction, 0.01);
  const auto built = io::buildScene<2>(c);
  EXPECT_EQ(built.scene.setup.method.shifting.cap, 0.3);
  EXPECT_TRUE(built.scene.setup.has("particle_shifting"));

  // The guard alone is not a method option.
  const auto guard =
      io::loadSceneText(std::string(kBase) + "method:\n  min_dt_fraction: 0\n  max_speed_fraction: 0.8\n  max_leak_depth: 0.3\n", "s.yaml");
  EXPECT_EQ(guard.method.name, "reference");
  EXPECT_EQ(guard.method.min_dt_fraction, 0.0);
  EXPECT_EQ(guard.method.max_speed_fraction, 0.8);
  EXPECT_EQ(guard.method.max_leak_depth, 0.3);
  const auto guard_again = io::loadSceneText(io::resolvedSceneYaml(guard), "resolved.yaml");
  EXPECT_EQ(guard_again.method.max_speed_fraction, 0.8);
  EXPECT_EQ(guard_again.method.max_leak_depth, 0.3);
  EXPECT_EQ(c.method.max_speed_fraction, 0.5);
  EXPECT_EQ(c.method.max_leak_depth, 0.1);
  const std::string speed = errorOf(std::string(kBase) + "method:\n  max_speed_fraction: -1\n");
  EXPECT_NE(speed.find("'method.max_speed_fraction'"), std::string::npos) << speed;
  const std::string leak = errorOf(std::string(kBase) + "method:\n  max_leak_depth: -0.1\n");
  EXPECT_NE(leak.find("'method.max_leak_depth'"), std::string::npos) << leak;

  const std::string cap = errorOf(std::string(kBase) + "method:\n  particle_shifting: {cap: 2}\n");
  EXPECT_NE(cap.find("'method.particle_shifting.cap'"), std::string::npos) << cap;
  EXPECT_NE(cap.find("s.yaml:11:"), std::string::npos) << cap;
  const std::string typo = errorOf(std::string(kBase) + "method:\n  particle_shifting: {coeficient: 2}\n");
  EXPECT_NE(typo.find("did you mean 'coefficient'"), std::string::npos) << typo;
  const std::string frac = errorOf(std::string(kBase) + "method:\n  min_dt_fraction: 1.5\n");
  EXPECT_NE(frac.find("'method.min_dt_fraction': expected a fraction in [0, 1)"), std::string::npos) << frac;
}

// The density diffusion's form is read, written back and reaches the built fluid.
TEST(SceneLoader, RenormalisedDensityDiffusion) {
  const auto c = io::loadSceneText(std::string(kBase) + "method:\n  density_diffusion: {form: renormalised, delta: 0.05}\n" +
                                       "effects: [pressure, density_diffusion, gravity, walls]\n",
                                   "s.yaml");
  EXPECT_EQ(c.method.density_diffusion_form, fluid::DensityDiffusionForm::Renormalised);
  const auto again = io::loadSceneText(io::resolvedSceneYaml(c), "resolved.yaml");
  EXPECT_EQ(again.method.density_diffusion_form, fluid::DensityDiffusionForm::Renormalised);
  EXPECT_EQ(again.method.density_diffusion_delta, 0.05);
  const std::string bad = errorOf(std::string(kBase) + "method:\n  density_diffusion: {form: antuono}\n");
  EXPECT_NE(bad.find("'method.density_diffusion.form'"), std::string::npos) << bad;
  EXPECT_NE(bad.find("'renormalised'"), std::string::npos) << bad;
}

// A tank with "floor: mirror" leaves out its floor's particles and sets the
// mirror_floor plane at its lower face; the key and the effect go together.
TEST(SceneLoader, MirrorFloorTank) {
  const std::string mirror = R"(dim: 2
end_time: 0.1
resolution:
  dx: 0.01
fluid:
  sound_speed: 25
effects: [pressure, gravity, walls, mirror_floor]
geometry:
  - tank: {lower: [0, -0.05], upper: [0.4, 0.3], floor: mirror}
  - water: {lower: [0, -0.05], upper: [0.1, 0.2]}
)";
  const auto c = io::loadSceneText(mirror, "s.yaml");
  const auto built = io::buildScene<2>(c);
  EXPECT_TRUE(built.scene.setup.has("mirror_floor"));
  EXPECT_DOUBLE_EQ(built.scene.setup.mirror_floor_height, -0.05);
  int up = 0;  // normals of a floor (the side walls' bottom particles point along x only)
  for (const auto& n : built.scene.boundary.particles.normals) up += n[1] > 0.5;
  EXPECT_EQ(up, 0) << "a floor particle was left in";
  const auto walls = io::buildScene<2>(io::loadSceneText(kBase, "s.yaml"));
  EXPECT_FALSE(walls.scene.setup.has("mirror_floor"));
  for (const auto& n : walls.scene.boundary.particles.normals) up += n[1] > 0.5;
  EXPECT_GT(up, 30) << "the walls floor has its row";
  const auto again = io::loadSceneText(io::resolvedSceneYaml(c), "resolved.yaml");
  EXPECT_TRUE(again.tanks.at(0).mirror_floor);

  const std::string no_effect = errorOf(std::string(kBase) + "effects: [pressure, gravity, walls, mirror_floor]\n");
  EXPECT_NE(no_effect.find("no tank has 'floor: mirror'"), std::string::npos) << no_effect;
  std::string missing = mirror;
  missing.replace(missing.find(", mirror_floor]"), 15, "]");
  const std::string no_key = errorOf(missing);
  EXPECT_NE(no_key.find("'mirror_floor' is not in the effects"), std::string::npos) << no_key;
  std::string typo = mirror;
  typo.replace(typo.find("floor: mirror"), 13, "floor: mirrored");
  const std::string bad = errorOf(typo);
  EXPECT_NE(bad.find("'geometry[0].tank.floor'"), std::string::npos) << bad;
  EXPECT_NE(bad.find("s.yaml:9:"), std::string::npos) << bad;
}

// A tank with "sides: mirror" leaves out its side walls' particles and sets the
// mirror_walls planes at its side faces; the key and the effect go together, and a
// domain periodic across them is refused at the key. A tank closed by images alone
// needs no 'walls', and listing it there (nothing has wall particles) is refused.
TEST(SceneLoader, MirrorWallsTank) {
  const std::string mirror = R"(dim: 3
end_time: 0.1
resolution:
  dx: 0.02
fluid:
  sound_speed: 25
effects: [pressure, gravity, mirror_floor, mirror_walls]
geometry:
  - tank: {lower: [0, 0, -0.1], upper: [0.4, 0.3, 0.2], floor: mirror, sides: mirror}
  - water: {lower: [0, 0, -0.1], upper: [0.4, 0.2, 0.2]}
)";
  const auto c = io::loadSceneText(mirror, "s.yaml");
  const auto built = io::buildScene<3>(c);
  ASSERT_EQ(built.scene.setup.mirror_walls.size(), 4u);
  EXPECT_DOUBLE_EQ(built.scene.setup.mirror_walls[2].position, -0.1);  // the -z face
  EXPECT_EQ(built.scene.setup.mirror_walls[2].axis, 2);
  EXPECT_EQ(built.scene.boundary.particles.size(), 0u) << "an open tank with mirror floor and sides keeps no particle";
  const auto again = io::loadSceneText(io::resolvedSceneYaml(c), "resolved.yaml");
  EXPECT_TRUE(again.tanks.at(0).mirror_sides);

  std::string missing = mirror;
  missing.replace(missing.find(", mirror_walls]"), 15, "]");
  const std::string no_effect = errorOf(missing);
  EXPECT_NE(no_effect.find("'mirror_walls' is not in the effects"), std::string::npos) << no_effect;
  std::string periodic = mirror;
  periodic.replace(periodic.find("geometry:"), 9,
                   "domain: {lower: [-0.1, -0.1, -0.1], upper: [0.5, 0.8, 0.2], periodic: [false, false, true]}\ngeometry:");
  const std::string across = errorOf(periodic);
  EXPECT_NE(across.find("'geometry[0].tank.sides'"), std::string::npos) << across;
  EXPECT_NE(across.find("periodic along z"), std::string::npos) << across;
  std::string walls = mirror;
  walls.replace(walls.find("gravity, mirror_floor"), 21, "gravity, walls, mirror_floor");
  const std::string idle = errorOf(walls);
  EXPECT_NE(idle.find("leave 'walls' out"), std::string::npos) << idle;
}

// The wall law's own length: read, checked against h_factor and b_off, written back.
TEST(SceneLoader, WallLawLength) {
  const auto c = io::loadSceneText(std::string(kBase) + "method:\n  h_factor: 2\n  boundary_h_factor: 1.2\n", "s.yaml");
  EXPECT_DOUBLE_EQ(c.method.boundary_h_factor, 1.2);
  EXPECT_EQ(c.method.name, "reference+options");
  const auto again = io::loadSceneText(io::resolvedSceneYaml(c), "resolved.yaml");
  EXPECT_DOUBLE_EQ(again.method.boundary_h_factor, 1.2);
  const auto same = io::loadSceneText(std::string(kBase) + "method:\n  boundary_h_factor: 1.2\n", "s.yaml");
  EXPECT_EQ(same.method.boundary_h_factor, 0.0);  // equal to h_factor: follows h
  const std::string longer = errorOf(std::string(kBase) + "method:\n  boundary_h_factor: 1.5\n");
  EXPECT_NE(longer.find("'method.boundary_h_factor': expected at most h_factor"), std::string::npos) << longer;
  const std::string past = errorOf(std::string(kBase) + "method:\n  h_factor: 2\n  boundary_h_factor: 1.2\n  b_off: 1.0\n");
  EXPECT_NE(past.find("'method.b_off'"), std::string::npos) << past;
  EXPECT_TRUE(errorOf(std::string(kBase) + "method:\n  h_factor: 2\n  b_off: 1.3\n").empty());
}

// The integrator: predictor-corrector by default, symplectic on request (written back,
// and the predictor's fraction is its own half step); a wrong name or a fraction other
// than 0.5 beside it names the key.
TEST(SceneLoader, Integrator) {
  EXPECT_EQ(io::loadSceneText(kBase, "s.yaml").method.integrator, fluid::Integrator::PredictorCorrector);
  const auto c = io::loadSceneText(std::string(kBase) + "method:\n  integrator: symplectic\n", "s.yaml");
  EXPECT_EQ(c.method.integrator, fluid::Integrator::Symplectic);
  EXPECT_EQ(c.method.name, "reference+options");
  EXPECT_EQ(io::loadSceneText(io::resolvedSceneYaml(c), "resolved.yaml").method.integrator, fluid::Integrator::Symplectic);
  const std::string typo = errorOf(std::string(kBase) + "method:\n  integrator: leapfrog\n");
  EXPECT_NE(typo.find("'method.integrator'"), std::string::npos) << typo;
  EXPECT_NE(typo.find("expected 'predictor_corrector' or 'symplectic', got 'leapfrog'"), std::string::npos) << typo;
  const std::string fraction = errorOf(std::string(kBase) + "method:\n  integrator: symplectic\n  predictor_fraction: 0.7\n");
  EXPECT_NE(fraction.find("'method.predictor_fraction'"), std::string::npos) << fraction;
  EXPECT_TRUE(errorOf(std::string(kBase) + "method:\n  integrator: symplectic\n  predictor_fraction: 0.5\n").empty());
}

// The wall law's form: reference by default, conservative on request, written back, and
// a misspelt form names the key and its line.
TEST(SceneLoader, WallLawForm) {
  EXPECT_EQ(io::loadSceneText(kBase, "s.yaml").method.boundary_force_form, fluid::BoundaryForceForm::Reference);
  const auto c = io::loadSceneText(std::string(kBase) + "method:\n  boundary_force: conservative\n", "s.yaml");
  EXPECT_EQ(c.method.boundary_force_form, fluid::BoundaryForceForm::Conservative);
  EXPECT_EQ(c.method.name, "reference+options");
  const auto again = io::loadSceneText(io::resolvedSceneYaml(c), "resolved.yaml");
  EXPECT_EQ(again.method.boundary_force_form, fluid::BoundaryForceForm::Conservative);
  const std::string bad = errorOf(std::string(kBase) + "method:\n  boundary_force: gradient\n");
  EXPECT_NE(bad.find("'method.boundary_force': expected 'reference' or 'conservative'"), std::string::npos) << bad;
}

// Velocity probes: read with their defaults, built into specs, written back; a bad
// fill threshold, a point of the wrong dimension or outside a given domain names the key.
TEST(SceneLoader, VelocityProbes) {
  const std::string probes = "velocity_probes:\n  - {name: V1, point: [0.05, 0.1]}\n  - {point: [0.2, 0.25], min_fill: 0.3}\n";
  const auto c = io::loadSceneText(std::string(kBase) + probes, "s.yaml");
  ASSERT_EQ(c.velocity_probes.size(), 2u);
  EXPECT_EQ(c.velocity_probes[1].name, "V2");
  EXPECT_DOUBLE_EQ(c.velocity_probes[0].min_fill, 0.5);
  EXPECT_DOUBLE_EQ(c.velocity_probes[1].min_fill, 0.3);
  const auto built = io::buildScene<2>(c);
  ASSERT_EQ(built.velocity_probes.size(), 2u);
  EXPECT_EQ(built.velocity_probe_names[0], "V1");
  EXPECT_DOUBLE_EQ(built.velocity_probes[0].point[1], 0.1);
  EXPECT_EQ(io::resolvedSceneYaml(io::loadSceneText(io::resolvedSceneYaml(c), "r.yaml")), io::resolvedSceneYaml(c));
  const std::string fill = errorOf(std::string(kBase) + "velocity_probes:\n  - {point: [0.05, 0.1], min_fill: 1}\n");
  EXPECT_NE(fill.find("'velocity_probes[0].min_fill'"), std::string::npos) << fill;
  EXPECT_NE(fill.find("s.yaml:11:"), std::string::npos) << fill;  // the line of the key
  EXPECT_NE(errorOf(std::string(kBase) + "velocity_probes:\n  - {point: [0.05, 0.1, 0]}\n").find("'velocity_probes[0].point'"),
            std::string::npos);
  const std::string outside = errorOf(std::string(kBase) + "domain: {lower: [-0.1, -0.1], upper: [0.5, 0.5]}\n" +
                                      "velocity_probes:\n  - {point: [0.05, 0.7]}\n");
  EXPECT_NE(outside.find("'velocity_probes[0].point': the point is outside the scene's domain"), std::string::npos)
      << outside;
}

// Packing probes: read with their defaults (spacing 0 = 0.618 dx at build), built into specs,
// written back; a box with upper below lower, a negative spacing or too many grid points
// names the key and its line.
TEST(SceneLoader, PackingProbes) {
  const std::string probes =
      "packing_probes:\n  - {name: bulk, lower: [0.02, 0.02], upper: [0.18, 0.1]}\n"
      "  - {lower: [0.0, 0.0], upper: [0.2, 0.2], spacing: 0.005, min_fill: 0.7}\n";
  const auto c = io::loadSceneText(std::string(kBase) + probes, "s.yaml");
  ASSERT_EQ(c.packing_probes.size(), 2u);
  EXPECT_EQ(c.packing_probes[1].name, "pack2");
  EXPECT_DOUBLE_EQ(c.packing_probes[0].spacing, 0.0);
  EXPECT_DOUBLE_EQ(c.packing_probes[1].min_fill, 0.7);
  EXPECT_DOUBLE_EQ(c.packing_probes[0].warn_rise, 0.005);
  const auto built = io::buildScene<2>(c);
  ASSERT_EQ(built.packing_probes.size(), 2u);
  EXPECT_EQ(built.packing_probe_names[0], "bulk");
  EXPECT_DOUBLE_EQ(built.packing_probes[0].spacing, 0.618 * c.dx);
  EXPECT_DOUBLE_EQ(built.packing_probes[1].upper[1], 0.2);
  EXPECT_DOUBLE_EQ(built.packing_warn_rises.at(0), 0.005);
  EXPECT_EQ(io::resolvedSceneYaml(io::loadSceneText(io::resolvedSceneYaml(c), "r.yaml")), io::resolvedSceneYaml(c));
  const std::string upside = errorOf(std::string(kBase) + "packing_probes:\n  - {lower: [0.1, 0.1], upper: [0.2, 0.05]}\n");
  EXPECT_NE(upside.find("'packing_probes[0].upper': each coordinate must exceed lower's"), std::string::npos) << upside;
  EXPECT_NE(upside.find("s.yaml:11:"), std::string::npos) << upside;
  const std::string spacing =
      errorOf(std::string(kBase) + "packing_probes:\n  - {lower: [0, 0], upper: [0.2, 0.2], spacing: -1}\n");
  EXPECT_NE(spacing.find("'packing_probes[0].spacing'"), std::string::npos) << spacing;
  const std::string many =
      errorOf(std::string(kBase) + "packing_probes:\n  - {lower: [0, 0], upper: [0.2, 0.2], spacing: 1e-5}\n");
  EXPECT_NE(many.find("more than 1e7 grid points"), std::string::npos) << many;
  const std::string rise =
      errorOf(std::string(kBase) + "packing_probes:\n  - {lower: [0, 0], upper: [0.2, 0.2], warn_rise: -0.01}\n");
  EXPECT_NE(rise.find("'packing_probes[0].warn_rise'"), std::string::npos) << rise;
}

// A water block fills whole spacings: one whose size is not a multiple of dx stops short
// of its upper face, and the built scene says where (check and run print it); a block of
// whole spacings gets no note. Here 0.2 m at dx = 0.015 m is 13.33 spacings: 13 layers,
// the surface at 0.195 m.
TEST(SceneLoader, WaterBlockOfPartSpacingsIsNoted) {
  const auto whole = io::buildScene<2>(io::loadSceneText(kBase, "s.yaml"));
  EXPECT_TRUE(whole.notes.empty());
  const auto part = io::buildScene<2>(io::loadSceneText(kBase, "s.yaml", {"resolution.dx=0.015"}));
  // Also 0.1 m along x is 6.67 spacings: 6 columns, a 10 mm gap before x = 0.1 m.
  ASSERT_EQ(part.notes.size(), 2u);
  EXPECT_NE(part.notes[0].find("water stops at x = 0.09 m"), std::string::npos) << part.notes[0];
  EXPECT_NE(part.notes[1].find("water stops at y = 0.195 m"), std::string::npos) << part.notes[1];
  double top = 0.0;
  for (const auto& r : part.scene.fluid.r) top = std::max(top, r[1] + 0.5 * 0.015);
  EXPECT_NEAR(top, 0.195, 1e-12);
}

// The METHOD.md 6.2c scenes (cases/buoy_in_waves): the periodic length holds the stated
// number of wavelengths of linear theory at d = 0.8 m (3, 1, 1) within 0.2%, the water
// fills it on whole spacings, the forcing ramps over two periods, and the buoy starts at
// its rest pose with the tether at the pretension.
TEST(SceneLoader, BuoyInWavesScenesMatchMethod62c) {
  const struct {
    int period;
    int wavelengths;
    double amplitude;
  } cases[] = {{1, 3, 0.058}, {2, 1, 0.04}, {3, 1, 0.071}};
  for (const auto& k : cases) {
    SCOPED_TRACE(k.period);
    const auto c = io::loadSceneFile(sourceDir() + "/cases/buoy_in_waves/buoy_waves_T" + std::to_string(k.period) + ".yaml");
    const double length = c.domain.upper[0] - c.domain.lower[0];
    const double lambda = fluid::waves::wavelengthFromPeriod(k.period, 0.8);
    EXPECT_NEAR(length / (k.wavelengths * lambda), 1.0, 2e-3) << "lambda " << lambda;
    EXPECT_TRUE(c.periodic[0]);
    EXPECT_NEAR(length / c.dx, std::round(length / c.dx), 1e-6);
    EXPECT_EQ(c.forcing.amplitude, k.amplitude);
    EXPECT_DOUBLE_EQ(c.forcing.ramp_up, 2.0 * k.period);
    EXPECT_EQ(c.moorings[0].pretension, 4.366);
    const auto built = io::buildScene<3>(c);
    EXPECT_GT(built.scene.fluid.size(), 0u);
  }
}

// A floor spanning the whole z period (0-0.72 m) keeps evenly spaced rows across the seam
// at any spacing: the row at 0.72 m, the periodic image of the row at 0, is dropped (the
// ship scenes rely on it to run at any dx).
TEST(SceneLoader, FaceSpanningThePeriodHasNoDoubleRowAtTheSeam) {
  const char* text = R"(dim: 3
name: periodic_floor
end_time: 0.1
resolution: {dx: 0.04}
effects: [pressure, gravity, walls]
domain: {lower: [0, -0.2, 0], upper: [0.8, 0.6, 0.72], periodic: [false, false, true]}
geometry:
  - box: {name: floor, lower: [0, -0.2, 0], upper: [0.8, 0, 0.72], open_faces: [-x, +x, -y, -z, +z]}
  - water: {lower: [0, 0, 0], upper: [0.8, 0.2, 0.72]}
)";
  for (double dx : {0.04, 0.03, 0.02}) {
    const auto built = io::buildScene<3>(io::loadSceneText(text, "s.yaml", {"resolution.dx=" + std::to_string(dx)}));
    const auto& r = built.scene.boundary.particles.r;
    const double step = 0.72 / std::ceil(0.72 / dx - 1e-9);
    // Nearest neighbour across the seam (minimum image in z) is one step away, not zero.
    double nearest = 1e9;
    for (std::size_t a = 0; a < r.size(); ++a)
      for (std::size_t b = a + 1; b < r.size(); ++b) {
        fluid::Vec<3> d = r[a] - r[b];
        d[2] -= 0.72 * std::round(d[2] / 0.72);
        nearest = std::min(nearest, d.norm());
      }
    EXPECT_NEAR(nearest, std::min(step, 0.8 / std::ceil(0.8 / dx - 1e-9)), 1e-9) << "dx " << dx;
    const long columns = std::lround(0.8 / (0.8 / std::ceil(0.8 / dx - 1e-9))) + 1;
    EXPECT_EQ(static_cast<long>(r.size()), columns * std::lround(0.72 / step)) << "dx " << dx;
  }
}

// A tank spanning a periodic axis has no faces normal to it (no wall across the seam):
// periodic in z, a tank with wall sides keeps its x faces and floor only; periodic in x
// and z with a mirror floor it has no particles at all and needs no 'walls'.
TEST(SceneLoader, TankSpanningThePeriodHasNoWallAtTheSeam) {
  const char* text = R"(dim: 3
end_time: 0.1
resolution: {dx: 0.04}
effects: [pressure, gravity, walls]
domain: {lower: [0, -0.2, 0], upper: [0.8, 0.6, 0.72], periodic: [false, false, true]}
geometry:
  - tank: {lower: [0, 0, 0], upper: [0.8, 0.4, 0.72]}
  - water: {lower: [0, 0, 0], upper: [0.8, 0.2, 0.72]}
)";
  const auto built = io::buildScene<3>(io::loadSceneText(text, "s.yaml"));
  const auto& r = built.scene.boundary.particles.r;
  ASSERT_GT(r.size(), 0u);
  for (const auto& p : r) {
    const bool on_floor = std::abs(p[1]) < 1e-9, on_end = std::abs(p[0]) < 1e-9 || std::abs(p[0] - 0.8) < 1e-9;
    EXPECT_TRUE(on_floor || on_end) << "a particle off the floor and the x faces at " << p.transpose();
  }
  std::string mirrored = text;
  mirrored.replace(mirrored.find("gravity, walls]"), 15, "gravity, mirror_floor]");
  mirrored.replace(mirrored.find("false, false, true]"), 19, "true, false, true]");
  mirrored.replace(mirrored.find("0.72]}\n  - water"), 6, "0.72], floor: mirror}");
  const auto open = io::buildScene<3>(io::loadSceneText(mirrored, "s.yaml"));
  EXPECT_EQ(open.scene.boundary.particles.size(), 0u);
  std::string idle = mirrored;
  idle.replace(idle.find("gravity, mirror_floor]"), 22, "gravity, walls, mirror_floor]");
  EXPECT_NE(errorOf(idle).find("leave 'walls' out"), std::string::npos) << errorOf(idle);
}
