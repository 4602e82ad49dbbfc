// moorsph_make_hull: writes the METHOD.md section 6.5 ship hull (io::section65Ship, fitted to
// its displaced volume, waterplane area and trim) or a hull of given parameters, as STL or
// OBJ, with its deck outline (CSV) and a report of its hydrostatics and mass properties.
//
//   moorsph_make_hull [--out hull.stl] [--deck deck.csv] [--max-edge 2.5]
//                     [--length L --beam B --depth D --draught T --section-exponent n
//                      --entrance Le --run Lr --entrance-exponent pe --run-exponent pr
//                      --transom t]
// Any shape option switches from the preset to the given parameters (the rest keep the
// preset's fitted values); the report then still uses the preset's mass and CoM.
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <stdexcept>
#include <string>

#include <moorsph/io/hull_generator.hpp>
#include <moorsph/io/mesh_properties.hpp>
#include <moorsph/io/mesh_writer.hpp>

using namespace moorsph;

namespace {

void report(const io::ShipPreset& ship, const io::HullParameters& h, const io::TriangleMesh& mesh) {
  const io::Hydrostatics hs = io::hydrostatics(mesh, h.draught);
  const io::SolidProperties solid = io::solidProperties(mesh);
  const io::MeshEdgeReport edges = io::checkEdges(mesh);
  const double rho = ship.water_density, m = ship.mass;
  const double kg = ship.centre_of_mass.y();
  std::printf("hull: L %.2f m, B %.2f m, D %.2f m, T %.2f m\n", h.length, h.beam, h.depth, h.draught);
  std::printf("shape: section exponent n %.4f (C_s %.4f), entrance %.2f m exponent %.4f, run %.2f m exponent %.4f, transom %.4f B\n",
              h.section_exponent, io::sectionCoefficient(h.section_exponent), h.entrance_length, h.entrance_exponent,
              h.run_length, h.run_exponent, h.transom_fraction);
  std::printf("mesh: %zu vertices, %zu triangles, %d edges, closed %s (open %d, non-manifold %d, misoriented %d)\n",
              mesh.vertices.size(), mesh.triangles.size(), edges.edges, edges.closed() ? "yes" : "NO", edges.open_edges,
              edges.overused_edges, edges.same_direction);
  std::printf("at draught %.3f m: displaced volume %.1f m^3 (C_b %.4f), waterplane area %.1f m^2 (C_wp %.4f)\n",
              h.draught, hs.volume, hs.volume / (h.length * h.beam * h.draught), hs.waterplane_area,
              hs.waterplane_area / (h.length * h.beam));
  std::printf("  centre of buoyancy x %.3f m from the bow, KB %.3f m; centre of floatation x %.3f m\n",
              hs.centre_of_buoyancy.x(), hs.centre_of_buoyancy.y(), hs.floatation_centre.x());
  std::printf("  sinkage per 1000 t at rho %.0f: %.4f m\n", rho, 1e6 / (rho * hs.waterplane_area));
  std::printf("  BM_T %.3f m, BM_L %.1f m; KG %.2f m -> GM_T %.3f m, GM_L %.1f m (no cable or free-surface terms)\n",
              hs.bmTransverse(), hs.bmLongitudinal(), kg, hs.centre_of_buoyancy.y() + hs.bmTransverse() - kg,
              hs.centre_of_buoyancy.y() + hs.bmLongitudinal() - kg);
  std::printf("  buoyancy %.1f t vs mass %.1f t: the cables must pull %.1f t (%.2f MN, %.2f MN each of 3)\n",
              rho * hs.volume / 1e3, m / 1e3, (rho * hs.volume - m) / 1e3, (rho * hs.volume - m) * 9.81 / 1e6,
              (rho * hs.volume - m) * 9.81 / 3e6);
  std::printf("closed hull: volume %.1f m^3, centroid (%.3f, %.3f, %.3f) m\n", solid.volume, solid.centroid.x(),
              solid.centroid.y(), solid.centroid.z());
  const Eigen::Vector3d k_solid = (solid.inertia_per_density.diagonal() / solid.volume).cwiseSqrt();
  std::printf("  uniform-solid radii of gyration about its centroid: roll %.2f m (%.3f B), yaw %.2f m (%.3f L), pitch %.2f m (%.3f L)\n",
              k_solid.x(), k_solid.x() / h.beam, k_solid.y(), k_solid.y() / h.length, k_solid.z(), k_solid.z() / h.length);
  std::printf("body: mass %.0f kg, centre_of_mass [%.2f, %.2f, %.2f] m, inertia [%.4e, %.4e, %.4e] kg m^2 (k = 0.35 B, 0.25 L, 0.25 L)\n",
              m, ship.centre_of_mass.x(), ship.centre_of_mass.y(), ship.centre_of_mass.z(), ship.inertia.x(),
              ship.inertia.y(), ship.inertia.z());
}

}  // namespace

int main(int argc, char** argv) {
  try {
    std::map<std::string, std::string> opt;
    for (int k = 1; k < argc; ++k) {
      const std::string key = argv[k];
      if (key.rfind("--", 0) != 0 || k + 1 >= argc) throw std::invalid_argument("expected '--option value', got '" + key + "'");
      opt[key.substr(2)] = argv[++k];
    }
    const double max_edge = opt.count("max-edge") ? std::stod(opt["max-edge"]) : 2.5;
    opt.erase("max-edge");
    const std::string out = opt.count("out") ? opt["out"] : "hull.stl";
    const std::string deck = opt.count("deck") ? opt["deck"] : "";
    opt.erase("out");
    opt.erase("deck");
    const io::ShipPreset ship = io::section65Ship(max_edge);
    io::HullParameters h = ship.hull;
    const std::map<std::string, double*> fields{
        {"length", &h.length}, {"beam", &h.beam}, {"depth", &h.depth}, {"draught", &h.draught},
        {"section-exponent", &h.section_exponent}, {"entrance", &h.entrance_length}, {"run", &h.run_length},
        {"entrance-exponent", &h.entrance_exponent}, {"run-exponent", &h.run_exponent},
        {"transom", &h.transom_fraction}};
    for (const auto& [key, value] : opt) {
      const auto it = fields.find(key);
      if (it == fields.end()) throw std::invalid_argument("unknown option '--" + key + "'");
      *it->second = std::stod(value);
    }
    const io::TriangleMesh mesh = io::makeHullMesh(h, max_edge);
    io::writeMesh(out, mesh);
    if (!deck.empty()) {
      std::ofstream csv(deck);
      if (!csv) throw std::runtime_error(deck + ": cannot open for writing");
      csv << "x,y,z\n";
      for (const auto& p : io::deckOutline(h, max_edge)) csv << p.x() << ',' << p.y() << ',' << p.z() << '\n';
    }
    report(ship, h, mesh);
    std::printf("wrote %s\n", out.c_str());
  } catch (const std::exception& e) {
    std::cerr << "moorsph_make_hull: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
