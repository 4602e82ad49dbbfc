// Wave-maker sections of a scene file: piston, damping_zones, forcing_region.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include "scene_sections.hpp"

namespace moorsph::io::detail {
namespace {

void readTable(MapReader& m, PistonConfig& p, const SceneConfig& c) {
  p.table = resolveSceneFile(c, m.requiredText("file"));
  for (const NumberRow& row : readNumberRows(m, "file", p.table, "piston signal")) {
    if (row.values.size() < 2)
      m.fail("file", p.table + ":" + std::to_string(row.line) + ": expected two numbers t [s], X [m]");
    const int line_number = row.line;
    const double t = row.values[0], x = row.values[1];
    if (!p.table_t.empty() && !(t > p.table_t.back()))
      m.fail("file", p.table + ":" + std::to_string(line_number) + ": times must increase");
    p.table_t.push_back(t);
    p.table_x.push_back(x);
  }
  if (p.table_t.size() < 2) m.fail("file", "the piston signal needs at least two rows t [s], X [m]");
}

/// A Peregrine breather focused downstream (METHOD.md 4c); the motion itself is built
/// with the effect (scene_effects.cpp), from these numbers alone, so a restart that
/// changes end_time makes the same signal.
void readBreather(MapReader& m, PistonConfig& p, const SceneConfig& c) {
  const double order = m.number("order", 1.0);
  if (order != 1.0 && order != 2.0) m.fail("order", "expected 1 or 2 (the Peregrine breather's order)");
  p.order = static_cast<int>(order);
  p.a0 = m.positive("a0", 0.0, "carrier amplitude a0 [m]");
  p.k0 = m.positive("k0", 0.0, "carrier wave number k0 [rad/m]");
  p.focus_distance = m.positive("focus_distance", 0.0, "focus distance from the piston face [m]");
  p.focus_time = m.positive("focus_time", 0.0, "focus time [s]");
  p.depth = m.positive("depth", c.waterHeight(), "still water depth d [m]");
  const double g = c.gravityMagnitude();
  const double carrier_period = 2.0 * M_PI / std::sqrt(g * p.k0);
  p.still = m.positive("still", 0.0, "time at rest before the waves [s]", true);
  p.ramp_up = m.positive("ramp_up", 4.0 * carrier_period, "ramp-up time [s]", true);
  p.ramp_down = m.positive("ramp_down", 2.0 * carrier_period, "ramp-down time at the record's end [s]", true);
  if (!(p.still + p.ramp_up < p.focus_time)) m.fail("focus_time", "expected focus_time > still + ramp_up [s]");
  // Not tied to end_time: a restart that runs longer must get the same motion. Past the
  // record the plate rests (after its ramp-down).
  p.duration = m.positive("duration", 2.0 * p.focus_time, "duration of the record [s]");
  p.finite_depth_correction = m.boolean("finite_depth_correction", false);
  if (!(p.duration > p.focus_time + p.ramp_down))
    m.fail("duration", "expected duration > focus_time + ramp_down [s]: the record must reach past the focus");
}

void readPiston(MapReader& top, SceneConfig& c) {
  if (!top.has("piston")) {
    top.child("piston");
    return;
  }
  MapReader m(top.child("piston"), "piston", top.source());
  PistonConfig& p = c.piston;
  p.present = true;
  p.name = m.text("name", "piston");
  p.x = m.requiredNumber("x");
  p.bottom = m.requiredNumber("bottom");
  p.top = m.requiredNumber("top");
  if (!(p.top - p.bottom >= 2.0 * c.dx)) m.fail("top", "expected top - bottom >= 2 dx [m]");
  if (c.dim == 3) {
    const auto z = m.vector("z", 2);
    p.z_lower = z[0];
    p.z_upper = z[1];
    if (!(p.z_upper - p.z_lower >= 2.0 * c.dx)) m.fail("z", "expected [z_lower, z_upper] at least 2 dx apart [m]");
  }
  if (!m.has("signal")) m.fail("signal", "required key is missing (expected a map with type: regular, breather or table)");
  MapReader s(m.child("signal"), "piston.signal", top.source());
  p.signal = s.text("type", "regular");
  if (p.signal == "regular") {
    p.wave_height = s.positive("wave_height", 0.0, "wave height H [m]");
    p.period = s.positive("period", 0.0, "wave period T [s]");
    p.depth = s.positive("depth", c.waterHeight(), "still water depth d [m]");
    p.ramp_up = s.positive("ramp_up", 2.0 * p.period, "ramp-up time [s]", true);
  } else if (p.signal == "breather") {
    readBreather(s, p, c);
  } else if (p.signal == "table") {
    readTable(s, p, c);
  } else {
    s.fail("type", "expected 'regular' (H, T, d), 'breather' (order, a0, k0, focus_distance, focus_time) or 'table' "
                   "(a CSV file t [s], X [m]), got '" + p.signal + "'");
  }
  s.finish();
  for (std::size_t k = 0; k < c.water.size(); ++k)
    if (c.water[k].box.lower[0] < p.x - 1e-12)
      m.fail("x", "water block " + std::to_string(k + 1) + " starts at x = " + std::to_string(c.water[k].box.lower[0]) +
                      " m, behind the piston face: water must lie on its +x side");
  m.finish();
}

void readDampingZones(MapReader& top, SceneConfig& c) {
  forEachListEntry(top, "damping_zones", "zones", [&](MapReader& m, std::size_t) {
    DampingZoneConfig z;
    z.x_start = m.requiredNumber("x_start");
    z.x_end = m.requiredNumber("x_end");
    if (!(z.x_end > z.x_start)) m.fail("x_end", "expected x_end > x_start [m]");
    z.k_max = m.positive("k_max", 0.0, "largest relaxation rate [1/s]");
    if (z.k_max * c.cflDt() >= 1.0) {
      char msg[200];
      std::snprintf(msg, sizeof msg, "k_max dt must stay below 1 for a stable step: dt = %.3g s allows k_max < %.4g 1/s",
                    c.cflDt(), 1.0 / c.cflDt());
      m.fail("k_max", msg);
    }
    m.finish();
    c.damping_zones.push_back(z);
  });
}

void readForcing(MapReader& top, SceneConfig& c) {
  if (!top.has("forcing_region")) {
    top.child("forcing_region");
    return;
  }
  MapReader m(top.child("forcing_region"), "forcing_region", top.source());
  ForcingRegionConfig& f = c.forcing;
  f.present = true;
  f.x_start = m.requiredNumber("x_start");
  f.length = m.positive("length", 0.0, "region length L_w [m]");
  double lowest = c.water.front().box.lower[1], highest = c.water.front().box.upper[1];
  for (const auto& w : c.water) {
    lowest = std::min(lowest, w.box.lower[1]);
    highest = std::max(highest, w.box.upper[1]);
  }
  f.floor = m.number("floor", lowest);
  f.bottom_gap = m.positive("bottom_gap", 0.0, "gap above the floor [m]", true);
  f.still_level = m.number("still_level", highest);
  if (!(f.still_level > f.floor + f.bottom_gap)) m.fail("still_level", "expected still_level > floor + bottom_gap [m]");
  f.kappa = m.number("kappa", f.kappa);
  if (std::pow(10.0, f.kappa) * c.mu / c.rho0 * c.cflDt() >= 1.0)
    m.fail("kappa", "the relaxation rate 10^kappa mu / rho0 times dt must stay below 1");
  f.ramp_up = m.positive("ramp_up", 0.0, "ramp-up time of the target [s]", true);
  f.end_time = m.positive("end_time", f.end_time, "time the forcing stops [s]", true);
  f.gain = m.positive("gain", 1.0, "gain on the target velocity (amplitude calibration)");
  if (!m.has("wave")) m.fail("wave", "required key is missing (expected theory, amplitude [m], period [s])");
  MapReader w(m.child("wave"), "forcing_region.wave", top.source());
  f.theory = w.text("theory", "airy");
  if (f.theory != "airy" && f.theory != "stokes2") w.fail("theory", "expected 'airy' or 'stokes2', got '" + f.theory + "'");
  f.amplitude = w.positive("amplitude", 0.0, "wave amplitude a [m]");
  f.period = w.positive("period", 0.0, "wave period T [s]");
  w.finish();
  m.finish();
}

}  // namespace

void readWaveMakers(MapReader& top, SceneConfig& c) {
  readPiston(top, c);
  readDampingZones(top, c);
  readForcing(top, c);
  // An effect is built if and only if the scene names it and gives its section.
  const struct {
    const char* effect;
    const char* section;
    bool given;
  } makers[] = {{"piston", "piston", c.piston.present},
                {"damping_zone", "damping_zones", !c.damping_zones.empty()},
                {"forcing_region", "forcing_region", c.forcing.present}};
  for (const auto& mk : makers) {
    if (mk.given && !c.hasEffect(mk.effect))
      top.fail(mk.section, std::string("the scene gives '") + mk.section + "' but 'effects' does not list '" + mk.effect + "'");
    if (!mk.given && c.hasEffect(mk.effect))
      top.fail("effects", std::string("'effects' lists '") + mk.effect + "' but the scene has no '" + mk.section + "' section");
  }
  if (c.piston.present && !c.hasEffect("walls")) top.fail("piston", "the piston is a wall: 'effects' must list 'walls'");
}

}  // namespace moorsph::io::detail
