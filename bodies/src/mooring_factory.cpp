#include <moorsph/bodies/mooring_factory.hpp>

#include <moorsph/bodies/elastic_catenary.hpp>
#include <moorsph/bodies/lumped_mass_line.hpp>
#include <moorsph/bodies/tension_only_spring.hpp>

#include <cmath>
#include <stdexcept>

namespace moorsph::bodies {

namespace {
constexpr double kPi = 3.14159265358979323846;

double require(double value, const char* model, const char* name) {
  if (!std::isfinite(value)) {
    throw std::invalid_argument(std::string(model) + ": missing parameter '" + name + "'");
  }
  return value;
}

// k and L0 of a spring-type model: given directly, or from the line description.
void springFromLine(const MooringLineParams& p, const char* model, double& k, double& l0, double& t0) {
  k = std::isfinite(p.stiffness) ? p.stiffness
                                 : require(p.axialStiffness, model, "stiffness or axial_stiffness") /
                                       require(p.length, model, "length");
  t0 = p.pretension;
  l0 = std::isfinite(p.restLength) || std::isfinite(t0) ? p.restLength : require(p.length, model, "rest_length or length");
}

double submergedWeight(const MooringLineParams& p, const char* model) {
  const double area = 0.25 * kPi * p.diameter * p.diameter;
  return (require(p.massPerLength, model, "mass_per_length") - p.waterDensity * area) * p.gravity.norm();
}
}  // namespace

std::vector<std::string> mooringModelNames() {
  return {"tension_only_spring", "cable_path", "elastic_catenary", "lumped_mass"};
}

std::unique_ptr<MooringLine> makeMooringLine(const MooringLineParams& p) {
  std::unique_ptr<MooringLine> line;
  if (p.model == "tension_only_spring") {
    TensionOnlySpringParams s;
    springFromLine(p, "tension_only_spring", s.stiffness, s.restLength, s.pretension);
    s.damping = p.damping;
    line = std::make_unique<TensionOnlySpring>(s);
  } else if (p.model == "cable_path") {
    CablePathParams c;
    springFromLine(p, "cable_path", c.stiffness, c.restLength, c.pretension);
    c.dissipation = p.dissipation;
    c.viaPoints = p.viaPoints;
    line = std::make_unique<CablePathLine>(c);
  } else if (p.model == "elastic_catenary") {
    ElasticCatenaryParams c;
    c.length = require(p.length, "elastic_catenary", "length");
    c.axialStiffness = require(p.axialStiffness, "elastic_catenary", "axial_stiffness");
    c.weightPerLength = submergedWeight(p, "elastic_catenary");
    c.seabedFriction = p.seabedFriction;
    c.anchorOnSeabed = p.anchorOnSeabed;
    c.up = -p.gravity.normalized();
    line = std::make_unique<ElasticCatenary>(c);
  } else if (p.model == "lumped_mass") {
    LumpedMassParams l;
    l.length = require(p.length, "lumped_mass", "length");
    l.axialStiffness = require(p.axialStiffness, "lumped_mass", "axial_stiffness");
    l.massPerLength = require(p.massPerLength, "lumped_mass", "mass_per_length");
    l.diameter = p.diameter;
    l.waterDensity = p.waterDensity;
    l.waterSurfaceHeight = p.waterSurfaceHeight;
    l.bendingStiffness = p.bendingStiffness;
    l.gravity = p.gravity;
    l.segments = p.segments;
    l.internalDampingRatio = p.internalDampingRatio;
    l.cdNormal = p.cdNormal;
    l.cdAxial = p.cdAxial;
    l.caNormal = p.caNormal;
    l.caAxial = p.caAxial;
    l.seabed = p.anchorOnSeabed;
    l.seabedFriction = p.seabedFriction;
    l.timeStep = p.timeStep;
    l.relaxationTime = p.relaxationTime;
    line = std::make_unique<LumpedMassLine>(l);
  } else {
    std::string names;
    for (const std::string& n : mooringModelNames()) names += (names.empty() ? "" : ", ") + n;
    throw std::invalid_argument("unknown mooring model '" + p.model + "' (valid: " + names + ")");
  }
  line->setBreakingLoad(p.breakingLoad);
  return line;
}

}  // namespace moorsph::bodies
