// Ngan et al. 2005's Cook-Torrance: the formula at fixed directions against Ngan's definition
// written out here (Beckmann, V-groove, Schlick with F0 = "eta", pi normalisation, albedo),
// and the whole test kit over a grid with the hard corners.
#include <gtest/gtest.h>

#include <cmath>

#include "catalog_suite.h"
#include "materials/bsdf/cook_torrance.h"
#include "materials/registry/spec_validation.h"

namespace scatterlab {
namespace cook_torrance_test {

TEST(NganCookTorrance, MatchesNgansDefinition) {
  const double m = 0.0367, f0 = 0.203;  // alum-bronze, Ngan et al.'s fit
  const auto model = makeBsdf(
      {{"type", "ngan-cook-torrance"}, {"albedo", {0.118, 0.0698, 0.0371}}, {"eta", f0}, {"roughness", m}});
  const std::vector<std::pair<Vec3d, Vec3d>> pairs{
      {directionFromDegrees(0, 0), directionFromDegrees(3, 180)},
      {directionFromDegrees(30, 20), directionFromDegrees(32, 195)},
      {directionFromDegrees(70, 0), directionFromDegrees(72, 178)},
      {directionFromDegrees(85, 45), directionFromDegrees(87, 222)}};
  for (const auto& [wi, wo] : pairs) {
    const Vec3d h = glm::normalize(wi + wo);
    const double alpha = std::acos(h.z);  // angle between h and n
    const double d =
        std::exp(-std::pow(std::tan(alpha) / m, 2)) / (Pi * m * m * std::pow(std::cos(alpha), 4));
    const double c = glm::dot(wi, h);
    const double g = std::min({1.0, 2 * h.z * wo.z / c, 2 * h.z * wi.z / c});
    const double fresnel = f0 + (1 - f0) * std::pow(1 - c, 5);
    const double expected = d * g * fresnel / (Pi * wi.z * wo.z);
    const Rgb f = model->eval(wi, wo);
    EXPECT_NEAR(f.x, 0.118 * expected, 1e-9 * 0.118 * expected);
    EXPECT_NEAR(f.z, 0.0371 * expected, 1e-9 * 0.0371 * expected);
    // Reciprocal: every factor is symmetric.
    EXPECT_NEAR(model->eval(wo, wi).x, f.x, 1e-12 * f.x);
  }
}

TEST(NganCookTorrance, VGrooveShadowsAtGrazing) {
  const Vec3d wi = directionFromDegrees(88, 0), wo = directionFromDegrees(60, 180);
  const Vec3d h = glm::normalize(wi + wo);
  EXPECT_NEAR(vGrooveShadowing(wi, wo, h), 2 * h.z * wi.z / glm::dot(wi, h), 1e-14);
  EXPECT_LT(vGrooveShadowing(wi, wo, h), 1.0);
}

TEST(NganCookTorrance, RegistryDefaultsBuild) {
  EXPECT_NO_THROW(makeBsdf({{"type", "ngan-cook-torrance"}}));
  EXPECT_THROW(makeBsdf({{"type", "ngan-cook-torrance"}, {"eta", 1.5}}), MaterialError);
  EXPECT_THROW(makeBsdf({{"type", "ngan-cook-torrance"}, {"roughness", 0.0}}), MaterialError);
}

// ---- The kit ----

// Cook's pi normalisation reflects up to 4/pi of the albedo (near-mirror lobes, F0 = 1); the
// kit's albedo <= 1 therefore runs at albedo 0.75 < pi/4.
constexpr double KitAlbedo = 0.75;

struct CookTorranceCase {
  double f0, roughness;
};
std::string name(const CookTorranceCase& c) {
  return "F0_" + catalog_suite::number(c.f0) + "_m" + catalog_suite::number(c.roughness);
}
void PrintTo(const CookTorranceCase& c, std::ostream* os) { *os << name(c); }
std::vector<CookTorranceCase> grid() {
  return {{1.0, 0.001}, {0.05, 0.01}, {1.0, 0.1}, {0.5, 0.3}, {1.0, 1.0}};
}
const catalog_suite::ChiSquareSuite Suite{"cook-torrance-kit",
                                          int(grid().size() * catalog_suite::incidentAngles().size())};

class NganCookTorranceKit : public ::testing::TestWithParam<CookTorranceCase> {};

TEST_P(NganCookTorranceKit, PassesEveryCheck) {
  const NganCookTorranceBsdf model(Rgb(KitAlbedo), GetParam().f0, GetParam().roughness);
  catalog_suite::expectPasses(model, name(GetParam()), Suite.options());
}

INSTANTIATE_TEST_SUITE_P(Grid, NganCookTorranceKit, ::testing::ValuesIn(grid()),
                         [](const ::testing::TestParamInfo<CookTorranceCase>& info) {
                           return name(info.param);
                         });

// The kit must reject deliberately broken samplers of this model (docs/validation.md, "Negative controls").
struct ControlCase {
  const char* name;
  nlohmann::json material;
  double wiTheta;
};
void PrintTo(const ControlCase& c, std::ostream* os) { *os << c.name; }
class NganCookTorranceNegativeControls : public ::testing::TestWithParam<ControlCase> {};
TEST_P(NganCookTorranceNegativeControls, AreAllRejected) {
  catalog_suite::expectControlsRejected(Suite, GetParam().material, GetParam().wiTheta);
}
INSTANTIATE_TEST_SUITE_P(
    Controls, NganCookTorranceNegativeControls,
    ::testing::Values(
        ControlCase{"Rough_wi45",
                    {{"type", "ngan-cook-torrance"}, {"albedo", 0.7}, {"eta", 0.5}, {"roughness", 0.3}},
                    45.0},
        ControlCase{"Sharp_wi80",
                    {{"type", "ngan-cook-torrance"}, {"albedo", 0.7}, {"eta", 0.9}, {"roughness", 0.05}},
                    80.0}),
    [](const ::testing::TestParamInfo<ControlCase>& info) { return std::string(info.param.name); });

}  // namespace cook_torrance_test
}  // namespace scatterlab
