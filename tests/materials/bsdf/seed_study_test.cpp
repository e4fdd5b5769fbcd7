// The repeated-seed study of the catalog suite (docs/validation.md section 1, "Size"): for models whose
// samplers differ in kind (visible-normal GGX, Ward's half-vector warp, a Blinn-Phong lobe over a diffuse
// term, anisotropic and grazing), a correct sampler tested with 300 seeds at alpha = 0.05 is rejected about
// 15 times, and its p-values are uniform. The catalog's fixed-seed kit tests then have the size they claim,
// not a lucky seed.
#include <gtest/gtest.h>

#include "catalog_suite.h"
#include "validation/bsdf_sampling.h"
#include "validation/seed_study.h"

namespace scatterlab {
namespace seed_study_test {

struct StudyCase {
  const char* name;
  nlohmann::json material;
  double wiTheta;
};
void PrintTo(const StudyCase& c, std::ostream* os) { *os << c.name; }

class CatalogSeedStudy : public ::testing::TestWithParam<StudyCase> {};

TEST_P(CatalogSeedStudy, RejectionRateIsAlphaAndPValuesAreUniform) {
  const auto model = makeBsdf(GetParam().material);
  const Vec3d wi = directionFromDegrees(GetParam().wiTheta, 30);
  constexpr int Runs = 300;
  const SeedStudyResult study = repeatedSeedStudy(
      bsdfDirectionSampler(*model, wi),
      [&](const Vec3d& wo) { return model->pdf(wi, wo, TransportMode::Radiance); }, SphericalGrid{16, 32},
      20000, Runs, 0.05, 5000);
  // Binomial(300, 0.05): mean 15, sd 3.77; 3.5 sd keeps a correct study's failure rate at 5e-4.
  EXPECT_LT(std::abs(study.rejectionZ()), 3.5) << study.rejected << " rejections in " << study.runs;
  // Kolmogorov-Smirnov against U(0, 1) at 0.001: D_crit = 1.95 / sqrt(300) = 0.113.
  EXPECT_LT(study.ksDistance(), 1.95 / std::sqrt(double(Runs)));
}

INSTANTIATE_TEST_SUITE_P(
    Grid, CatalogSeedStudy,
    ::testing::Values(
        StudyCase{"GgxConductor_wi45", {{"type", "conductor"}, {"alpha", 0.3}, {"metal", "Au"}}, 45.0},
        StudyCase{"AnisotropicWard_wi75", {{"type", "ward"}, {"alpha", {0.4, 0.1}}}, 75.0},
        StudyCase{
            "BlinnPhong_wi20", {{"type", "blinn-phong"}, {"kd", 0.4}, {"ks", 0.15}, {"exponent", 30}}, 20.0}),
    [](const ::testing::TestParamInfo<StudyCase>& info) { return std::string(info.param.name); });

}  // namespace seed_study_test
}  // namespace scatterlab
