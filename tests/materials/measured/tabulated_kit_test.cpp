// The tabulated BRDF's own sampler through the whole test kit (docs/validation.md section 5: the
// same chi-square, consistency and normalisation checks as the analytic models, against the
// tabulated pdf), on measured-style tables of published fits: a near-mirror metal (chrome,
// Beckmann roughness 0.009), a glossy plastic and a broad, mostly diffuse felt; incident angles
// up to 89.9 degrees; one odd grid. The negative controls must be rejected, and the sampler
// must beat cosine sampling on a specular material by more than 10x in variance.
#include <gtest/gtest.h>

#include <cstdio>

#include "materials/core/rng.h"
#include "materials/core/warp.h"
#include "materials/measured/tabulated_brdf.h"
#include "measured_test_support.h"
#include "validation/bsdf_check.h"
#include "validation/negative_controls.h"

namespace scatterlab {
namespace tabulated_kit_test {

using nlohmann::json;

struct KitCase {
  std::string material;  // a line of ngan_cooktorrance.fit
  std::vector<double> angles;
};
void PrintTo(const KitCase& c, std::ostream* os) { *os << c.material; }

const std::vector<KitCase>& kitCases() {
  static const std::vector<KitCase> cases{
      {"chrome", {0, 45, 85, 89.9}},
      {"red-plastic", {30, 89.9}},
      {"pink-felt", {60}},
  };
  return cases;
}
constexpr int OddGridTests = 1;

// Sidak over every chi-square test of a correct sampler in this file.
int suiteChiSquareTests() {
  int n = OddGridTests;
  for (const KitCase& c : kitCases()) n += int(c.angles.size());
  return n;
}

BsdfCheckOptions suiteOptions(const std::vector<double>& angles) {
  BsdfCheckOptions o;
  o.wiThetaDeg = angles;
  o.samples = 1'000'000;
  o.thetaBins = 64;
  o.phiBins = 128;
  o.seed = 2024;
  o.chiSquareTestCount = suiteChiSquareTests();
  o.reciprocityPairs = 20000;
  o.imageDir = std::filesystem::path(SCATTERLAB_TEST_OUTPUT_DIR) / "tabulated-kit";
  o.imagesOnFailureOnly = true;
  return o;
}

// The tabulated model of a published fit, with its Cook-Torrance roughness scaled.
std::unique_ptr<TabulatedBrdf> tabulatedFit(const std::string& name, double roughnessScale = 1.0) {
  std::vector<json> components = measured_test::publishedFit(name);
  components.at(1)["roughness"] = components.at(1)["roughness"].get<double>() * roughnessScale;
  return std::make_unique<TabulatedBrdf>(measured_test::synthesise(components).table);
}

void printChiSquare(const CheckReport& report) {
  for (const CheckRow& row : report.rows)
    if (row.test == "chi2")
      std::printf("[ chi2 ] %s wi %5.1f: chi2 %.1f dof %d p %.3f\n", row.material.c_str(),
                  row.wiThetaDeg.value_or(-1), row.statistic, row.dof.value_or(0), row.pValue.value_or(-1));
}

class TabulatedKit : public ::testing::TestWithParam<KitCase> {};

TEST_P(TabulatedKit, PassesEveryCheck) {
  const auto model = tabulatedFit(GetParam().material);
  const CheckReport report = runBsdfChecks(*model, GetParam().material, suiteOptions(GetParam().angles));
  printChiSquare(report);
  EXPECT_TRUE(report.passed()) << formatTable(report);
}

INSTANTIATE_TEST_SUITE_P(PublishedFits, TabulatedKit, ::testing::ValuesIn(kitCases()),
                         [](const ::testing::TestParamInfo<KitCase>& info) {
                           std::string name = info.param.material;
                           std::erase(name, '-');
                           return name;
                         });

// An odd grid, so that the highlight does not always sit on a cell edge.
TEST(TabulatedKitOddGrid, ChromePassesOn37x83) {
  BsdfCheckOptions o = suiteOptions({45});
  o.thetaBins = 37;
  o.phiBins = 83;
  const CheckReport report = runBsdfChecks(*tabulatedFit("chrome"), "chrome", o);
  printChiSquare(report);
  EXPECT_TRUE(report.passed()) << formatTable(report);
}

// Every control is rejected. The roughness-mismatch control samples from the table of the
// same fit with a 10% larger roughness.
struct ControlCase {
  std::string material;
  double wiTheta;
};
void PrintTo(const ControlCase& c, std::ostream* os) { *os << c.material << " at wi " << c.wiTheta; }

class TabulatedNegativeControls : public ::testing::TestWithParam<ControlCase> {};

TEST_P(TabulatedNegativeControls, AreAllRejected) {
  const ControlCase& c = GetParam();
  const auto model = tabulatedFit(c.material);
  const auto rougher = tabulatedFit(c.material, 1.1);
  const CheckReport report =
      runNegativeControls(*model, rougher.get(), c.material, suiteOptions({c.wiTheta}));
  ASSERT_EQ(report.rows.size(), allNegativeControls().size());
  for (const CheckRow& row : report.rows) {
    EXPECT_TRUE(row.passed) << row.test << ": " << row.note;
    EXPECT_EQ(row.note.rfind("rejected", 0), 0u) << row.test << ": " << row.note;
  }
}

INSTANTIATE_TEST_SUITE_P(Kit, TabulatedNegativeControls,
                         ::testing::Values(ControlCase{"chrome", 30.0}, ControlCase{"red-plastic", 75.0}),
                         [](const ::testing::TestParamInfo<ControlCase>& info) {
                           std::string name = info.param.material;
                           std::erase(name, '-');
                           return name + "_wi" + std::to_string(int(info.param.wiTheta));
                         });

// ---- Efficiency -----------------------------------------------------------------------------

// Per-sample variance of the directional-albedo estimator f cos / pdf (channel mean).
template <typename Sampler> double albedoEstimatorVariance(Sampler sample, uint64_t seed) {
  constexpr int N = 200000;
  double sum = 0, sum2 = 0;
  for (int i = 0; i < N; ++i) {
    CounterRng rng(seed, uint64_t(i));
    const double uLobe = rng.uniform();
    const double x = sample(uLobe, rng.uniform2D());
    sum += x;
    sum2 += x * x;
  }
  const double mean = sum / N;
  return sum2 / N - mean * mean;
}

double varianceRatio(const TabulatedBrdf& brdf, double wiTheta) {
  const Vec3d wi = directionFromDegrees(wiTheta, 0);
  const auto mean = [](const Rgb& v) { return (v.x + v.y + v.z) / 3.0; };
  const double tabulated = albedoEstimatorVariance(
      [&](double uLobe, const Vec2d& u) {
        const auto s = brdf.sample(wi, uLobe, u);
        return s ? mean(s->weight) : 0.0;
      },
      1);
  const double cosine = albedoEstimatorVariance(
      [&](double, const Vec2d& u) {
        const Vec3d wo = sampleCosineHemisphere(u);
        return wo.z > 0 ? mean(brdf.eval(wi, wo)) * Pi : 0.0;  // f cos / (cos / pi)
      },
      2);
  return cosine / tabulated;
}

TEST(TabulatedSamplerEfficiency, BeatsCosineSamplingOnSpecularMaterials) {
  for (const auto& [name, minimum] :
       {std::pair<std::string, double>{"chrome", 1000.0}, {"gray-plastic", 10.0}}) {
    const auto brdf = tabulatedFit(name);
    for (double wiTheta : {0.0, 45.0, 80.0}) {
      const double ratio = varianceRatio(*brdf, wiTheta);
      std::printf(
          "[ efficiency ] %s wi %.0f: variance with cosine sampling / with the table's sampler = %.1f\n",
          name.c_str(), wiTheta, ratio);
      EXPECT_GT(ratio, minimum) << name << " wi " << wiTheta;
    }
  }
}

}  // namespace tabulated_kit_test
}  // namespace scatterlab
