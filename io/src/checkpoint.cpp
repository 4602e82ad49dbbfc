#include <moorsph/io/checkpoint.hpp>

#include <filesystem>
#include <stdexcept>
#include <moorsph/fluid/piston.hpp>
#include "h5_helpers.hpp"

namespace moorsph::io {

namespace {

// D values per particle, one particle after another: the layout of the (N, D) datasets.
template <int D>
std::vector<double> flatten(const std::vector<fluid::Vec<D>>& r) {
  std::vector<double> out;
  out.reserve(D * r.size());
  for (const auto& x : r)
    for (int d = 0; d < D; ++d) out.push_back(x[d]);
  return out;
}

template <int D>
std::vector<fluid::Vec<D>> unflatten(const std::vector<double>& flat) {
  std::vector<fluid::Vec<D>> out(flat.size() / D);
  for (std::size_t i = 0; i < out.size(); ++i)
    for (int d = 0; d < D; ++d) out[i][d] = flat[D * i + d];
  return out;
}

}  // namespace

template <int D>
Checkpoint captureCheckpoint(const fluid::FluidSimulation<D>& sim) {
  const auto& f = sim.fluid();
  Checkpoint c;
  c.dim = D;
  c.time = sim.time();
  c.last_dt = sim.lastDt();
  c.steps = static_cast<std::int64_t>(sim.stepCount());
  c.r = flatten<D>(f.r);
  c.v = flatten<D>(f.v);
  c.rho = f.rho;
  c.m = f.m;
  c.id = f.id;
  c.r_at_build = flatten<D>(sim.neighbours().fluidAtBuild());
  c.boundary_r_at_build = flatten<D>(sim.neighbours().boundaryAtBuild());
  if (const auto* out = sim.outflow(); out && out->tally().particles > 0) {
    const fluid::OutflowTally& t = out->tally();
    c.outflow = {static_cast<double>(t.particles), t.mass, t.energy, t.first_time};
  }
  if (const auto* piston = sim.template findEffect<fluid::Piston<D>>()) c.piston_work = {piston->work()};
  return c;
}

template <int D>
void restoreEffectTotals(const Checkpoint& c, fluid::FluidSimulation<D>& sim) {
  if (c.outflow.size() == 4) {
    fluid::Outflow<D>* out = sim.updOutflow();
    if (!out)
      throw std::runtime_error("the checkpoint's run removed " + std::to_string(static_cast<long long>(c.outflow[0])) +
                               " particles through 'outflow', which the scene no longer lists");
    out->restoreTally({static_cast<std::size_t>(c.outflow[0]), c.outflow[1], c.outflow[2], c.outflow[3]});
  }
  auto* piston = sim.template updEffect<fluid::Piston<D>>();
  if (piston && c.piston_work.size() == 1) piston->restoreWork(c.piston_work[0]);
}

template <int D>
fluid::FluidParticles<D> restoreParticles(const Checkpoint& c) {
  if (c.dim != D) throw std::runtime_error("checkpoint is " + std::to_string(c.dim) + "D, the scene " + std::to_string(D) + "D");
  fluid::FluidParticles<D> f;
  f.r = unflatten<D>(c.r);
  f.v = unflatten<D>(c.v);
  f.rho = c.rho;
  f.m = c.m;
  f.id = c.id;
  return f;
}

template Checkpoint captureCheckpoint<2>(const fluid::FluidSimulation<2>&);
template Checkpoint captureCheckpoint<3>(const fluid::FluidSimulation<3>&);
template fluid::FluidParticles<2> restoreParticles<2>(const Checkpoint&);
template fluid::FluidParticles<3> restoreParticles<3>(const Checkpoint&);
template void restoreEffectTotals<2>(const Checkpoint&, fluid::FluidSimulation<2>&);
template void restoreEffectTotals<3>(const Checkpoint&, fluid::FluidSimulation<3>&);

template <int D>
bool restoreNeighbourLists(const Checkpoint& c, fluid::FluidSimulation<D>& sim) {
  if (c.r_at_build.empty()) return false;
  try {
    sim.restoreNeighbourLists(unflatten<D>(c.r_at_build), unflatten<D>(c.boundary_r_at_build));
  } catch (const std::invalid_argument&) {
    // The saved positions do not fit this run's lists (a changed smoothing length or
    // skin gives other cells; a changed boundary count): its first step builds them afresh.
    return false;
  }
  return true;
}

template bool restoreNeighbourLists<2>(const Checkpoint&, fluid::FluidSimulation<2>&);
template bool restoreNeighbourLists<3>(const Checkpoint&, fluid::FluidSimulation<3>&);

void writeCheckpoint(const std::string& path, const Checkpoint& c) {
  const std::string tmp = path + ".tmp";
  {
    h5::Handle file(H5Fcreate(tmp.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose, "create " + tmp);
    h5::writeStringAttribute(file, "format", "moorsph checkpoint 1");
    h5::writeDoubleAttribute(file, "dim", c.dim);
    h5::writeDoubleAttribute(file, "time", c.time);
    h5::writeDoubleAttribute(file, "last_dt", c.last_dt);
    h5::writeStringAttribute(file, "scene", c.scene_yaml);
    h5::writeStringAttribute(file, "reason", c.reason);
    h5::writeInt64(file, "counters", {c.steps, c.next_output, c.next_snapshot}, "1");
    h5::writeDoubles(file, "r", c.r, c.dim, "m");
    h5::writeDoubles(file, "v", c.v, c.dim, "m/s");
    h5::writeDoubles(file, "rho", c.rho, 1, "kg/m^3");
    h5::writeDoubles(file, "m", c.m, 1, "kg");
    h5::writeInt64(file, "id", c.id, "1");
    if (!c.r_at_build.empty()) h5::writeDoubles(file, "r_at_build", c.r_at_build, c.dim, "m");
    if (!c.boundary_r_at_build.empty())
      h5::writeDoubles(file, "boundary_r_at_build", c.boundary_r_at_build, c.dim, "m");
    if (!c.bodies.empty()) h5::writeDoubles(file, "bodies", c.bodies, 1, "SI");
    if (!c.outflow.empty()) h5::writeDoubles(file, "outflow", c.outflow, 1, "particles, kg, J, s");
    if (!c.piston_work.empty()) h5::writeDoubles(file, "piston_work", c.piston_work, 1, "J");
    if (c.scene_fluid_count > 0) h5::writeInt64(file, "scene_fluid_count", {c.scene_fluid_count}, "1");
    if (H5Fflush(file, H5F_SCOPE_GLOBAL) < 0) throw std::runtime_error("HDF5: flush " + tmp);
  }
  std::filesystem::rename(tmp, path);  // atomic on one file system: never a half-written checkpoint
}

Checkpoint readCheckpoint(const std::string& path) {
  if (!std::filesystem::exists(path)) throw std::runtime_error(path + ": no such checkpoint");
  H5E_auto2_t func = nullptr;
  void* data = nullptr;
  H5Eget_auto2(H5E_DEFAULT, &func, &data);
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // report our own message, not HDF5's stack
  const hid_t id = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  H5Eset_auto2(H5E_DEFAULT, func, data);
  h5::Handle file(id, H5Fclose, path + ": not an HDF5 file");
  if (!h5::hasAttribute(file, "format") || h5::readStringAttribute(file, "format") != "moorsph checkpoint 1")
    throw std::runtime_error(path + ": not a moorsph checkpoint");
  Checkpoint c;
  c.dim = static_cast<int>(h5::readDoubleAttribute(file, "dim"));
  c.time = h5::readDoubleAttribute(file, "time");
  c.last_dt = h5::readDoubleAttribute(file, "last_dt");
  c.scene_yaml = h5::readStringAttribute(file, "scene");
  c.reason = h5::readStringAttribute(file, "reason");
  const auto counters = h5::readInt64(file, "counters");
  if (counters.size() != 3) throw std::runtime_error(path + ": bad counters");
  c.steps = counters[0];
  c.next_output = counters[1];
  c.next_snapshot = counters[2];
  c.r = h5::readDoubles(file, "r");
  c.v = h5::readDoubles(file, "v");
  c.rho = h5::readDoubles(file, "rho");
  c.m = h5::readDoubles(file, "m");
  c.id = h5::readInt64(file, "id");
  if (H5Lexists(file, "r_at_build", H5P_DEFAULT) > 0) c.r_at_build = h5::readDoubles(file, "r_at_build");
  if (H5Lexists(file, "boundary_r_at_build", H5P_DEFAULT) > 0)
    c.boundary_r_at_build = h5::readDoubles(file, "boundary_r_at_build");
  if (H5Lexists(file, "bodies", H5P_DEFAULT) > 0) c.bodies = h5::readDoubles(file, "bodies");
  if (H5Lexists(file, "outflow", H5P_DEFAULT) > 0) c.outflow = h5::readDoubles(file, "outflow");
  if (H5Lexists(file, "piston_work", H5P_DEFAULT) > 0) c.piston_work = h5::readDoubles(file, "piston_work");
  if (H5Lexists(file, "scene_fluid_count", H5P_DEFAULT) > 0) {
    const auto count = h5::readInt64(file, "scene_fluid_count");
    if (count.size() != 1) throw std::runtime_error(path + ": bad scene_fluid_count");
    c.scene_fluid_count = count[0];
  }
  const std::size_t n = c.rho.size();
  if (c.r.size() != n * c.dim || c.v.size() != n * c.dim || c.m.size() != n || c.id.size() != n ||
      (!c.r_at_build.empty() && c.r_at_build.size() != n * c.dim) || c.boundary_r_at_build.size() % c.dim != 0)
    throw std::runtime_error(path + ": arrays of inconsistent sizes");
  return c;
}

}  // namespace moorsph::io
