// All six imposed-heave chain cases of refdata/moordyn_quasistatic_chain (depths 50,
// 200, 600 m; fairlead heave amplitudes 2 m (A1) and 5 m (A2), period 10 s) against the
// OrcaFlex fairlead tension series, with the line as MoorDyn's input files
// WD0050/0200/0600_Chain.txt define it (see refdata README):
//  - 82, 82 and 170 segments;
//  - BA given there as "-1": MoorDyn reads a negative BA as BA = zeta l sqrt(EA m) with
//    zeta = 1, which is HALF the critical damping of one segment on its node mass
//    (critical: 2 l sqrt(EA m)); so BA = l sqrt(EA m) here;
//  - seabed kBot = 1e5 Pa/m, cBot = 1e4 Pa s/m, friction 0.5; Cd 1.37, Ca 1, CaAx 0;
// with one correction, to the axial drag. The reference is OrcaFlex, whose studless
// chain has axial Cd 1.15 on an axial drag DIAMETER d_nom/pi (Orcina, OrcaFlex help,
// "Chain"), i.e. a force per length 1/2 rho 1.15 d_nom |v|v. MoorDyn's file converts
// only the diameter (0.64 = 1.15 / 1.8 for d_vol = 1.8 d_nom) and then applies it, as
// this model does, on the area pi d_vol l: pi times OrcaFlex's axial drag. Here
// CdAx = 0.64 / pi (= 1.15 d_nom / (pi d_vol) = 0.203). With MoorDyn's literal 0.64 the
// tension swing came out too large, by up to +19 % (600 m, 5 m) on the amplitude, and
// did not change with 2x the segments or half the step; with CdAx = 0 it was 9 % too
// small; docs/moorings.md records the figures.
// (An earlier version also used 40 segments, twice this internal damping and a 30x
// stiffer seabed.)
//
// Criteria: MoorDyn's own (tests/quasi_static_chain.cpp, "15 % error on the fairlead
// tension oscillation"): with dT = T(t) - T_static, ours from our initial static
// tension and the reference's from the quasi-static codes' value,
//   e = max_t |dT_ours - dT_ref| / (2 max_t |dT_ref|) < 0.15;
// and the stricter ratio of half peak-to-peak amplitudes, within 15 % as well.
#include <moorsph/bodies/lumped_mass_line.hpp>

#include <gtest/gtest.h>

#include "reference_data.hpp"

#include <stdexcept>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace mb = moorsph::bodies;

namespace {
constexpr double kPi = 3.14159265358979323846;

std::vector<std::vector<double>> readTsv(const std::string& rel) {
  const std::string path = moorsph::test::referenceDataPath("moordyn_quasistatic_chain/" + rel);
  std::ifstream in(path);
  std::vector<std::vector<double>> rows;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream ss(line);
    std::vector<double> row;
    double v;
    while (ss >> v) row.push_back(v);
    if (row.size() >= 4) rows.push_back(row);
  }
  return rows;
}

struct Case {
  const char* depth;
  double anchorX, anchorZ, length;
  int segments;            // NumSegs of the MoorDyn input
  double staticTension;    // kN, quasi-static reference used by MoorDyn's test
};
constexpr Case kCases[] = {{"0050", 400.0, -50.0, 410.0, 82, 991.6},
                           {"0200", 700.0, -200.0, 760.0, 82, 2065.4},
                           {"0600", 1500.0, -600.0, 1700.0, 170, 5232.6}};

mb::LumpedMassParams moorDynChain(const Case& c) {
  mb::LumpedMassParams p;
  p.length = c.length;
  p.segments = c.segments;
  p.massPerLength = 390.0;
  p.diameter = 0.252;
  p.axialStiffness = 1.674e9;
  p.internalDamping = (c.length / c.segments) * std::sqrt(p.axialStiffness * p.massPerLength);  // BA = -1
  p.cdNormal = 1.37;
  p.cdAxial = 0.64 / kPi;  // OrcaFlex axial drag diameter d/pi (header)
  p.caNormal = 1.0;
  p.caAxial = 0.0;
  p.waterDensity = 1025.0;
  p.gravity = Eigen::Vector3d(0.0, 0.0, -9.81);
  p.seabedStiffness = 1.0e5;
  p.seabedDamping = 1.0e4;
  p.seabedFriction = 0.5;
  p.relaxationTime = 200.0;  // TmaxIC
  p.relaxationDamping = 0.3;
  return p;
}

struct Result {
  double moorDynError;      // e above
  double amplitudeError;    // half peak-to-peak, ours/ref - 1
};

Result runCase(const Case& c, const std::string& amp) {
  const auto motion = readTsv("ZZP1_" + amp + ".tsv");
  const auto ref = readTsv(std::string("WD") + c.depth + "_Chain_ZZP1_" + amp + ".tsv");
  EXPECT_GT(motion.size(), 200u);
  EXPECT_GT(ref.size(), 150u);
  // Without the reference data (../shared/refdata or tests/data/refdata) stop here with that said, instead of
  // indexing empty series below (it crashed the test binary).
  if (motion.empty() || ref.empty())
    throw std::runtime_error("imposed heave chain: reference series for '" + amp + "' not found in refdata");
  mb::LumpedMassLine line(moorDynChain(c));
  mb::LineEnds a;
  a.anchor = Eigen::Vector3d(c.anchorX, 0.0, c.anchorZ);
  a.fairlead = Eigen::Vector3d(motion[0][1], motion[0][2], motion[0][3]);
  line.initialize(a);
  const double ourStatic = line.calcForces(a).fairleadTension / 1e3;
  double ourMin = 1e30, ourMax = -1e30, refMin = 1e30, refMax = -1e30, worst = 0.0, refSwing = 0.0;
  std::size_t j = 0, matched = 0;
  for (std::size_t r = 1; r < motion.size(); ++r) {  // t = -10 s ... 20 s, first 10 s unscored
    mb::LineEnds b = a;
    b.fairlead = Eigen::Vector3d(motion[r][1], motion[r][2], motion[r][3]);
    line.advance(motion[r][0] - motion[r - 1][0], a, b);
    a = b;
    while (j < ref.size() && ref[j][0] < motion[r][0] - 1e-6) ++j;
    if (j < ref.size() && std::abs(ref[j][0] - motion[r][0]) < 1e-6) {
      const double t = line.calcForces(a).fairleadTension / 1e3, tRef = ref[j][3];
      ourMin = std::min(ourMin, t);
      ourMax = std::max(ourMax, t);
      refMin = std::min(refMin, tRef);
      refMax = std::max(refMax, tRef);
      worst = std::max(worst, std::abs((t - ourStatic) - (tRef - c.staticTension)));
      refSwing = std::max(refSwing, std::abs(tRef - c.staticTension));
      ++matched;
    }
  }
  EXPECT_GT(matched, 150u);
  const double ours = 0.5 * (ourMax - ourMin), theirs = 0.5 * (refMax - refMin);
  const Result res{worst / (2.0 * refSwing), ours / theirs - 1.0};
  std::printf("[figure] chain WD%s %s (%d segments): static %.1f kN (quasi-static ref %.1f); MoorDyn error %.3f "
              "(worst %.1f kN over 2 x %.1f kN); amplitude %.1f vs %.1f kN (%+.1f%%)\n",
              c.depth, amp.c_str(), c.segments, ourStatic, c.staticTension, res.moorDynError, worst, refSwing, ours,
              theirs, 100.0 * res.amplitudeError);
  return res;
}

}  // namespace

TEST(ImposedHeaveChain, TwoMetreHeaveWithinFifteenPercentAtAllDepths) {
  for (const Case& c : kCases) {
    const Result r = runCase(c, "A1");
    EXPECT_LT(r.moorDynError, 0.15);
    EXPECT_LT(std::abs(r.amplitudeError), 0.15);
  }
}

TEST(ImposedHeaveChain, FiveMetreHeaveWithinFifteenPercentAtAllDepths) {
  for (const Case& c : kCases) {
    const Result r = runCase(c, "A2");
    EXPECT_LT(r.moorDynError, 0.15);
    EXPECT_LT(std::abs(r.amplitudeError), 0.15);
  }
}
