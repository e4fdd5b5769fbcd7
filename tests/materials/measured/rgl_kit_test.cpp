// The RGL model's own sampler (the file's luminance and vndf warps) through the whole test kit
// (docs/validation.md sections 1-4) at every incident elevation the shipped files tabulate
// and between them, and the negative controls rejected (docs/references.md, "RGL measured
// BRDFs"). The full sweep is a Grid/ instantiation (release pass only); one angle per file runs
// in every pass.
#include <gtest/gtest.h>

#include <cstdio>

#include "materials/measured/rgl_brdf.h"
#include "materials/measured/rgl_synthesis.h"
#include "materials/registry/spec_validation.h"
#include "validation/bsdf_check.h"
#include "validation/negative_controls.h"

namespace scatterlab {
namespace rgl_kit_test {

const std::filesystem::path RglDir = std::filesystem::path(SCATTERLAB_DATA_DIR) / "rgl";

struct KitCase {
  std::string file;
  std::vector<double> angles;  // degrees
};

// The two files tabulate theta_i at 0, ~29, ~41, ~51, ~61, ~70, ~79 and 90 degrees: every node
// (90 as 89.5: at 90 wi lies in the surface) and the midpoints between them.
std::vector<double> sweepAngles(const std::string& file) {
  const TensorFile tensor = readTensorFile(RglDir / (file + ".bsdf"));
  std::vector<double> nodes;
  for (double theta : tensor.find("theta_i")->values()) nodes.push_back(std::min(degrees(theta), 89.5));
  std::vector<double> angles;
  for (size_t i = 0; i < nodes.size(); ++i) {
    angles.push_back(nodes[i]);
    if (i + 1 < nodes.size()) angles.push_back(0.5 * (nodes[i] + nodes[i + 1]));
  }
  return angles;
}

std::string caseName(const std::string& file) { return file.starts_with("cc_ibiza") ? "Ibiza" : "Felt"; }

// The sweeps (15 angles per file), the two quick cases and the synthesised file.
constexpr int SuiteChiSquareTests = 2 * 15 + 2 + 1;

BsdfCheckOptions suiteOptions(const std::vector<double>& angles) {
  BsdfCheckOptions o;
  o.wiThetaDeg = angles;
  o.samples = 1'000'000;
  o.seed = 2018;
  o.chiSquareTestCount = SuiteChiSquareTests;
  o.imageDir = std::filesystem::path(SCATTERLAB_TEST_OUTPUT_DIR) / "rgl-kit";
  o.imagesOnFailureOnly = true;
  return o;
}

void expectPasses(const std::string& file, const BsdfCheckOptions& options) {
  const auto brdf = readRglBrdf(RglDir / (file + ".bsdf"));
  const CheckReport report = runBsdfChecks(*brdf, file, options);
  for (const CheckRow& row : report.rows)
    if (row.test == "chi2")
      std::printf("[ chi2 ] %s wi %5.1f: chi2 %.1f dof %d p %.3f\n", file.c_str(),
                  row.wiThetaDeg.value_or(-1), row.statistic, row.dof.value_or(0), row.pValue.value_or(-1));
  EXPECT_TRUE(report.passed()) << formatTable(report);
}

class RglKit : public ::testing::TestWithParam<std::string> {};

// The sweep takes a quarter of the samples on a quarter of the cells (32 x 64, about 120 samples
// per cell where the lobe is) to keep its 30 checks at a few CPU seconds each.
TEST_P(RglKit, PassesAtEveryTabulatedAngleAndBetween) {
  const std::vector<double> angles = sweepAngles(GetParam());
  ASSERT_EQ(angles.size(), 15u);
  BsdfCheckOptions options = suiteOptions(angles);
  options.samples = 250'000;
  options.thetaBins = 32;
  options.phiBins = 64;
  expectPasses(GetParam(), options);
}

INSTANTIATE_TEST_SUITE_P(Grid, RglKit, ::testing::Values("acrylic_felt_green_rgb", "cc_ibiza_sunset_rgb"),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           return caseName(info.param);
                         });

TEST(RglKitQuick, GlossyVinylAt45Degrees) { expectPasses("cc_ibiza_sunset_rgb", suiteOptions({45})); }
TEST(RglKitQuick, FeltAt70Degrees) { expectPasses("acrylic_felt_green_rgb", suiteOptions({70})); }

// The applicable controls are rejected; an RGL file has no roughness to mismatch, so that
// control is reported as not applicable.
struct ControlCase {
  std::string file;
  double wiTheta;
};

class RglNegativeControls : public ::testing::TestWithParam<ControlCase> {};

TEST_P(RglNegativeControls, AreRejected) {
  const auto brdf = readRglBrdf(RglDir / (GetParam().file + ".bsdf"));
  const CheckReport report =
      runNegativeControls(*brdf, nullptr, GetParam().file, suiteOptions({GetParam().wiTheta}));
  ASSERT_EQ(report.rows.size(), allNegativeControls().size());
  int rejected = 0;
  for (const CheckRow& row : report.rows) {
    EXPECT_TRUE(row.passed) << row.test << ": " << row.note;
    if (row.test == "control " + toString(NegativeControl::RoughnessMismatch) ||
        row.note.find("not applicable") != std::string::npos)
      continue;
    EXPECT_EQ(row.note.rfind("rejected", 0), 0u) << row.test << ": " << row.note;
    ++rejected;
  }
  EXPECT_EQ(rejected, 3);
}

INSTANTIATE_TEST_SUITE_P(Controls, RglNegativeControls,
                         ::testing::Values(ControlCase{"cc_ibiza_sunset_rgb", 30.0},
                                           ControlCase{"acrylic_felt_green_rgb", 60.0}),
                         [](const ::testing::TestParamInfo<ControlCase>& info) {
                           return caseName(info.param.file) + "At" + std::to_string(int(info.param.wiTheta));
                         });

// Anisotropic and spectral files made by the writer pass the kit too: the reader's warps over
// a 9 x 4 incident grid and a spectral colour table.
TEST(RglKitSynthesised, AnisotropicFilePasses) {
  const auto model =
      makeBsdf({{"type", "conductor"}, {"metal", "Au"}, {"distribution", "ggx"}, {"alpha", {0.15, 0.4}}});
  RglSynthesisOptions options;
  options.phiI.clear();
  for (int i = 0; i < 9; ++i) options.phiI.push_back(-Pi + 2 * Pi * i / 8);
  options.thetaI = {0.0, 0.5, 0.9, 1.2};
  options.vndfResolution = 32;
  options.colourResolution = 12;
  const RglBrdf brdf(synthesizeRglFile(modelChannels(*model), options), "anisotropic");
  BsdfCheckOptions o = suiteOptions({40});
  o.wiPhiDeg = 60;
  const CheckReport report = runBsdfChecks(brdf, "anisotropic", o);
  EXPECT_TRUE(report.passed()) << formatTable(report);
}

}  // namespace rgl_kit_test
}  // namespace scatterlab
