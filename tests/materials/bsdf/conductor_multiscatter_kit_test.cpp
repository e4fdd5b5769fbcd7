// The Kulla-Conty compensated conductor through the whole test kit (docs/validation.md sections
// 1-4): its sampler is a mixture (the single-scattering lobe with probability E(wi), the
// compensation lobe's tabulated sampler otherwise) with the exact mixture pdf, so chi-square,
// consistency and normalisation apply
// unchanged; white variants also get the kit's furnace row. Grid: GGX and Beckmann, visible
// and classic normals, alpha 0.001 .. 1 and 0.05 x 0.8, incident angles to 89.9 degrees; plus
// the negative controls, which the kit must reject.
#include <gtest/gtest.h>

#include "catalog_suite.h"
#include "materials/bsdf/conductor.h"
#include "materials/bsdf/metals.h"
#include "validation/negative_controls.h"

namespace scatterlab {
namespace conductor_multiscatter_kit_test {

struct Case {
  MicrofacetType type;
  MicrofacetSampling sampling;
  double alphaX, alphaY;
  bool white;                    // a perfect conductor (F = 1): lossless, so the kit adds its furnace row
  std::vector<double> angles{};  // incident polar angles, degrees
};

std::string name(const Case& c) {
  return std::string(c.type == MicrofacetType::Ggx ? "Ggx" : "Beckmann") +
         (c.sampling == MicrofacetSampling::Visible ? "Visible" : "Classic") + "_" +
         catalog_suite::number(c.alphaX) + "x" + catalog_suite::number(c.alphaY) +
         (c.white ? "_white" : "_gold");
}
void PrintTo(const Case& c, std::ostream* os) { *os << name(c); }

std::unique_ptr<BsdfModel> make(const Case& c, double alphaScale = 1.0) {
  const MetalIor* gold = findMetal("Au");
  return makeMicrofacetConductor(c.type, std::min(1.0, c.alphaX * alphaScale),
                                 std::min(1.0, c.alphaY * alphaScale), c.white ? Rgb(1.0) : gold->eta,
                                 c.white ? Rgb(1e8) : gold->k, c.sampling, MultipleScattering::KullaConty);
}

// The compensated model costs about twice the single-scattering one in the kit (two table
// lookups per evaluation), and the single-scattering lobe has its own full grid in
// conductor_kit_test.cpp; so each case here runs the angles that are hard for it: grazing
// incidence at the smallest roughness, where the compensation lobe lies within a degree of
// the horizon, normal and grazing at the largest (the white case gets the kit's furnace row),
// 60-89.9 degrees for anisotropy, where the per-material azimuthal table matters, and the
// classic normal sampler once in the mixture.
const std::vector<Case>& grid() {
  static const std::vector<Case> cases{
      {MicrofacetType::Ggx, MicrofacetSampling::Visible, 0.001, 0.001, false, {89.9}},
      {MicrofacetType::Ggx, MicrofacetSampling::Visible, 1.0, 1.0, true, {0, 89.9}},
      {MicrofacetType::Ggx, MicrofacetSampling::Visible, 0.05, 0.8, false, {60}},
      {MicrofacetType::Ggx, MicrofacetSampling::Classic, 0.3, 0.3, false, {85}},
      {MicrofacetType::Beckmann, MicrofacetSampling::Visible, 0.1, 0.1, false, {85}},
      {MicrofacetType::Beckmann, MicrofacetSampling::Visible, 0.05, 0.8, true, {89.9}},
  };
  return cases;
}

int gridChiSquareTests() {
  int count = 0;
  for (const Case& c : grid()) count += int(c.angles.size());
  return count;
}

const catalog_suite::ChiSquareSuite Suite{"conductor-multiscatter-kit", gridChiSquareTests()};

class ConductorMultiscatterKit : public ::testing::TestWithParam<Case> {};

TEST_P(ConductorMultiscatterKit, PassesEveryCheck) {
  BsdfCheckOptions o = Suite.options();
  o.wiThetaDeg = GetParam().angles;
  const auto model = make(GetParam());
  ASSERT_EQ(model->isLossless(), GetParam().white);
  catalog_suite::expectPasses(*model, name(GetParam()), o);
}

INSTANTIATE_TEST_SUITE_P(Grid, ConductorMultiscatterKit, ::testing::ValuesIn(grid()),
                         [](const ::testing::TestParamInfo<Case>& info) { return name(info.param); });

// Visible-normal sampling: the classic pdf is symmetric in wi and wo, and with the lobe chosen
// with probability E(wi) ~ 1 the swap would change the mixture too little to be seen.
struct ControlCase {
  Case conductor;
  double wiTheta;
};
void PrintTo(const ControlCase& c, std::ostream* os) { *os << name(c.conductor) << " at wi " << c.wiTheta; }

class ConductorMultiscatterNegativeControls : public ::testing::TestWithParam<ControlCase> {};

TEST_P(ConductorMultiscatterNegativeControls, AreAllRejected) {
  const ControlCase& c = GetParam();
  const auto model = make(c.conductor);
  const auto sampler = make(c.conductor, 1.1);  // alpha 10% larger in the sampler
  BsdfCheckOptions o = Suite.options();
  o.imageDir.reset();
  o.wiThetaDeg = {c.wiTheta};
  const CheckReport report = runNegativeControls(*model, sampler.get(), name(c.conductor), o);
  ASSERT_EQ(report.rows.size(), allNegativeControls().size());
  for (const CheckRow& row : report.rows) {
    EXPECT_TRUE(row.passed) << row.test << ": " << row.note;
    EXPECT_EQ(row.note.rfind("rejected", 0), 0u) << row.test << ": " << row.note;
  }
}

INSTANTIATE_TEST_SUITE_P(Controls, ConductorMultiscatterNegativeControls,
                         ::testing::Values(ControlCase{
                             {MicrofacetType::Ggx, MicrofacetSampling::Visible, 0.6, 0.2, false}, 60.0}),
                         [](const ::testing::TestParamInfo<ControlCase>& info) {
                           return name(info.param.conductor) + "_wi" +
                                  std::to_string(int(info.param.wiTheta));
                         });

}  // namespace conductor_multiscatter_kit_test
}  // namespace scatterlab
