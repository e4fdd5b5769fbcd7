// The rough dielectric through the whole test kit (docs/validation.md sections 1-4), from both
// sides of the interface: GGX and Beckmann, alpha 0.001 .. 1 and anisotropy 0.05 x 0.8,
// eta 1.1 / 1.5 / 2.4, incident angles 0 .. 89.9 degrees from outside and (the kit adds them
// for transmission) 180 - theta from inside, where eta < 1 and total internal reflection
// happen. Plus the negative controls, from both sides.
//
// Cost, and what it buys: a kit run on this model costs ~3x a conductor's (both hemispheres
// carry a lobe, both transport modes are checked), dominated by the quadrature of the
// expected counts, which scales with the number of cells. So the grid runs 2.5e5 samples on
// 32 x 64 and (odd, so that no peak always sits on a cell edge) 37 x 71 cells, and is not
// the full product of the parameters: every distribution meets alpha 0.001, alpha 1 and the
// anisotropic 0.05 x 0.8, and eta 1.1, 1.5 and 2.4 each appear with both distributions'
// corners. Moderate roughness runs through the whole kit in tests/validation/
// transmission_kit_test.cpp and in the negative controls below, which keep 1e6 samples.
#include <gtest/gtest.h>

#include "catalog_suite.h"
#include "materials/bsdf/rough_dielectric.h"

namespace scatterlab {
namespace rough_dielectric_kit_test {

using nlohmann::json;

struct DielectricCase {
  const char* distribution;
  double alphaX, alphaY, eta;
};

std::string name(const DielectricCase& c) {
  return std::string(c.distribution) + "_" + catalog_suite::number(c.alphaX) + "x" +
         catalog_suite::number(c.alphaY) + "_eta" + catalog_suite::number(c.eta);
}
void PrintTo(const DielectricCase& c, std::ostream* os) { *os << name(c); }

json material(const DielectricCase& c) {
  return {{"type", "rough-dielectric"},
          {"distribution", c.distribution},
          {"alpha", {c.alphaX, c.alphaY}},
          {"eta", c.eta}};
}

const std::vector<DielectricCase>& grid() {
  static const std::vector<DielectricCase> cases{
      {"ggx", 0.001, 0.001, 1.5},      {"ggx", 1.0, 1.0, 2.4},      {"ggx", 0.05, 0.8, 1.1},
      {"beckmann", 0.001, 0.001, 2.4}, {"beckmann", 1.0, 1.0, 1.1}, {"beckmann", 0.8, 0.05, 1.5},
  };
  return cases;
}

// Incident angles: normal, oblique and grazing from outside; the kit mirrors them to 180,
// 120 and 90.1 degrees (inside, 120 is beyond the critical angle for eta >= 1.16, so mostly
// total internal reflection), and 150 adds a refraction-dominated angle from inside.
const std::vector<double> IncidentAngles{0, 60, 89.9, 150};
constexpr int AnglesPerCase = 7;

constexpr size_t GridSamples = 250'000;

const catalog_suite::ChiSquareSuite Suite{"rough-dielectric-kit", int(grid().size()) * AnglesPerCase};

class RoughDielectricKit : public ::testing::TestWithParam<DielectricCase> {};

TEST_P(RoughDielectricKit, PassesEveryCheckFromBothSides) {
  const auto model = makeBsdf(material(GetParam()));
  BsdfCheckOptions o = Suite.options();
  o.wiThetaDeg = IncidentAngles;
  o.samples = GridSamples;
  const bool odd = GetParam().alphaX != GetParam().alphaY;  // the anisotropic cases
  o.thetaBins = odd ? 37 : 32;
  o.phiBins = odd ? 71 : 64;
  ASSERT_EQ(incidentAngles(o, *model), (std::vector<double>{0, 60, 89.9, 150, 180, 120, 90.1}));
  ASSERT_EQ(chiSquareTestCount(o, *model), AnglesPerCase);
  catalog_suite::expectPasses(*model, name(GetParam()), o);
}

INSTANTIATE_TEST_SUITE_P(Grid, RoughDielectricKit, ::testing::ValuesIn(grid()),
                         [](const ::testing::TestParamInfo<DielectricCase>& info) {
                           return name(info.param);
                         });

// The negative controls at one incident angle (above 90: from inside). Every control must be
// rejected: none of them is a no-op for this model (its pdf is not symmetric in wi and wo,
// the sampler depends on alpha, and the Jacobian is there in both lobes).
struct ControlCase {
  DielectricCase dielectric;
  double wiTheta;
};
void PrintTo(const ControlCase& c, std::ostream* os) { *os << name(c.dielectric) << " at wi " << c.wiTheta; }

class RoughDielectricNegativeControls : public ::testing::TestWithParam<ControlCase> {};

TEST_P(RoughDielectricNegativeControls, AreAllRejected) {
  const ControlCase& c = GetParam();
  const json m = material(c.dielectric);
  const auto model = makeBsdf(m);
  const auto sampler = makeBsdf(*withMismatchedRoughness(m, 1.1));
  BsdfCheckOptions o = Suite.options();
  o.wiThetaDeg = {c.wiTheta};
  o.transmissionFromBelow = false;  // the side is the case's
  o.thetaBins = 32;                 // coarser cells hold more samples each: no loss of power for these errors
  o.phiBins = 64;
  o.imageDir.reset();
  const CheckReport report = runNegativeControls(*model, sampler.get(), name(c.dielectric), o);
  ASSERT_EQ(report.rows.size(), allNegativeControls().size());
  for (const CheckRow& row : report.rows) {
    EXPECT_TRUE(row.passed) << row.test << ": " << row.note;
    EXPECT_EQ(row.note.rfind("rejected", 0), 0u) << row.test << ": " << row.note;
  }
}

INSTANTIATE_TEST_SUITE_P(Controls, RoughDielectricNegativeControls,
                         ::testing::Values(ControlCase{{"ggx", 0.3, 0.1, 1.5}, 60.0},
                                           ControlCase{{"ggx", 0.3, 0.1, 1.5}, 150.0},
                                           ControlCase{{"beckmann", 0.2, 0.2, 2.4}, 120.0}),
                         [](const ::testing::TestParamInfo<ControlCase>& info) {
                           return name(info.param.dielectric) + "_wi" +
                                  std::to_string(int(info.param.wiTheta));
                         });

}  // namespace rough_dielectric_kit_test
}  // namespace scatterlab
