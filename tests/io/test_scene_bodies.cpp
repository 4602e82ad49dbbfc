// Scene files with bodies and mooring lines: what loads, what is built (body surfaces
// as movable, reaction-tracking boundary surfaces; no water inside a body), and each
// class of error named with file:line:column and key.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <string>
#include <moorsph/io/body_geometry.hpp>
#include <moorsph/io/scene_builder.hpp>
#include <moorsph/io/scene_loader.hpp>

using namespace moorsph;

namespace {

// A 3D tank with a sphere tethered to the floor (the lab buoy, coarse).
const char* const kBuoy = R"(dim: 3
end_time: 0.1
resolution: {dx: 0.04}
geometry:
  - tank: {name: tank, lower: [0, 0, 0], upper: [0.8, 0.8, 0.8]}
  - water: {lower: [0, 0, 0], upper: [0.8, 0.5, 0.8]}
bodies:
  - name: buoy
    mass: 1.745
    centre_of_mass: [0, -0.027, 0]
    inertia: [1.735209e-3, 1.776363e-3, 1.735209e-3]
    position: [0.4, 0.5, 0.4]
    shape: {sphere: {radius: 0.1015}}
moorings:
  - name: tether
    model: tension_only_spring
    fairlead: {body: buoy, point: [0, -0.1015, 0]}
    anchor: {point: [0.4, 0.09, 0.4]}
    stiffness: 30.88
    pretension: 4.366
coupling: {release_time: 0.05, ramp_time: 0.02}
)";

// A 2D box body.
const char* const kBox = R"(dim: 2
end_time: 0.1
resolution: {dx: 0.01}
fluid: {sound_speed: 20}
geometry:
  - tank: {name: tank, lower: [0, 0], upper: [0.8, 0.4]}
  - water: {lower: [0, 0], upper: [0.8, 0.2]}
bodies:
  - name: box
    mass: 10
    inertia: 0.0416667
    position: [0.4, 0.2]
    shape:
      box: {size: [0.2, 0.1]}
)";

std::string errorOf(const std::string& text, const std::vector<std::string>& sets = {}) {
  try {
    io::loadSceneText(text, "s.yaml", sets);
  } catch (const io::SceneError& e) {
    return e.what();
  }
  return "";
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

TEST(SceneBodies, BuoyLoadsWithItsLineAndCoupling) {
  const io::SceneConfig c = io::loadSceneText(kBuoy, "s.yaml");
  ASSERT_EQ(c.bodies.size(), 1u);
  ASSERT_EQ(c.moorings.size(), 1u);
  EXPECT_TRUE(c.hasEffect("bodies"));  // added to the default effect list
  EXPECT_EQ(c.bodies[0].mass, 1.745);
  EXPECT_EQ(c.bodies[0].centre_of_mass[1], -0.027);
  EXPECT_EQ(c.bodies[0].inertia[1][1], 1.776363e-3);
  EXPECT_EQ(c.bodies[0].inertia[0][1], 0.0);
  EXPECT_EQ(c.moorings[0].model, "tension_only_spring");
  EXPECT_EQ(c.moorings[0].fairlead.body, "buoy");
  EXPECT_TRUE(c.moorings[0].anchor.body.empty());
  EXPECT_EQ(c.moorings[0].stiffness, 30.88);
  EXPECT_TRUE(std::isnan(c.moorings[0].rest_length));
  EXPECT_EQ(c.coupling.release_time, 0.05);
  // The resolved scene reloads to the same bodies (restarts compare resolved scenes).
  const io::SceneConfig again = io::loadSceneText(io::resolvedSceneYaml(c), "resolved.yaml");
  EXPECT_EQ(again.bodies[0].inertia, c.bodies[0].inertia);
  EXPECT_EQ(again.moorings[0].pretension, 4.366);
  EXPECT_EQ(again.coupling.ramp_time, 0.02);
}

TEST(SceneBodies, BodySurfaceIsMovableAndWaterStaysOutside) {
  const io::SceneConfig c = io::loadSceneText(kBuoy, "s.yaml");
  const auto built = io::buildScene<3>(c);
  ASSERT_EQ(built.body_surfaces.size(), 1u);
  const auto& info = built.scene.boundary.surfaces[built.body_surfaces[0]];
  EXPECT_EQ(info.name, "buoy");
  EXPECT_TRUE(info.movable);
  EXPECT_TRUE(info.track_reaction);
  EXPECT_EQ(info.reference_point, Eigen::Vector3d(0.4, 0.5, 0.4));
  // Every surface particle lies on the sphere, with its normal pointing out.
  std::size_t n = 0;
  const auto& b = built.scene.boundary.particles;
  for (std::size_t k = 0; k < b.size(); ++k) {
    if (b.surface[k] != built.body_surfaces[0]) continue;
    ++n;
    const Eigen::Vector3d arm = b.r[k] - Eigen::Vector3d(0.4, 0.5, 0.4);
    EXPECT_NEAR(arm.norm(), 0.1015, 1e-12);
    EXPECT_GT(b.normals[b.normal_begin[k]].dot(arm), 0.99 * arm.norm());
  }
  // About one particle per spacing^2 of surface (Fibonacci lattice: ceil(4 pi R^2 / s^2)).
  EXPECT_EQ(n, static_cast<std::size_t>(std::ceil(4.0 * M_PI * 0.1015 * 0.1015 / (0.04 * 0.04))));
  for (const auto& r : built.scene.fluid.r) EXPECT_GE((r - Eigen::Vector3d(0.4, 0.5, 0.4)).norm(), 0.1015 + 0.45 * 0.04);
}

// `sampling: rings` puts a 3D sphere's particles on mirror-symmetric latitude rings. In
// a pressure field that depends on height only, p = rho g (y0 - y), the sideways force
// sum_k p_k n_k dA over a closed surface must vanish (Archimedes: buoyancy is vertical).
// The rings give it to round-off; the Fibonacci lattice leaves a sideways part of
// 1e-4 to 2e-3 of the buoyancy (tests/fluid/test_shape_sampling.cpp), which moved a
// tethered buoy centimetres sideways (docs/validation/tethered-buoy.md).
TEST(SceneBodies, SphereRingsSamplingHasNoSidewaysHydrostaticForce) {
  auto sideways = [](const std::vector<std::string>& sets) {
    const io::SceneConfig c = io::loadSceneText(kBuoy, "s.yaml", sets);
    const auto built = io::buildScene<3>(c);
    const auto& b = built.scene.boundary.particles;
    Eigen::Vector3d force = Eigen::Vector3d::Zero();
    double count = 0.0;
    for (std::size_t k = 0; k < b.size(); ++k) {
      if (b.surface[k] != built.body_surfaces[0]) continue;
      force += (0.8 - b.r[k][1]) * b.normals[b.normal_begin[k]];  // p / (rho g) n, unit area each
      count += 1.0;
    }
    const double buoyancy = 4.0 * M_PI * 0.1015 * 0.1015 * 0.1015 / 3.0 * count / (4.0 * M_PI * 0.1015 * 0.1015);
    return std::hypot(force[0], force[2]) / buoyancy;
  };
  EXPECT_LT(sideways({"bodies.0.shape.sphere.sampling=rings"}), 1e-12);
  EXPECT_GT(sideways({}), 1e-5);  // the default Fibonacci lattice: the part rings remove
  const io::SceneConfig c = io::loadSceneText(kBuoy, "s.yaml", {"bodies.0.shape.sphere.sampling=rings"});
  EXPECT_EQ(io::loadSceneText(io::resolvedSceneYaml(c), "resolved.yaml").bodies[0].shape.sampling, "rings");
  const std::string bad = errorOf(kBuoy, {"bodies.0.shape.sphere.sampling=ring"});
  EXPECT_TRUE(has(bad, "'bodies[0].shape.sphere.sampling': expected fibonacci or rings, got 'ring'")) << bad;
}

TEST(SceneBodies, RotatedBoxKeepsWaterOutOfItsRotatedVolume) {
  io::SceneConfig c = io::loadSceneText(kBox, "s.yaml", {"bodies.0.orientation_deg=30"});
  const double a = M_PI / 6;
  EXPECT_NEAR(c.bodies[0].orientation[1], a, 1e-15);
  const auto built = io::buildScene<2>(c);
  for (const auto& r : built.scene.fluid.r) {
    const Eigen::Vector2d d = r - Eigen::Vector2d(0.4, 0.2);
    const double u = std::cos(a) * d.x() + std::sin(a) * d.y(), v = -std::sin(a) * d.x() + std::cos(a) * d.y();
    EXPECT_FALSE(std::abs(u) < 0.1 && std::abs(v) < 0.05) << "water inside the box at " << r.transpose();
  }
  EXPECT_TRUE(io::insideBody<2>(c.bodies[0], Eigen::Vector2d(0.4 + 0.09 * std::cos(a), 0.2 + 0.09 * std::sin(a)), 0.0));
  EXPECT_FALSE(io::insideBody<2>(c.bodies[0], Eigen::Vector2d(0.49, 0.16), 0.0));  // inside unrotated, outside rotated
}

TEST(SceneBodies, UnknownKeysAndWrongTypesAreNamed) {
  std::string typo = kBox;
  typo.replace(typo.find("    inertia"), 4, "    ");
  typo.replace(typo.find("inertia:"), 8, "inertya:");
  const std::string t = errorOf(typo);
  EXPECT_TRUE(has(t, "s.yaml:9:5:") && has(t, "'bodies[0].inertia': required key is missing")) << t;
  std::string extra = kBox;
  extra.replace(extra.find("    position"), 4, "    inertya: 1\n    ");
  const std::string x = errorOf(extra);
  EXPECT_TRUE(has(x, "s.yaml:12:5: 'bodies[0].inertya': unknown key (did you mean 'inertia'?)")) << x;
  const std::string shape = errorOf(std::string(kBox).replace(std::string(kBox).find("box: {size"), 3, "cube"));
  EXPECT_TRUE(has(shape, "'bodies[0].shape.cube': unknown key (did you mean 'cube'") || has(shape, "'bodies[0].shape.cube'")) << shape;
  const std::string mass = errorOf(kBox, {"bodies.0.mass=heavy"});
  EXPECT_TRUE(has(mass, "--set bodies.0.mass: 'bodies[0].mass'") && has(mass, "expected a number")) << mass;
  const std::string model = errorOf(kBuoy, {"moorings.0.model=tension_only_sprng"});
  EXPECT_TRUE(has(model, "unknown mooring model 'tension_only_sprng' (did you mean 'tension_only_spring'?)")) << model;
  const std::string line_key = errorOf(std::string(kBuoy) + "");
  EXPECT_EQ(line_key, "");
  std::string bad_line = kBuoy;
  bad_line.replace(bad_line.find("    stiffness: 30.88"), 20, "    stifness: 30.88");
  const std::string l = errorOf(bad_line);
  EXPECT_TRUE(has(l, "s.yaml:") && has(l, "stiffness")) << l;
}

TEST(SceneBodies, MissingRequiredKeysAreNamed) {
  std::string no_mass = kBox;
  no_mass.replace(no_mass.find("    mass: 10\n"), 13, "");
  EXPECT_TRUE(has(errorOf(no_mass), "'bodies[0].mass': required key is missing")) << errorOf(no_mass);
  std::string no_shape = kBox;
  no_shape.erase(no_shape.find("    shape:"));
  EXPECT_TRUE(has(errorOf(no_shape), "'bodies[0].shape': required key is missing")) << errorOf(no_shape);
  std::string no_rest = kBuoy;
  no_rest.replace(no_rest.find("    pretension: 4.366\n"), 22, "");
  const std::string r = errorOf(no_rest);
  EXPECT_TRUE(has(r, "'moorings[0].rest_length': required key is missing for model tension_only_spring")) << r;
  const std::string cat = errorOf(kBuoy, {"moorings.0.model=elastic_catenary"});
  EXPECT_TRUE(has(cat, "'moorings[0].length': required key is missing for model elastic_catenary")) << cat;
  const std::string both = errorOf(kBuoy, {"moorings.0.rest_length=0.4"});
  EXPECT_TRUE(has(both, "give rest_length or pretension, not both")) << both;
}

TEST(SceneBodies, OutOfRangeValuesAreRejected) {
  const std::string negative = errorOf(kBox, {"bodies.0.mass=-1"});
  EXPECT_TRUE(has(negative, "'bodies[0].mass'") && has(negative, "expected a mass > 0")) << negative;
  const std::string small = errorOf(kBuoy, {"bodies.0.shape.sphere.radius=0.02"});
  EXPECT_TRUE(has(small, "finer than the resolution allows (at least 0.04 m at dx = 0.04 m)")) << small;
  const std::string small_box = errorOf(kBox, {"bodies.0.shape.box.size=[0.2, 0.015]"});
  EXPECT_TRUE(has(small_box, "edge along y is 0.015 m")) << small_box;
  const std::string not_pd = errorOf(kBuoy, {"bodies.0.inertia=[1e-3, -1e-3, 1e-3]"});
  EXPECT_TRUE(has(not_pd, "'bodies[0].inertia': the inertia tensor is not positive definite")) << not_pd;
  const std::string triangle = errorOf(kBuoy, {"bodies.0.inertia=[1e-3, 1e-3, 5e-3]"});
  EXPECT_TRUE(has(triangle, "I1 + I2 >= I3")) << triangle;
  const std::string inertia2d = errorOf(kBox, {"bodies.0.inertia=0"});
  EXPECT_TRUE(has(inertia2d, "'bodies[0].inertia': expected a number > 0")) << inertia2d;
  const std::string same = errorOf(kBuoy, {"moorings.0.anchor.point=[0.4, 0.3985, 0.4]"});
  EXPECT_TRUE(has(same, "'moorings[0].anchor': the anchor coincides with the fairlead")) << same;
  const std::string own = errorOf(kBuoy, {"moorings.0.anchor.body=buoy"});
  EXPECT_TRUE(has(own, "the anchor is on the fairlead's own body")) << own;
  const std::string unknown_body = errorOf(kBuoy, {"moorings.0.fairlead.body=boy"});
  EXPECT_TRUE(has(unknown_body, "no body is named 'boy' (did you mean 'buoy'?)")) << unknown_body;
  const std::string pre = errorOf(kBuoy, {"moorings.0.pretension=100"});
  EXPECT_TRUE(has(pre, "the rest length would be <= 0")) << pre;
  const std::string outside = errorOf(kBuoy, {"bodies.0.position=[2, 0.5, 0.4]"});
  EXPECT_TRUE(has(outside, "outside every tank")) << outside;
  const std::string dof = errorOf(kBox, {"bodies.0.fixed=[z]"});
  EXPECT_TRUE(has(dof, "unknown degree of freedom 'z'; expected among x, y, rz")) << dof;
  const std::string mesh2d = errorOf(kBox, {"bodies.0.shape={mesh: {file: a.stl}}"});
  EXPECT_TRUE(has(mesh2d, "a mesh body is 3D only")) << mesh2d;
}

TEST(SceneBodies, EffectListMustAgreeWithTheBodies) {
  const std::string missing = errorOf(std::string(kBox) + "effects: [pressure, gravity, walls]\n");
  EXPECT_TRUE(has(missing, "the scene has bodies but 'bodies' is not in its effects")) << missing;
  const std::string no_walls = errorOf(std::string(kBox) + "effects: [pressure, gravity, bodies]\n");
  EXPECT_TRUE(has(no_walls, "'walls' is not in its effects")) << no_walls;
  std::string no_bodies = kBox;
  no_bodies.erase(no_bodies.find("bodies:"));
  const std::string extra = errorOf(no_bodies + "effects: [pressure, gravity, walls, bodies]\n");
  EXPECT_TRUE(has(extra, "'bodies' is listed but the scene has no 'bodies' list")) << extra;
  const std::string lines_alone = errorOf(no_bodies + "moorings: []\n");
  EXPECT_TRUE(has(lines_alone, "mooring lines need bodies")) << lines_alone;
  EXPECT_TRUE(has(errorOf(std::string(kBox) + "cables: []\n"), "listed under 'moorings'"));
}

TEST(SceneBodies, ExampleScenesLoad) {
  const char* dir = std::getenv("MOORSPH_SOURCE_DIR");
  const std::string source = dir ? dir : ".";
  for (const char* name : {"floating_box_2d", "tethered_buoy_3d", "moored_buoy_catenary_3d"}) {
    SCOPED_TRACE(name);
    const io::SceneConfig c = io::loadSceneFile(source + "/cases/" + name + ".yaml");
    EXPECT_FALSE(c.bodies.empty());
  }
}

TEST(SceneBodies, MeshAndCylinderBodiesAreSampledInTheirBodyFrame) {
  // The OBJ cylinder (R 0.05 m, y from 0 to 0.15 m) translated so its centre is the
  // reference point; and the same cylinder as a primitive along y.
  const char* dir = std::getenv("MOORSPH_SOURCE_DIR");
  const std::string scene = std::string(dir ? dir : ".") + "/cases/body_test.yaml";  // meshes/ resolves beside it
  std::string text = kBuoy;
  text.replace(text.find("{sphere: {radius: 0.1015}}"), 26,
               "{mesh: {file: meshes/cylinder.obj, translate: [0, -0.075, 0]}}");
  text.replace(text.find("dx: 0.04"), 8, "dx: 0.02");
  const io::SceneConfig mesh = io::loadSceneText(text, scene);
  EXPECT_EQ(mesh.bodies[0].shape.kind, "mesh");
  const auto built = io::buildScene<3>(mesh);
  const Eigen::Vector3d centre(0.4, 0.5, 0.4);
  const auto& b = built.scene.boundary.particles;
  std::size_t n = 0;
  for (std::size_t k = 0; k < b.size(); ++k) {
    if (b.surface[k] != built.body_surfaces[0]) continue;
    ++n;
    const Eigen::Vector3d d = b.r[k] - centre;
    EXPECT_LE(std::hypot(d.x(), d.z()), 0.05 + 1e-9);
    EXPECT_LE(std::abs(d.y()), 0.075 + 1e-9);
  }
  // About one particle per spacing^2 of the surface (2 pi R L + 2 pi R^2 = 0.0628 m^2 -> ~157).
  EXPECT_GT(n, 120u);
  EXPECT_LT(n, 260u);
  for (const auto& r : built.scene.fluid.r) {
    const Eigen::Vector3d d = r - centre;
    EXPECT_FALSE(std::hypot(d.x(), d.z()) < 0.05 && std::abs(d.y()) < 0.075) << "water inside the body at " << r.transpose();
  }
  text.replace(text.find("{mesh: {file: meshes/cylinder.obj, translate: [0, -0.075, 0]}}"), 62,
               "{cylinder: {radius: 0.05, length: 0.15, axis: y}}");
  const io::SceneConfig prim = io::loadSceneText(text, scene);
  const auto again = io::buildScene<3>(prim);
  for (const auto& r : again.scene.fluid.r) {
    const Eigen::Vector3d d = r - centre;
    EXPECT_FALSE(std::hypot(d.x(), d.z()) < 0.05 && std::abs(d.y()) < 0.075) << "water inside the body at " << r.transpose();
  }
}

// 3D green water reads its deck outline from a CSV (x, y, z rows: y ignored) next to the
// scene; a missing file or a bad row is refused naming the key; points need D numbers.
TEST(SceneBodies, DeckOutlineFileAndPoints) {
  const std::string dir = testing::TempDir();
  std::ofstream(dir + "/deck.csv") << "x,y,z\n-0.1,0.1,-0.1\n0.1,0.1,-0.1\n0.1,0.1,0.1\n-0.1,0.1,0.1\n";
  std::string text = kBuoy;
  text.replace(text.find("    shape: {sphere"), 0,
               "    points: {top: [0, 0.1015, 0]}\n    green_water: {deck_height: 0.05, outline_file: " + dir +
                   "/deck.csv}\n");
  const auto c = io::loadSceneText(text, "s.yaml");
  ASSERT_EQ(c.bodies[0].deck_outline.size(), 4u);
  EXPECT_EQ(c.bodies[0].deck_outline[2][0], 0.1);
  EXPECT_EQ(c.bodies[0].deck_outline[2][1], 0.1);
  EXPECT_EQ(c.bodies[0].points[0].second[1], 0.1015);
  std::string missing = text;
  missing.replace(missing.find("/deck.csv"), 9, "/none.csv");
  EXPECT_TRUE(has(errorOf(missing), "'bodies[0].green_water.outline_file': cannot open the deck outline")) << errorOf(missing);
  std::string flat = text;
  flat.replace(flat.find("top: [0, 0.1015, 0]"), 19, "top: [0, 0.1015]");
  EXPECT_TRUE(has(errorOf(flat), "'bodies[0].points.top'")) << errorOf(flat);
}
