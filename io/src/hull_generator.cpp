#include <moorsph/io/hull_generator.hpp>

#include <cmath>
#include <functional>
#include <map>
#include <stdexcept>
#include <string>

#include <moorsph/io/mesh_properties.hpp>

namespace moorsph::io {

void validate(const HullParameters& p) {
  auto require = [](bool ok, const std::string& what) {
    if (!ok) throw std::invalid_argument("hull: " + what);
  };
  require(p.length > 0.0 && p.beam > 0.0, "'length' and 'beam' must be > 0");
  require(p.draught > 0.0 && p.depth >= p.draught, "'draught' must be > 0 and 'depth' >= 'draught'");
  require(p.section_exponent >= 1.0, "'section_exponent' must be >= 1 (1 is a V section)");
  require(p.entrance_exponent >= 1.0 && p.run_exponent >= 1.0, "'entrance_exponent' and 'run_exponent' must be >= 1");
  require(p.transom_fraction >= 0.0 && p.transom_fraction <= 1.0, "'transom_fraction' must be in [0, 1]");
  require(p.entrance_length >= 0.0 && p.run_length >= 0.0 && p.entrance_length + p.run_length <= p.length,
          "'entrance_length' and 'run_length' must be >= 0 and add up to at most 'length'");
}

double waterlineFraction(const HullParameters& p, double x) {
  if (x < 0.0 || x > p.length) return 0.0;
  if (x < p.entrance_length) return 1.0 - std::pow(1.0 - x / p.entrance_length, p.entrance_exponent);
  const double from_stern = p.length - x;
  if (from_stern < p.run_length) {
    const double t = p.transom_fraction;
    return t + (1.0 - t) * (1.0 - std::pow(1.0 - from_stern / p.run_length, p.run_exponent));
  }
  return 1.0;
}

double sectionCoefficient(double n) {
  return std::exp(2.0 * std::lgamma(1.0 + 1.0 / n) - std::lgamma(1.0 + 2.0 / n));
}

namespace {

int steps(double span, double max_edge) { return std::max(1, static_cast<int>(std::ceil(span / max_edge - 1e-9))); }

/// Station abscissae: the entrance, the parallel body and the run each split evenly.
std::vector<double> stations(const HullParameters& p, double max_edge) {
  const double ends[4] = {0.0, p.entrance_length, p.length - p.run_length, p.length};
  std::vector<double> x{0.0};
  for (int s = 0; s < 3; ++s) {
    const double span = ends[s + 1] - ends[s];
    if (span <= 0.0) continue;
    const int n = steps(span, max_edge);
    for (int k = 1; k <= n; ++k) x.push_back(k == n ? ends[s + 1] : ends[s] + span * k / n);
  }
  return x;
}

/// One point of a station's ring: lateral position as a fraction of the local half-breadth
/// (z = u * B/2 * w(x)), height y, and the "level" it collapses to on the centreline when
/// the station has zero width.
struct RingPoint {
  double u, y;
  int level;
};

/// The closed section outline: keel, starboard bottom (superellipse) and side, the deck
/// across, port side and bottom back toward the keel.
std::vector<RingPoint> ring(const HullParameters& p, double max_edge) {
  const double half_beam = 0.5 * p.beam, T = p.draught, n = p.section_exponent;
  const int K = std::max(4, steps(half_beam + T, max_edge));
  const int Ns = p.depth > T ? steps(p.depth - T, max_edge) : 0;
  const int Nd = std::max(2, steps(p.beam, max_edge));
  std::vector<RingPoint> starboard;  // levels 1 .. K + Ns
  for (int k = 1; k <= K; ++k) {
    // Superellipse by its angle parameter: z = cos(t)^(2/n), T - y = T sin(t)^(2/n).
    const double t = 0.5 * M_PI * (1.0 - static_cast<double>(k) / K);
    const double u = k == K ? 1.0 : std::pow(std::cos(t), 2.0 / n);
    const double y = k == K ? T : T - T * std::pow(std::sin(t), 2.0 / n);
    starboard.push_back({u, y, k});
  }
  for (int j = 1; j <= Ns; ++j) starboard.push_back({1.0, j == Ns ? p.depth : T + (p.depth - T) * j / Ns, K + j});
  const int top = K + Ns;
  std::vector<RingPoint> r{{0.0, 0.0, 0}};
  r.insert(r.end(), starboard.begin(), starboard.end());
  for (int j = 1; j < Nd; ++j) r.push_back({1.0 - 2.0 * j / Nd, p.depth, top});
  for (auto it = starboard.rbegin(); it != starboard.rend(); ++it) r.push_back({-it->u, it->y, it->level});
  return r;
}

}  // namespace

TriangleMesh makeHullMesh(const HullParameters& p, double max_edge) {
  validate(p);
  if (!(max_edge > 0.0)) throw std::invalid_argument("hull: max_edge must be > 0");
  const std::vector<double> xs = stations(p, max_edge);
  const std::vector<RingPoint> rp = ring(p, max_edge);
  const int M = static_cast<int>(rp.size());
  TriangleMesh mesh;
  std::vector<std::vector<int>> id(xs.size(), std::vector<int>(M));
  for (std::size_t i = 0; i < xs.size(); ++i) {
    const double hb = 0.5 * p.beam * waterlineFraction(p, xs[i]);
    std::map<int, int> centreline;  // level -> vertex, for a station of zero width
    for (int r = 0; r < M; ++r) {
      const bool collapse = hb == 0.0 || rp[r].level == 0;
      if (collapse && centreline.count(rp[r].level)) {
        id[i][r] = centreline[rp[r].level];
        continue;
      }
      mesh.vertices.emplace_back(xs[i], rp[r].y, collapse ? 0.0 : rp[r].u * hb);
      id[i][r] = static_cast<int>(mesh.vertices.size()) - 1;
      if (collapse) centreline[rp[r].level] = id[i][r];
    }
  }
  auto add = [&](int a, int b, int c) {
    if (a != b && b != c && c != a) mesh.triangles.push_back({a, b, c});
  };
  for (std::size_t i = 0; i + 1 < xs.size(); ++i)
    for (int r = 0; r < M; ++r) {
      const int a = id[i][r], b = id[i][(r + 1) % M], c = id[i + 1][(r + 1) % M], d = id[i + 1][r];
      add(a, b, c);
      add(a, c, d);
    }
  // Flat ends (no entrance or no run): a fan from a point inside the convex section,
  // wound against the neighbouring strip so every edge is used once each way.
  const std::size_t last = xs.size() - 1;
  for (const std::size_t i : {std::size_t{0}, last}) {
    if (waterlineFraction(p, xs[i]) == 0.0) continue;
    mesh.vertices.emplace_back(xs[i], 0.5 * p.depth, 0.0);
    const int centre = static_cast<int>(mesh.vertices.size()) - 1;
    for (int r = 0; r < M; ++r) {
      const int a = id[i][r], b = id[i][(r + 1) % M];
      if (i == 0) add(centre, b, a);
      else add(centre, a, b);
    }
  }
  if (mesh.signedVolume() < 0.0) mesh.flip();
  return mesh;
}

std::vector<Eigen::Vector3d> deckOutline(const HullParameters& p, double max_edge) {
  validate(p);
  const std::vector<double> xs = stations(p, max_edge);
  std::vector<Eigen::Vector3d> outline;
  for (int side : {1, -1})
    for (std::size_t k = 0; k < xs.size(); ++k) {
      const double x = side > 0 ? xs[k] : xs[xs.size() - 1 - k];
      const double hb = 0.5 * p.beam * waterlineFraction(p, x);
      if (hb == 0.0 && side < 0) continue;  // a pointed end appears once
      outline.emplace_back(x, p.depth, side * hb);
    }
  return outline;
}

namespace {

/// Bisection for an increasing f on [lo, hi] (in log space when `log`); nullopt when f(lo),
/// f(hi) do not bracket 0 (sign of the miss in `miss`: -1 target below the range, +1 above).
std::optional<double> solveIncreasing(const std::function<double(double)>& f, double lo, double hi, int* miss = nullptr,
                                      bool log = true) {
  double flo = f(lo), fhi = f(hi);
  if (flo > 0.0 || fhi < 0.0) {
    if (miss) *miss = flo > 0.0 ? -1 : 1;
    return std::nullopt;
  }
  auto middle = [&] { return log ? std::sqrt(lo * hi) : 0.5 * (lo + hi); };
  for (int it = 0; it < 60; ++it) {
    const double mid = middle();
    if (f(mid) < 0.0) lo = mid;
    else hi = mid;
  }
  return middle();
}

/// Waterplane area and centre of floatation of the mesh at y = T: its waterline is the
/// polyline through the stations' waterline points, so the trapezoid sums are exact.
std::pair<double, double> waterplane(const HullParameters& p, const std::vector<double>& xs) {
  double area = 0.0, moment = 0.0;
  for (std::size_t i = 0; i + 1 < xs.size(); ++i) {
    const double x0 = xs[i], x1 = xs[i + 1], w0 = waterlineFraction(p, x0), w1 = waterlineFraction(p, x1);
    area += 0.5 * (w0 + w1) * (x1 - x0);
    moment += (x1 - x0) * (x0 * (2.0 * w0 + w1) + x1 * (w0 + 2.0 * w1)) / 6.0;
  }
  return {p.beam * area, area > 0.0 ? moment / area : 0.0};
}

constexpr double kLow = 1.0, kHigh = 1000.0;  // exponent search range

}  // namespace

HullParameters fitHull(HullParameters p, const HullTargets& targets, double max_edge) {
  validate(p);
  const std::vector<double> xs = stations(p, max_edge);
  const double awp = targets.waterplane_area;
  if (!targets.lcb_from_bow) {
    auto area_miss = [&](double e) {
      p.entrance_exponent = p.run_exponent = e;
      return waterplane(p, xs).first - awp;
    };
    const auto q = solveIncreasing(area_miss, kLow, kHigh);
    if (!q) throw std::invalid_argument("hull fit: waterplane area " + std::to_string(awp) + " m^2 not reachable with exponents in [1, 1000] for this entrance and run");
    p.entrance_exponent = p.run_exponent = *q;
  } else {
    // A wider transom with the entrance re-solved for the area (finer) moves the centre of
    // floatation aft: bisection on t, an unreachable area counting as "too far aft" (t too
    // large: too full even with a wedge entrance) or "too far forward".
    auto lcf_miss = [&](double t) {
      p.transom_fraction = t;
      auto area_miss = [&](double e) {
        p.entrance_exponent = e;
        return waterplane(p, xs).first - awp;
      };
      int miss = 0;
      const auto pe = solveIncreasing(area_miss, kLow, kHigh, &miss);
      if (!pe) return miss < 0 ? 1e9 : -1e9;
      p.entrance_exponent = *pe;
      return waterplane(p, xs).second - *targets.lcb_from_bow;
    };
    const auto t = solveIncreasing(lcf_miss, 0.0, 1.0, nullptr, false);
    if (!t) throw std::invalid_argument("hull fit: centre of buoyancy " + std::to_string(*targets.lcb_from_bow) + " m from the bow not reachable with this entrance and run");
    lcf_miss(*t);  // leaves t and p_e at the solution
  }
  // Volume grows with the section exponent (C_s from 1/2 at n = 1 toward 1).
  auto volume_miss = [&](double n) {
    p.section_exponent = n;
    return hydrostatics(makeHullMesh(p, max_edge), p.draught).volume - targets.displaced_volume;
  };
  const auto n = solveIncreasing(volume_miss, kLow, kHigh);
  if (!n) throw std::invalid_argument("hull fit: displaced volume " + std::to_string(targets.displaced_volume) + " m^3 needs a section coefficient outside [0.5, 1]");
  p.section_exponent = *n;
  return p;
}

ShipPreset section65Ship(double max_edge) {
  ShipPreset s;
  s.max_edge = max_edge;
  s.hull.length = 259.2;
  s.hull.beam = 31.6;
  s.hull.depth = 23.5;
  s.hull.draught = 12.0;
  s.hull.entrance_length = 0.40 * s.hull.length;
  s.hull.run_length = 0.15 * s.hull.length;
  s.hull.run_exponent = 2.0;
  s.targets.displaced_volume = 55000.0;
  // Sinkage 0.137 m per 1000 t: rho A_wp * 0.137 m = 1e6 kg.
  s.targets.waterplane_area = 1e6 / (s.water_density * 0.137);
  // No trim: rho V x_B = m x_G + (rho V - m) x_fairlead (cables' pull = buoyancy surplus,
  // taken as vertical at the keel fairleads).
  const double buoyant_mass = s.water_density * s.targets.displaced_volume;
  s.targets.lcb_from_bow = (s.mass * s.centre_of_mass.x() + (buoyant_mass - s.mass) * s.fairlead_from_bow) / buoyant_mass;
  s.hull = fitHull(s.hull, s.targets, max_edge);
  // Radii of gyration commonly assumed in seakeeping when the weight distribution is
  // unknown: roll 0.35 B, pitch and yaw 0.25 L. Hull axes: roll about x, yaw about y,
  // pitch about z.
  const double k_roll = 0.35 * s.hull.beam, k_pitch = 0.25 * s.hull.length;
  s.inertia = s.mass * Eigen::Vector3d(k_roll * k_roll, k_pitch * k_pitch, k_pitch * k_pitch);
  return s;
}

}  // namespace moorsph::io
