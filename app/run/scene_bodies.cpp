#include "scene_bodies.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <moorsph/bodies/mooring_factory.hpp>
#include <moorsph/coupling/green_water.hpp>
#include <moorsph/io/body_geometry.hpp>

namespace moorsph::app {
namespace {

Eigen::Vector3d toEigen(const io::Triple& t) { return Eigen::Vector3d(t[0], t[1], t[2]); }

int bodyIndex(const io::SceneConfig& c, const std::string& name) {
  return name.empty() ? bodies::LineAttachment::kGround : c.bodyIndex(name);
}

/// Ground position of a line end with every body at its rest pose (`position`, no offset).
Eigen::Vector3d restPoint(const io::SceneConfig& c, const io::LineEndConfig& e) {
  if (e.body.empty()) return toEigen(e.point);
  const io::BodyConfig& b = c.bodies[c.bodyIndex(e.body)];
  return toEigen(b.position) + io::bodyRotation(b) * toEigen(e.point);
}

bodies::RigidBodySpec bodySpec(const io::SceneConfig& c, const io::BodyConfig& b) {
  bodies::RigidBodySpec s;
  s.name = b.name;
  s.mass = b.mass;
  s.centreOfMass = toEigen(b.centre_of_mass);
  for (int r = 0; r < 3; ++r)
    for (int k = 0; k < 3; ++k) s.inertiaAboutCom(r, k) = b.inertia[r][k];
  s.mobilizer = c.dim == 2 ? bodies::Mobilizer::Planar : bodies::Mobilizer::Free;
  s.fixedDofs = b.fixed;
  s.initial.position = toEigen(b.start());
  s.initial.orientation = Eigen::Quaterniond(io::bodyRotation(b));
  s.initial.velocity = toEigen(b.velocity);
  return s;
}

bodies::MooringLineParams lineParams(const io::SceneConfig& c, const io::MooringConfig& l) {
  bodies::MooringLineParams p;
  p.model = l.model;
  p.stiffness = l.stiffness;
  p.restLength = l.rest_length;
  p.pretension = l.pretension;
  p.damping = l.damping;
  p.dissipation = l.dissipation;
  for (const auto& v : l.via_points) p.viaPoints.push_back({bodyIndex(c, v.body), toEigen(v.point)});
  p.length = l.length;
  p.axialStiffness = l.axial_stiffness;
  p.bendingStiffness = l.bending_stiffness;
  p.massPerLength = l.mass_per_length;
  p.diameter = l.diameter;
  p.waterDensity = c.rho0;
  double level = -1e300;  // still level: the highest water top
  for (const auto& w : c.water) level = std::max(level, w.box.upper[1]);
  p.waterSurfaceHeight = level;
  p.gravity = toEigen(c.gravity);
  p.seabedFriction = l.seabed_friction;
  p.anchorOnSeabed = l.anchor_on_seabed;
  p.segments = l.segments;
  p.internalDampingRatio = l.internal_damping_ratio;
  p.cdNormal = l.cd_normal;
  p.cdAxial = l.cd_axial;
  p.caNormal = l.ca_normal;
  p.caAxial = l.ca_axial;
  p.timeStep = l.time_step;
  p.relaxationTime = l.relaxation_time;
  p.breakingLoad = l.breaking_load;
  // A pretension is meant at the rest pose. A straight spring's rest length follows
  // from it there, L0 = |fairlead - anchor| - T / k, so a body started away from rest
  // (an `offset`: a release test) keeps the line the rest pose asks for.
  if (l.model == "tension_only_spring" && !std::isnan(l.pretension)) {
    const double k = !std::isnan(l.stiffness) ? l.stiffness : l.axial_stiffness / l.length;
    p.restLength = (restPoint(c, l.fairlead) - restPoint(c, l.anchor)).norm() - l.pretension / k;
    p.pretension = std::numeric_limits<double>::quiet_NaN();
  }
  return p;
}

}  // namespace

// Eigen's eulerAngles puts its first angle in [0, pi] and flips the others by pi near
// zero: unreadable in a plot of small motions. These are continuous through zero.
Eigen::Vector3d rollPitchYaw(const Eigen::Quaterniond& q) {
  const Eigen::Matrix3d R = q.normalized().toRotationMatrix();
  // R = Ry(yaw) Rz(pitch) Rx(roll): R10 = sin(pitch), R11 / R12 and R00 / R20 give roll and yaw.
  return Eigen::Vector3d(std::atan2(-R(1, 2), R(1, 1)), std::asin(std::clamp(R(1, 0), -1.0, 1.0)),
                         std::atan2(-R(2, 0), R(0, 0)));
}

std::unique_ptr<bodies::MultibodySystem> buildSceneBodies(const io::SceneConfig& c) {
  bodies::SystemOptions options;
  options.gravity = toEigen(c.gravity);
  options.maxStep = c.coupling.max_step;
  auto system = std::make_unique<bodies::MultibodySystem>(options);
  for (const auto& b : c.bodies) system->addBody(bodySpec(c, b));
  for (const auto& l : c.moorings) {
    bodies::LineAttachment where;
    where.fairleadBody = bodyIndex(c, l.fairlead.body);
    where.fairleadPoint = toEigen(l.fairlead.point);
    where.anchorBody = bodyIndex(c, l.anchor.body);
    where.anchorPoint = toEigen(l.anchor.point);
    try {
      system->addLine(l.name, where, bodies::makeMooringLine(lineParams(c, l)));
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(l.where.text + ": mooring line '" + l.name + "': " + e.what());
    }
  }
  system->initialize();
  return system;
}

template <int D>
std::unique_ptr<coupling::CoSimulation<D>> makeCoSimulation(const io::SceneConfig& c, const io::BuiltScene<D>& built,
                                                             const fluid::FluidParticles<D>& particles,
                                                             const std::vector<double>& restore) {
  auto fluid = std::make_unique<fluid::FluidSimulation<D>>(built.scene.setup, particles, built.scene.boundary);
  io::addSceneEffects(*fluid, c, built);
  auto system = buildSceneBodies(c);
  if (!restore.empty()) system->restore(unpackSnapshot(restore));
  std::vector<coupling::CoupledBody> links;
  for (std::size_t k = 0; k < built.body_surfaces.size(); ++k) links.push_back({static_cast<int>(k), built.body_surfaces[k]});
  coupling::CouplingOptions options{c.coupling.release_time, c.coupling.ramp_time};
  return std::make_unique<coupling::CoSimulation<D>>(std::move(fluid), std::move(system), std::move(links), options);
}

// ---- checkpoint packing: a version number (2), then the snapshot's fields in order ----

std::vector<double> packSnapshot(const bodies::SystemSnapshot& s) {
  std::vector<double> out{2.0, s.time, static_cast<double>(s.bodies.size())};
  auto put = [&](const Eigen::Vector3d& v) { out.insert(out.end(), {v.x(), v.y(), v.z()}); };
  for (const auto& k : s.bodies) {
    put(k.position);
    out.insert(out.end(), {k.orientation.w(), k.orientation.x(), k.orientation.y(), k.orientation.z()});
    put(k.velocity);
    put(k.angularVelocity);
    put(k.acceleration);
    put(k.angularAcceleration);
  }
  out.push_back(static_cast<double>(s.wrenches.size()));
  for (const auto& w : s.wrenches) {
    put(w.force);
    put(w.torque);
  }
  out.push_back(static_cast<double>(s.lines.size()));
  for (const auto& l : s.lines) {
    out.insert(out.end(), {l.broken ? 1.0 : 0.0, l.breakTime, l.breakTension, l.cableDissipated,
                           static_cast<double>(l.internalState.size())});
    out.insert(out.end(), l.internalState.begin(), l.internalState.end());
  }
  out.insert(out.end(), {s.dissipated, s.externalWork});
  return out;
}

bodies::SystemSnapshot unpackSnapshot(const std::vector<double>& in) {
  std::size_t at = 0;
  auto next = [&]() {
    if (at >= in.size()) throw std::runtime_error("checkpoint: the bodies' state is truncated");
    return in[at++];
  };
  auto vec = [&]() {
    Eigen::Vector3d v;
    for (int k = 0; k < 3; ++k) v[k] = next();
    return v;
  };
  // Version 1 lacked the break tension.
  const double version = next();
  if (version != 1.0 && version != 2.0) throw std::runtime_error("checkpoint: unknown version of the bodies' state");
  bodies::SystemSnapshot s;
  s.time = next();
  s.bodies.resize(static_cast<std::size_t>(next()));
  for (auto& k : s.bodies) {
    k.position = vec();
    const double w = next(), x = next(), y = next(), z = next();
    k.orientation = Eigen::Quaterniond(w, x, y, z);
    k.velocity = vec();
    k.angularVelocity = vec();
    k.acceleration = vec();
    k.angularAcceleration = vec();
  }
  s.wrenches.resize(static_cast<std::size_t>(next()));
  for (auto& w : s.wrenches) {
    w.force = vec();
    w.torque = vec();
  }
  s.lines.resize(static_cast<std::size_t>(next()));
  for (auto& l : s.lines) {
    l.broken = next() != 0.0;
    l.breakTime = next();
    if (version >= 2.0) l.breakTension = next();
    l.cableDissipated = next();
    l.internalState.resize(static_cast<std::size_t>(next()));
    for (auto& v : l.internalState) v = next();
  }
  s.dissipated = next();
  s.externalWork = next();
  return s;
}

// ---- series ----

/// points_<body>: ground positions of the centre of mass and of the scene's named
/// body-frame points (bow and stern heights, CoM surge/heave/sway).
template <int D>
void attachPointSeries(cases::RunRecorder<D>& recorder, const coupling::CoSimulation<D>& co, const io::BodyConfig& b,
                       int body) {
  std::vector<std::pair<std::string, Eigen::Vector3d>> points{
      {"com", Eigen::Vector3d(b.centre_of_mass[0], b.centre_of_mass[1], b.centre_of_mass[2])}};
  for (const auto& [name, p] : b.points) points.emplace_back(name, Eigen::Vector3d(p[0], p[1], p[2]));
  std::vector<io::SeriesColumn> columns;
  for (const auto& [name, p] : points)
    for (int k = 0; k < D; ++k) columns.push_back({name + "_" + "xyz"[k], "m"});
  recorder.addSeries("points_" + b.name, columns, [&co, body, points](const fluid::FluidSimulation<D>&) {
    const bodies::BodyKinematics k = co.bodies().kinematics(body);
    std::vector<double> v;
    for (const auto& [name, p] : points) {
      const Eigen::Vector3d g = k.pointToGround(p);
      for (int a = 0; a < D; ++a) v.push_back(g[a]);
    }
    return v;
  }, "ground positions of the body's centre of mass (com) and named points (bodies[].points)");
}

/// green_water_<body>: fluid volume above the deck inside its outline.
template <int D>
void attachGreenWaterSeries(cases::RunRecorder<D>& recorder, const coupling::CoSimulation<D>& co,
                            const io::BodyConfig& b, int body) {
  coupling::DeckOutline deck;
  deck.deck_height = b.deck_height;
  for (const auto& p : b.deck_outline) deck.outline.emplace_back(p[0], p[1]);
  recorder.addSeries("green_water_" + b.name, {{"volume", D == 2 ? "m^2/m" : "m^3"}},
                     [&co, body, deck](const fluid::FluidSimulation<D>& s) {
                       return std::vector<double>{coupling::greenWaterVolume<D>(s.fluid(), co.bodies().kinematics(body), deck)};
                     },
                     "green water: fluid volume above the deck (body-frame y > deck_height) inside the deck outline");
}

template <int D>
void attachBodySeries(cases::RunRecorder<D>& recorder, const coupling::CoSimulation<D>& co, const io::SceneConfig& c) {
  const std::string per_span = D == 2 ? "/m" : "";
  for (std::size_t k = 0; k < c.bodies.size(); ++k) {
    const std::string& name = c.bodies[k].name;
    const int body = static_cast<int>(k);
    std::vector<io::SeriesColumn> pose{{"x", "m"}, {"y", "m"}};
    if (D == 3) pose.insert(pose.end(), {{"z", "m"}, {"roll", "rad"}, {"pitch", "rad"}, {"yaw", "rad"}, {"qw", "1"},
                                         {"qx", "1"}, {"qy", "1"}, {"qz", "1"}});
    else pose.push_back({"angle", "rad"});
    recorder.addSeries("body_" + name, pose, [&co, body](const fluid::FluidSimulation<D>&) {
      const bodies::BodyKinematics k = co.bodies().kinematics(body);
      std::vector<double> v{k.position.x(), k.position.y()};
      if (D == 3) {
        const Eigen::Vector3d rpy = rollPitchYaw(k.orientation);
        v.insert(v.end(), {k.position.z(), rpy[0], rpy[1], rpy[2], k.orientation.w(), k.orientation.x(),
                           k.orientation.y(), k.orientation.z()});
      }
      else v.push_back(2.0 * std::atan2(k.orientation.z(), k.orientation.w()));
      return v;
    }, "body reference point position and orientation (roll, pitch, yaw: R = Ry(yaw) Rz(pitch) Rx(roll), y up; quaternion body -> ground)");
    std::vector<io::SeriesColumn> speed{{"vx", "m/s"}, {"vy", "m/s"}};
    if (D == 3) speed.insert(speed.end(), {{"vz", "m/s"}, {"wx", "rad/s"}, {"wy", "rad/s"}});
    speed.push_back({"wz", "rad/s"});
    recorder.addSeries("velocity_" + name, speed, [&co, body](const fluid::FluidSimulation<D>&) {
      const bodies::BodyKinematics k = co.bodies().kinematics(body);
      std::vector<double> v{k.velocity.x(), k.velocity.y()};
      if (D == 3) v.insert(v.end(), {k.velocity.z(), k.angularVelocity.x(), k.angularVelocity.y()});
      v.push_back(k.angularVelocity.z());
      return v;
    }, "velocity of the body reference point and angular velocity (ground frame)");
    std::vector<io::SeriesColumn> load{{"Fx", "N" + per_span}, {"Fy", "N" + per_span}};
    if (D == 3) load.insert(load.end(), {{"Fz", "N"}, {"Mx", "N m"}, {"My", "N m"}});
    load.push_back({"Mz", "N m" + per_span});
    recorder.addSeries("wrench_" + name, load, [&co, k](const fluid::FluidSimulation<D>& sim) {
      // While held, the load the hold restrains (the held body's buoyancy as the water settles).
      const bool held = sim.time() <= co.coupling().options().release_time;
      const bodies::BodyWrench& w = held ? co.coupling().fluidWrench(k) : co.coupling().appliedWrench(k);
      std::vector<double> v{w.force.x(), w.force.y()};
      if (D == 3) v.insert(v.end(), {w.force.z(), w.torque.x(), w.torque.y()});
      v.push_back(w.torque.z());
      return v;
    }, "fluid wrench applied to the body (ground frame, moment about the reference point; ramped as coupling.ramp_time says, wall contact included); while the body is held, the fluid's wrench on it that the hold restrains");
    attachPointSeries(recorder, co, c.bodies[k], body);
    if (c.bodies[k].green_water) attachGreenWaterSeries(recorder, co, c.bodies[k], body);
  }
  for (std::size_t k = 0; k < c.moorings.size(); ++k) {
    const int line = static_cast<int>(k);
    recorder.addSeries("line_" + c.moorings[k].name,
                       {{"fairlead_tension", "N"}, {"anchor_tension", "N"}, {"slack", "1"}, {"broken", "1"}},
                       [&co, line](const fluid::FluidSimulation<D>&) {
                         const bodies::LineDiagnostics d = co.bodies().lineDiagnostics(line);
                         return std::vector<double>{d.fairleadTension, d.anchorTension, d.slack ? 1.0 : 0.0, d.broken ? 1.0 : 0.0};
                       },
                       "mooring line " + c.moorings[k].model + ": tension at both ends, slack (1) and broken (1) flags");
  }
  const std::string J = D == 2 ? "J/m" : "J";
  recorder.addSeries("ledger",
                     {{"fluid_kinetic", J}, {"fluid_potential", J}, {"fluid_elastic", J}, {"fluid_outflow", J},
                      {"body_kinetic", J}, {"body_potential", J}, {"line_elastic", J}, {"line_dissipated", J},
                      {"work_by_fluid_on_bodies", J}, {"total", J}},
                     [&co](const fluid::FluidSimulation<D>&) {
                       const coupling::EnergyLedger e = co.calcEnergy();
                       return std::vector<double>{e.fluid_kinetic, e.fluid_potential, e.fluid_elastic, e.fluid_outflow,
                                                  e.body_kinetic, e.body_potential, e.line_elastic, e.line_dissipated,
                                                  e.work_by_fluid_on_bodies, e.total()};
                     },
                     "energy ledger of the coupled system (coupling/co_simulation.hpp); total excludes the work term");
  recorder.addSeries("coupling_timing", {{"fluid", "s"}, {"bodies", "s"}, {"exchange", "s"}},
                     [&co](const fluid::FluidSimulation<D>&) {
                       return std::vector<double>{co.fluidSeconds(), co.bodySeconds(), co.exchangeSeconds()};
                     },
                     "accumulated wall time: fluid phases, body integration (Simbody), exchange (placing surfaces, wrenches)");
}

std::vector<std::string> describeBodies(const io::SceneConfig& c, const bodies::MultibodySystem& system) {
  std::vector<std::string> out;
  char text[512];
  for (std::size_t k = 0; k < c.bodies.size(); ++k) {
    const io::BodyConfig& b = c.bodies[k];
    const int dof = system.unlockedMobilityCount(static_cast<int>(k));
    const io::Triple s = b.start();
    std::snprintf(text, sizeof text,
                  "body '%s': %s, %d of %d DOF free, mass %g %s, centre of mass (%g, %g, %g) m (body frame), "
                  "starts at (%g, %g, %g) m",
                  b.name.c_str(), b.shape.kind.c_str(), dof, c.dim == 2 ? 3 : 6, b.mass, c.dim == 2 ? "kg/m" : "kg",
                  b.centre_of_mass[0], b.centre_of_mass[1], b.centre_of_mass[2], s[0], s[1], s[2]);
    out.push_back(text);
  }
  for (int k = 0; k < system.lineCount(); ++k) {
    const io::MooringConfig& l = c.moorings[static_cast<std::size_t>(k)];
    const bodies::LineDiagnostics d = system.lineDiagnostics(k);
    std::snprintf(text, sizeof text, "line '%s': %s from %s to %s, initial tension %.4g N at the fairlead%s", l.name.c_str(),
                  l.model.c_str(), l.fairlead.body.c_str(), l.anchor.body.empty() ? "a ground anchor" : l.anchor.body.c_str(),
                  d.fairleadTension, d.slack ? " (slack)" : "");
    out.push_back(text);
  }
  std::snprintf(text, sizeof text, "coupling: bodies held until t = %g s, fluid load ramped in over %g s, body step <= %g s",
                c.coupling.release_time, c.coupling.ramp_time, c.coupling.max_step);
  out.push_back(text);
  return out;
}

template std::unique_ptr<coupling::CoSimulation<2>> makeCoSimulation<2>(const io::SceneConfig&, const io::BuiltScene<2>&,
                                                                        const fluid::FluidParticles<2>&, const std::vector<double>&);
template std::unique_ptr<coupling::CoSimulation<3>> makeCoSimulation<3>(const io::SceneConfig&, const io::BuiltScene<3>&,
                                                                        const fluid::FluidParticles<3>&, const std::vector<double>&);
template void attachBodySeries<2>(cases::RunRecorder<2>&, const coupling::CoSimulation<2>&, const io::SceneConfig&);
template void attachBodySeries<3>(cases::RunRecorder<3>&, const coupling::CoSimulation<3>&, const io::SceneConfig&);

}  // namespace moorsph::app
