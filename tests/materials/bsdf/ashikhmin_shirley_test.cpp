// Ashikhmin-Shirley 2000 (anisotropic, with its diffuse term) and Ngan et al.'s isotropic
// variant: formulas at fixed directions against the paper written out here, the half-vector
// sampler against the paper's p(h), and the whole test kit over a grid with the hard corners.
#include <gtest/gtest.h>

#include <cmath>

#include "catalog_suite.h"
#include "materials/bsdf/ashikhmin_shirley.h"
#include "materials/registry/spec_validation.h"

namespace scatterlab {
namespace ashikhmin_shirley_test {

const std::vector<std::pair<Vec3d, Vec3d>>& pairs() {
  static const std::vector<std::pair<Vec3d, Vec3d>> p{
      {directionFromDegrees(0, 0), directionFromDegrees(8, 180)},
      {directionFromDegrees(30, 20), directionFromDegrees(40, 190)},
      {directionFromDegrees(60, 0), directionFromDegrees(50, 120)},
      {directionFromDegrees(80, 45), directionFromDegrees(75, 230)}};
  return p;
}

double schlick(double f0, double c) { return f0 + (1 - f0) * std::pow(1 - c, 5); }

TEST(AshikhminShirley, PaperModelMatchesEquations4And5) {
  const double nu = 30, nv = 300, rs = 0.2, rd = 0.6;
  const auto model = AshikhminShirleyBsdf::paper(nu, nv, Rgb(rs), Rgb(rd));
  for (const auto& [k1, k2] : pairs()) {
    const Vec3d h = glm::normalize(k1 + k2);
    const double phiH = std::atan2(h.y, h.x);
    const double hk = glm::dot(h, k1);
    const double specular =
        std::sqrt((nu + 1) * (nv + 1)) / (8 * Pi) *
        std::pow(h.z, nu * std::pow(std::cos(phiH), 2) + nv * std::pow(std::sin(phiH), 2)) /
        (hk * std::max(k1.z, k2.z)) * schlick(rs, hk);
    const double diffuse =
        28 * rd / (23 * Pi) * (1 - rs) * (1 - std::pow(1 - k1.z / 2, 5)) * (1 - std::pow(1 - k2.z / 2, 5));
    const double expected = specular + diffuse;
    EXPECT_NEAR(model.eval(k1, k2).y, expected, 1e-10 * expected);
    EXPECT_NEAR(model.eval(k2, k1).y, expected, 1e-10 * expected);  // reciprocal
  }
}

TEST(AshikhminShirley, NganVariantMatchesItsDefinition) {
  // alum-bronze, Ngan et al.'s fit: specular lobe only, scaled by the albedo.
  const double n = 1350, f0 = 0.249;
  const auto model = makeBsdf({{"type", "ngan-ashikhmin-shirley"},
                               {"albedo", {0.108, 0.0637, 0.0337}},
                               {"fresnelReflectance", f0},
                               {"sharpness", n}});
  for (const auto& [wi, wo0] : pairs()) {
    // Near the mirror direction, where the sharp lobe is not negligible.
    const Vec3d wo = glm::normalize(Vec3d(-wi.x, -wi.y, wi.z) + 0.02 * (wo0 - wi));
    const Vec3d h = glm::normalize(wi + wo);
    const double hk = glm::dot(h, wi);
    const double expected =
        (n + 1) / (8 * Pi) * std::pow(h.z, n) / (hk * std::max(wi.z, wo.z)) * schlick(f0, hk);
    const Rgb f = model->eval(wi, wo);
    EXPECT_NEAR(f.x, 0.108 * expected, 1e-9 * 0.108 * expected);
    EXPECT_NEAR(f.z, 0.0337 * expected, 1e-9 * 0.0337 * expected);
  }
}

// Eq. 9 maps the first quarter of u.x into the first quadrant of phi; the other quarters are
// its mirror images (the density, eq. 8, is checked by the kit's chi-square test).
TEST(AshikhminShirley, HalfVectorSamplerCoversEveryQuadrant) {
  const auto model = AshikhminShirleyBsdf::paper(10, 1000, Rgb(0.5), Rgb(0.5));
  for (double u : {0.1, 0.35, 0.6, 0.85}) {
    const Vec3d h = model.sampleHalfVector({u, 0.5});
    const int quadrant = int(4 * u);
    EXPECT_EQ(h.x > 0, quadrant == 0 || quadrant == 3) << u;
    EXPECT_EQ(h.y > 0, quadrant == 0 || quadrant == 1) << u;
    EXPECT_NEAR(glm::length(h), 1.0, 1e-14);
  }
}

TEST(AshikhminShirley, RegistryDefaultsBuild) {
  EXPECT_NO_THROW(makeBsdf({{"type", "ashikhmin-shirley"}}));
  EXPECT_NO_THROW(makeBsdf({{"type", "ngan-ashikhmin-shirley"}}));
  EXPECT_THROW(makeBsdf({{"type", "ashikhmin-shirley"}, {"exponent", -1}}), MaterialError);
  EXPECT_THROW(makeBsdf({{"type", "ngan-ashikhmin-shirley"}, {"fresnelReflectance", 2}}), MaterialError);
}

// ---- The kit ----

struct AsCase {
  bool ngan;
  double nu, nv, rs, rd;
};
std::string name(const AsCase& c) {
  return std::string(c.ngan ? "Ngan" : "Paper") + "_" + catalog_suite::number(c.nu) + "x" +
         catalog_suite::number(c.nv) + "_rs" + catalog_suite::number(c.rs);
}
void PrintTo(const AsCase& c, std::ostream* os) { *os << name(c); }
// Exponents from 0 (uniform half vectors) to 1e5; 800 x 1 is the anisotropy of alpha
// 0.05 x 0.8 (n ~ 2 / alpha^2 - 2).
std::vector<AsCase> grid() {
  return {{false, 0, 0, 1.0, 1.0},           {false, 10, 10, 0.05, 1.0}, {false, 1000, 1000, 1.0, 0.0},
          {false, 100000, 100000, 0.5, 0.5}, {false, 800, 1, 0.2, 0.8},  {true, 1, 1, 1.0, 0.0},
          {true, 78200, 78200, 0.999, 0.0}};
}
const catalog_suite::ChiSquareSuite Suite{"ashikhmin-shirley-kit",
                                          int(grid().size() * catalog_suite::incidentAngles().size())};

class AshikhminShirleyKit : public ::testing::TestWithParam<AsCase> {};

TEST_P(AshikhminShirleyKit, PassesEveryCheck) {
  const AsCase& c = GetParam();
  const auto model = c.ngan ? AshikhminShirleyBsdf::ngan(Rgb(1.0), c.rs, c.nu)
                            : AshikhminShirleyBsdf::paper(c.nu, c.nv, Rgb(c.rs), Rgb(c.rd));
  catalog_suite::expectPasses(model, name(c), Suite.options());
}

INSTANTIATE_TEST_SUITE_P(Grid, AshikhminShirleyKit, ::testing::ValuesIn(grid()),
                         [](const ::testing::TestParamInfo<AsCase>& info) { return name(info.param); });

// The kit must reject deliberately broken samplers of this model (docs/validation.md, "Negative controls").
struct ControlCase {
  const char* name;
  nlohmann::json material;
  double wiTheta;
};
void PrintTo(const ControlCase& c, std::ostream* os) { *os << c.name; }
class AshikhminShirleyNegativeControls : public ::testing::TestWithParam<ControlCase> {};
TEST_P(AshikhminShirleyNegativeControls, AreAllRejected) {
  catalog_suite::expectControlsRejected(Suite, GetParam().material, GetParam().wiTheta);
}
INSTANTIATE_TEST_SUITE_P(
    Controls, AshikhminShirleyNegativeControls,
    ::testing::Values(
        ControlCase{"Anisotropic_wi0",
                    {{"type", "ashikhmin-shirley"}, {"exponent", {200, 20}}, {"rs", 0.5}, {"rd", 0.3}},
                    0.0},
        ControlCase{"Ngan_wi60",
                    {{"type", "ngan-ashikhmin-shirley"}, {"fresnelReflectance", 0.5}, {"sharpness", 300}},
                    60.0}),
    [](const ::testing::TestParamInfo<ControlCase>& info) { return std::string(info.param.name); });

}  // namespace ashikhmin_shirley_test
}  // namespace scatterlab
