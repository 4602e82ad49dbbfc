// One line description, the model swapped by one word: every model is built, reports
// its name, and for a light taut line (where the catenary sag is negligible) all of
// them agree with the spring closed form T = (EA/L)(span - L) to within the sag effect.
#include <moorsph/bodies/mooring_factory.hpp>
#include <moorsph/bodies/multibody_system.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace mb = moorsph::bodies;

TEST(MooringFactory, EveryModelWordBuildsThatModel) {
  mb::MooringLineParams p;
  p.length = 100.0;
  p.axialStiffness = 1e7;
  p.massPerLength = 1.0;
  p.diameter = 0.01;
  for (const std::string& name : mb::mooringModelNames()) {
    p.model = name;
    EXPECT_EQ(mb::makeMooringLine(p)->modelName(), name);
  }
  p.model = "catenary";
  try {
    mb::makeMooringLine(p);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("elastic_catenary"), std::string::npos);
  }
  p.model = "elastic_catenary";
  p.length = std::nan("");
  EXPECT_THROW(mb::makeMooringLine(p), std::invalid_argument);
}

TEST(MooringFactory, SwappingTheWordKeepsATautLightLineConsistent) {
  // 100 m line, EA 1e7 N, 1 kg/m in water; span 101 m horizontal and 0 vertical
  // above a far seabed: T ~ 1e7 * 0.01 = 1e5 N, weight 1e3 N, sag effect < 1e-3.
  mb::MooringLineParams p;
  p.length = 100.0;
  p.axialStiffness = 1e7;
  p.massPerLength = 1.0;
  p.waterDensity = 0.0;
  p.anchorOnSeabed = false;
  p.segments = 20;
  p.relaxationTime = 20.0;
  const double expected = 1e7 * 0.01;
  for (const std::string& name : mb::mooringModelNames()) {
    p.model = name;
    mb::MultibodySystem sys;
    mb::RigidBodySpec body;
    body.mass = 1e3;
    body.inertiaAboutCom = Eigen::Matrix3d::Identity();
    body.initial.position = Eigen::Vector3d(101.0, 0.0, 0.0);
    sys.addBody(body);
    sys.addLine("line", mb::LineAttachment{}, mb::makeMooringLine(p));
    sys.initialize();
    const double t = sys.lineDiagnostics(0).fairleadTension;
    std::printf("[figure] %-20s fairlead tension %.2f N (spring closed form %.2f N)\n", name.c_str(), t, expected);
    EXPECT_NEAR(t, expected, 2e-3 * expected) << name;
  }
}
