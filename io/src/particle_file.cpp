#include <moorsph/io/particle_file.hpp>

#include <algorithm>
#include <cstdio>
#include <numeric>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include "h5_helpers.hpp"

namespace moorsph::io {

template <int D>
ParticleSnapshot takeSnapshot(const fluid::FluidSimulation<D>& sim) {
  const auto& f = sim.fluid();
  const std::size_t nf = f.size();
  const std::size_t nb = sim.walls() ? sim.walls()->particles().size() : 0;
  const std::size_t n = nf + nb;
  ParticleSnapshot s;
  s.time = sim.time();
  s.position.assign(3 * n, 0.0);
  s.velocity.assign(3 * n, 0.0);
  s.pressure.assign(n, 0.0);
  s.density.assign(n, sim.setup().rho0);
  s.type.assign(n, 1);
  s.id.resize(n);
  // Ids are 0..nf-1 from the builder; place each particle at its id (the arrays are
  // re-sorted by cell during the run). Once the outflow has removed particles the ids
  // have gaps: place them in id order.
  bool ids_dense = true;
  for (std::size_t i = 0; i < nf && ids_dense; ++i) ids_dense = f.id[i] >= 0 && static_cast<std::size_t>(f.id[i]) < nf;
  std::vector<std::size_t> slot(nf);
  if (ids_dense) {
    for (std::size_t i = 0; i < nf; ++i) slot[i] = static_cast<std::size_t>(f.id[i]);
  } else {
    std::vector<std::size_t> by_id(nf);
    std::iota(by_id.begin(), by_id.end(), std::size_t{0});
    std::sort(by_id.begin(), by_id.end(), [&](std::size_t a, std::size_t b) { return f.id[a] < f.id[b]; });
    for (std::size_t k = 0; k < nf; ++k) slot[by_id[k]] = k;
  }
  for (std::size_t i = 0; i < nf; ++i) {
    const std::size_t k = slot[i];
    for (int d = 0; d < D; ++d) {
      s.position[3 * k + d] = f.r[i][d];
      s.velocity[3 * k + d] = f.v[i][d];
    }
    s.density[k] = f.rho[i];
    s.pressure[k] = sim.eos().pressure(f.rho[i]);
    s.type[k] = 0;
    s.id[k] = f.id[i];
  }
  for (std::size_t b = 0; b < nb; ++b) {
    const auto& r = sim.walls()->particles().r[b];
    for (int d = 0; d < D; ++d) s.position[3 * (nf + b) + d] = r[d];
    s.id[nf + b] = static_cast<std::int64_t>(nf + b);
  }
  return s;
}

template ParticleSnapshot takeSnapshot<2>(const fluid::FluidSimulation<2>&);
template ParticleSnapshot takeSnapshot<3>(const fluid::FluidSimulation<3>&);

ParticleFile::ParticleFile(const std::string& directory) : directory_(directory) {
  const std::string path = directory_ + "/particles.h5";
  file_ = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  if (file_ < 0) throw std::runtime_error(path + ": cannot create HDF5 file");
  h5::Handle g(H5Gcreate2(file_, "snapshots", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose, "create /snapshots");
  h5::writeStringAttribute(g, "description", "one group per output time; fluid first (by id), then boundary");
  h5::Handle v(H5Gcreate2(file_, "polyvertex", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose, "create /polyvertex");
  h5::writeStringAttribute(v, "description", "/polyvertex/N = 0..N-1: the XDMF vertex cells of an N-particle snapshot");
  writeXdmf();
}

// ParaView's Xdmf3 readers (Xdmf3ReaderS is the one OpenDataFile picks for .xmf) build
// no cells from a Polyvertex topology without connectivity, so the points exist but
// draw nothing in the default Surface representation (seen with ParaView 5.11). An
// explicit 0..N-1 list, one per particle count and shared by every snapshot of that
// count, gives one vertex cell per particle in both the Xdmf2 and Xdmf3 readers.
void ParticleFile::writePolyvertex(std::size_t n) {
  const std::string path = "polyvertex/" + std::to_string(n);
  if (H5Lexists(file_, path.c_str(), H5P_DEFAULT) > 0) return;
  std::vector<std::int64_t> index(n);
  for (std::size_t i = 0; i < n; ++i) index[i] = static_cast<std::int64_t>(i);
  h5::Handle v(H5Gopen2(file_, "polyvertex", H5P_DEFAULT), H5Gclose, "open /polyvertex");
  h5::writeInt64(v, std::to_string(n), index, "1");
}

ParticleFile::~ParticleFile() {
  if (file_ >= 0) H5Fclose(file_);
}

void ParticleFile::write(const ParticleSnapshot& s) {
  char name[32];
  std::snprintf(name, sizeof name, "%06zu", entries_.size());
  const std::string group = std::string("snapshots/") + name;
  {
    h5::Handle g(H5Gcreate2(file_, group.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose, "create " + group);
    h5::writeDoubleAttribute(g, "time", s.time);
    h5::writeDoubles(g, "position", s.position, 3, "m");
    h5::writeDoubles(g, "velocity", s.velocity, 3, "m/s");
    h5::writeDoubles(g, "pressure", s.pressure, 1, "Pa");
    h5::writeDoubles(g, "density", s.density, 1, "kg/m^3");
    h5::writeInt32(g, "type", s.type, "1");
    h5::writeInt64(g, "id", s.id, "1");
  }
  writePolyvertex(s.size());
  if (H5Fflush(file_, H5F_SCOPE_GLOBAL) < 0) throw std::runtime_error("HDF5: flush particles.h5");
  entries_.push_back({group, s.time, s.size()});
  writeXdmf();
}

void ParticleFile::writeXdmf() const {
  const std::string path = directory_ + "/particles.xmf";
  const std::string tmp = path + ".tmp";
  {
    std::ofstream x(tmp);
    x << "<?xml version=\"1.0\" ?>\n<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n<Xdmf Version=\"2.0\">\n <Domain>\n"
      << "  <Grid Name=\"particles\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
    for (const auto& e : entries_) {
      const std::string n = std::to_string(e.n);
      auto item = [&](const char* field, const char* dims, const char* type, int precision) {
        x << "     <DataItem Dimensions=\"" << dims << "\" NumberType=\"" << type << "\" Precision=\"" << precision
          << "\" Format=\"HDF\">particles.h5:/" << e.group << "/" << field << "</DataItem>\n";
      };
      char time[40];
      std::snprintf(time, sizeof time, "%.17g", e.time);
      x << "   <Grid Name=\"" << e.group << "\" GridType=\"Uniform\">\n    <Time Value=\"" << time << "\"/>\n"
        << "    <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" << n << "\" NodesPerElement=\"1\">\n";
      x << "     <DataItem Dimensions=\"" << n << "\" NumberType=\"Int\" Precision=\"8\" Format=\"HDF\">particles.h5:/polyvertex/"
        << n << "</DataItem>\n    </Topology>\n    <Geometry GeometryType=\"XYZ\">\n";
      item("position", (n + " 3").c_str(), "Float", 8);
      x << "    </Geometry>\n";
      x << "    <Attribute Name=\"velocity\" AttributeType=\"Vector\" Center=\"Node\">\n";
      item("velocity", (n + " 3").c_str(), "Float", 8);
      x << "    </Attribute>\n";
      for (const char* field : {"pressure", "density"}) {
        x << "    <Attribute Name=\"" << field << "\" AttributeType=\"Scalar\" Center=\"Node\">\n";
        item(field, n.c_str(), "Float", 8);
        x << "    </Attribute>\n";
      }
      x << "    <Attribute Name=\"type\" AttributeType=\"Scalar\" Center=\"Node\">\n";
      item("type", n.c_str(), "Int", 4);
      x << "    </Attribute>\n";
      x << "    <Attribute Name=\"id\" AttributeType=\"Scalar\" Center=\"Node\">\n";
      item("id", n.c_str(), "Int", 8);
      x << "    </Attribute>\n   </Grid>\n";
    }
    x << "  </Grid>\n </Domain>\n</Xdmf>\n";
    if (!x) throw std::runtime_error(tmp + ": cannot write");
  }
  std::filesystem::rename(tmp, path);
}

}  // namespace moorsph::io
