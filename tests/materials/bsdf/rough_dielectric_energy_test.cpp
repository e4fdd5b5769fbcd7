// The rough dielectric's single-scattering energy (docs/validation.md section 3: a lossy
// model says how much it loses). Light that scatters more than once among the microfacets is not in
// the model, so the directional albedo E = E_R + E_T (importance transport: power) falls
// below 1 as alpha grows, from outside and inside, and isLossless() is false. Energy
// compensation (Kulla & Conty 2017) is the "multiscatter": "kulla-conty" option
// (rough_dielectric_multiscatter.h), which tabulates exactly these E
// (rough_dielectric_multiscatter_test.cpp checks its tables against this table's points).
//
// E comes from rough_dielectric_albedo.h (quadrature over the visible-normal sample square);
// here it is checked against an independent estimate, a quadrature of f |cos wo| over the
// sphere of wo, reflection and transmission apart, and the whole table is printed.
#include <gtest/gtest.h>

#include <cstdio>

#include "materials/bsdf/rough_dielectric_albedo.h"
#include "validation/chi_square.h"

namespace scatterlab {
namespace rough_dielectric_energy_test {

constexpr double Eta = 1.5;
const std::vector<double> Alphas{0.1, 0.3, 0.6, 1.0};
// From outside (< 90) and from inside (> 90; 120 and 100 are beyond the critical angle).
const std::vector<double> Angles{0, 30, 60, 80, 180, 150, 120, 100};

// E_R and E_T by adaptive quadrature of eval |cos wo| over 16 x 32 cells of the sphere,
// each refined from 16 x 16 initial pieces (minDepth 4), fine enough to find an alpha = 0.1
// lobe without the kit's sample probes.
LobeAlbedo sphereQuadrature(const BsdfModel& model, const Vec3d& wi) {
  QuadratureOptions q;
  q.relativeTolerance = 1e-6;
  q.absoluteTolerance = 1e-9;
  q.minDepth = 4;
  const auto integrand = [&](const Vec3d& wo) {
    const double f = model.eval(wi, wo, TransportMode::Importance).x * std::abs(wo.z);
    return wo.z * wi.z > 0 ? glm::dvec2(f, 0.0) : glm::dvec2(0.0, f);
  };
  glm::dvec2 sum(0.0);
  for (const glm::dvec2& cell : integrateCells(SphericalGrid{16, 32}, integrand, {}, q)) sum += cell;
  return {sum.x, sum.y};
}

struct Case {
  MicrofacetType type;
  double alpha, theta;
};
void PrintTo(const Case& c, std::ostream* os) {
  *os << (c.type == MicrofacetType::Ggx ? "GGX" : "Beckmann") << " alpha " << c.alpha << " wi " << c.theta;
}

class RoughDielectricAlbedo : public ::testing::TestWithParam<Case> {};

// The two quadratures integrate different functions (sample weights over u; f |cos| over wo)
// of the same model: they agree to their own tolerances, 2e-4 absolute per lobe.
TEST_P(RoughDielectricAlbedo, AgreesWithSphereQuadrature) {
  const Case& c = GetParam();
  const Vec3d wi = directionFromDegrees(c.theta, 30);
  const auto model = makeRoughDielectric(c.type, c.alpha, c.alpha, Eta);
  const LobeAlbedo sphere = sphereQuadrature(*model, wi);
  const LobeAlbedo e = c.type == MicrofacetType::Ggx
                           ? roughDielectricAlbedo(GgxDistribution<double>(c.alpha, c.alpha), Eta, wi,
                                                   TransportMode::Importance)
                           : roughDielectricAlbedo(BeckmannDistribution<double>(c.alpha, c.alpha), Eta, wi,
                                                   TransportMode::Importance);
  EXPECT_NEAR(e.reflection, sphere.reflection, 2e-4);
  EXPECT_NEAR(e.transmission, sphere.transmission, 2e-4);
  EXPECT_LT(e.total(), 1.0);
}

INSTANTIATE_TEST_SUITE_P(
    SingleScattering, RoughDielectricAlbedo,
    ::testing::Values(Case{MicrofacetType::Ggx, 0.1, 0}, Case{MicrofacetType::Ggx, 0.1, 150},
                      Case{MicrofacetType::Ggx, 0.3, 60}, Case{MicrofacetType::Ggx, 0.3, 120},
                      Case{MicrofacetType::Ggx, 1.0, 80}, Case{MicrofacetType::Ggx, 1.0, 180},
                      Case{MicrofacetType::Beckmann, 0.3, 30}, Case{MicrofacetType::Beckmann, 0.6, 100}),
    [](const ::testing::TestParamInfo<Case>& info) {
      return std::string(info.param.type == MicrofacetType::Ggx ? "Ggx" : "Beckmann") + "_alpha" +
             std::to_string(int(info.param.alpha * 10)) + "_wi" + std::to_string(int(info.param.theta));
    });

// The table for energy compensation (GGX, eta 1.5, importance transport), printed. Asserted:
// nothing is gained (E < 1), the loss grows with alpha at every angle and side, and the
// smooth limit (alpha 0.001) loses less than 0.3%.
TEST(RoughDielectricEnergy, SingleScatteringLossGrowsWithRoughnessOnBothSides) {
  std::printf("single-scattering albedo, GGX, eta %.2f, importance: E_R + E_T = E\n", Eta);
  std::printf("  alpha  wi(deg)      E_R      E_T        E   loss\n");
  for (const double theta : Angles) {
    const Vec3d wi = directionFromDegrees(theta, 30);
    double previous =
        roughDielectricAlbedo(GgxDistribution<double>(0.001, 0.001), Eta, wi, TransportMode::Importance)
            .total();
    EXPECT_GT(previous, 0.997) << "alpha 0.001, wi " << theta;
    for (const double alpha : Alphas) {
      const LobeAlbedo e =
          roughDielectricAlbedo(GgxDistribution<double>(alpha, alpha), Eta, wi, TransportMode::Importance);
      std::printf("  %5.2f  %7.1f  %7.4f  %7.4f  %7.4f  %4.1f%%\n", alpha, theta, e.reflection,
                  e.transmission, e.total(), 100 * (1 - e.total()));
      EXPECT_LT(e.total(), previous) << "alpha " << alpha << ", wi " << theta;
      previous = e.total();
    }
  }
}

}  // namespace rough_dielectric_energy_test
}  // namespace scatterlab
