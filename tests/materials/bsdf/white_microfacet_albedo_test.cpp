// E(mu, alpha), the single-scattering albedo with F = 1 (white_microfacet_albedo.h): the
// committed table is what the generator computes, the generator's quadrature agrees with a
// closed form and with an independent integral over wo, the interpolation stays within its
// stated bound, E_avg is the integral of the interpolant, and the loss the issue quotes.
#include "materials/bsdf/white_microfacet_albedo.h"

#include <gtest/gtest.h>

#include <cstdio>

#include "materials/core/rng.h"
#include "materials/core/warp.h"

namespace scatterlab {
namespace white_microfacet_albedo_test {

// The generator's accuracy (white_microfacet_albedo.h): absolute error below 1e-6. A node
// recomputed here with the same quadrature matches to round-off on the same build; 1e-6 also
// allows another compiler's or the sanitizer build's floating-point contraction.
constexpr double GeneratorAccuracy = 1e-6;

// The interpolation error bounds stated in white_microfacet_albedo.h (maximum over 1500 random
// (alpha, mu): 7.8e-5 GGX, 1.9e-4 Beckmann), rounded up.
constexpr double GgxInterpolationBound = 1e-4;
constexpr double BeckmannInterpolationBound = 2e-4;

const char* name(MicrofacetType type) { return type == MicrofacetType::Ggx ? "GGX" : "Beckmann"; }

// Nodes at the corners of the table (alpha 0.001 and 1, mu near 0 and 1, mu = 1) and inside.
TEST(WhiteMicrofacetAlbedoTable, RegeneratedEntriesMatchTheCommittedOnes) {
  constexpr int Last = WhiteAlbedoGrid::AlphaNodes - 1, LastCos = WhiteAlbedoGrid::CosNodes - 1;
  const std::vector<std::pair<int, int>> ggxNodes{{0, 1},    {0, 15},         {0, LastCos},
                                                  {Last, 1}, {Last, LastCos}, {17, 9}};
  const std::vector<std::pair<int, int>> beckmannNodes{{0, 14}, {Last, 2}, {Last, LastCos}, {21, 27}};
  for (const MicrofacetType type : {MicrofacetType::Ggx, MicrofacetType::Beckmann}) {
    const auto& table = whiteAlbedoTable(type);
    for (const auto& [i, j] : type == MicrofacetType::Ggx ? ggxNodes : beckmannNodes) {
      const double committed = table[size_t(i) * WhiteAlbedoGrid::CosNodes + j];
      EXPECT_NEAR(computeWhiteAlbedoNode(type, i, j), committed, GeneratorAccuracy)
          << name(type) << " node alpha " << WhiteAlbedoGrid::alphaNode(i) << " mu "
          << WhiteAlbedoGrid::cosAt(WhiteAlbedoGrid::cosNodeCoordinate(j), WhiteAlbedoGrid::alphaNode(i));
    }
    // mu = 0 is the grazing limit, exactly 1, at every roughness.
    for (int i = 0; i <= Last; ++i) EXPECT_EQ(table[size_t(i) * WhiteAlbedoGrid::CosNodes], 1.0);
  }
}

// GGX at alpha = 1 has D = 1/pi; at normal incidence Lambda(wi) = 0, the visible normals have
// density cos theta_m / pi, wo makes 2 theta_m with the normal and G2 / G1 = 1 / (1 + Lambda(wo))
// = 2 cos 2theta_m / (1 + cos 2theta_m). So E = 2 int_0^{pi/4} sin theta cos 2theta / cos theta
// dtheta = 2 int_{1/sqrt 2}^1 (2c^2 - 1) / c dc = 1 - ln 2.
TEST(WhiteMicrofacetAlbedoTable, GgxAtAlphaOneAndNormalIncidenceIsOneMinusLn2) {
  const double committed = GgxWhiteAlbedoTable.back();
  EXPECT_NEAR(committed, 1.0 - std::log(2.0), GeneratorAccuracy);
  // A lookup at a node returns the node.
  EXPECT_NEAR(WhiteMicrofacetAlbedo(MicrofacetType::Ggx, 1.0, 1.0)(Vec3d(0, 0, 1)), committed, 1e-15);
}

// An independent route: E = integral over wo of D(h) G2(wi, wo) / (4 cos_i) (F = 1), by
// adaptive quadrature over (cos theta_o, phi_o) refined from 64 x 64 pieces; at alpha >= 0.1
// that resolves the lobe. Agreement within the generator's accuracy.
TEST(WhiteMicrofacetAlbedoTable, GeneratorQuadratureAgreesWithAnIntegralOverWo) {
  QuadratureOptions options;
  options.relativeTolerance = 1e-9;
  options.absoluteTolerance = 1e-11;
  options.minDepth = 6;
  const auto overWo = [&](const auto& distribution, const Vec3d& wi) {
    return adaptiveSimpson2D(
        [&](double cosTheta, double phi) {
          const Vec3d wo = sphericalDirection(safeSqrt(1.0 - cosTheta * cosTheta), cosTheta, phi);
          return distribution.D(glm::normalize(wi + wo)) * distribution.G2(wi, wo) / (4.0 * wi.z);
        },
        0.0, 1.0, -Pi, Pi, options);
  };
  for (const auto& [alpha, theta] : std::vector<std::pair<double, double>>{{0.1, 80}, {0.4, 30}, {1.0, 88}}) {
    const Vec3d wi = directionFromDegrees(theta, 0);
    const GgxDistribution<double> ggx(alpha, alpha);
    const BeckmannDistribution<double> beckmann(alpha, alpha);
    EXPECT_NEAR(whiteMicrofacetAlbedo(ggx, wi), overWo(ggx, wi), GeneratorAccuracy)
        << "GGX " << alpha << " " << theta;
    EXPECT_NEAR(whiteMicrofacetAlbedo(beckmann, wi), overWo(beckmann, wi), GeneratorAccuracy)
        << "Beckmann " << alpha << " " << theta;
  }
}

// Between the nodes: cell centres (the farthest points from the nodes) at the table's corners
// and inside, against the generator's quadrature.
TEST(WhiteMicrofacetAlbedoTable, InterpolationIsWithinItsStatedBound) {
  const auto centre = [](int i) { return (i + 0.5) / (WhiteAlbedoGrid::AlphaNodes - 1); };
  const auto cosCentre = [](int j) { return (j + 0.5) / (WhiteAlbedoGrid::CosNodes - 1); };
  for (const MicrofacetType type : {MicrofacetType::Ggx, MicrofacetType::Beckmann}) {
    for (const auto& [i, j] : std::vector<std::pair<int, int>>{
             {0, 0}, {0, 13}, {0, 30}, {30, 0}, {30, 20}, {30, 30}, {6, 28}, {14, 12}}) {
      const double alpha = WhiteAlbedoGrid::alphaAt(centre(i));
      const double mu = WhiteAlbedoGrid::cosAt(cosCentre(j), alpha);
      const Vec3d wi(safeSqrt(1.0 - mu * mu), 0.0, mu);
      const double exact = type == MicrofacetType::Ggx
                               ? whiteMicrofacetAlbedo(GgxDistribution<double>(alpha, alpha), wi)
                               : whiteMicrofacetAlbedo(BeckmannDistribution<double>(alpha, alpha), wi);
      const WhiteMicrofacetAlbedo table(type, alpha, alpha);
      EXPECT_NEAR(table(wi), exact,
                  type == MicrofacetType::Ggx ? GgxInterpolationBound : BeckmannInterpolationBound)
          << name(type) << " alpha " << alpha << " mu " << mu;
    }
  }
}

// The per-material anisotropic table (fixed rule, 16 azimuths): within the 4e-3 stated for
// 0.05 x 0.8 at the kit's incident directions and at other azimuths.
TEST(WhiteMicrofacetAlbedoTable, AnisotropicTableIsWithinItsStatedBound) {
  for (const MicrofacetType type : {MicrofacetType::Ggx, MicrofacetType::Beckmann}) {
    const WhiteMicrofacetAlbedo table(type, 0.05, 0.8);
    // Beckmann's visible-normal sampler costs ~10 times GGX's in the reference quadrature.
    const std::vector<std::pair<double, double>> directions =
        type == MicrofacetType::Ggx
            ? std::vector<std::pair<double, double>>{{0, 30}, {30, 30},  {60, 30}, {85, 30}, {89.9, 30},
                                                     {85, 5}, {89.9, 5}, {60, 75}, {85, 200}}
            : std::vector<std::pair<double, double>>{{60, 30}, {85, 30}, {89.9, 5}, {85, 200}};
    for (const auto& [theta, phi] : directions) {
      const Vec3d wi = directionFromDegrees(theta, phi);
      const double exact = type == MicrofacetType::Ggx
                               ? whiteMicrofacetAlbedo(GgxDistribution<double>(0.05, 0.8), wi)
                               : whiteMicrofacetAlbedo(BeckmannDistribution<double>(0.05, 0.8), wi);
      EXPECT_NEAR(table(wi), exact, 4e-3) << name(type) << " theta " << theta << " phi " << phi;
    }
  }
}

// 1 - E_avg is the hemispherical integral of 1 - E of the very interpolant (so compensation
// normalised by it is exact for that E), checked by a quadrature over (cos theta, phi) of the
// lookups, 16 x 16 pieces, relative 1e-7 — an isotropic and an anisotropic case.
TEST(WhiteMicrofacetAlbedoTable, AverageLossIsTheIntegralOfTheInterpolant) {
  QuadratureOptions options;
  options.relativeTolerance = 1e-8;
  options.absoluteTolerance = 1e-14;
  options.minDepth = 4;
  for (const auto& [type, ax, ay] :
       std::vector<std::tuple<MicrofacetType, double, double>>{{MicrofacetType::Ggx, 0.3, 0.3},
                                                               {MicrofacetType::Beckmann, 0.02, 0.02},
                                                               {MicrofacetType::Ggx, 0.05, 0.8}}) {
    const WhiteMicrofacetAlbedo albedo(type, ax, ay);
    const double integral =
        adaptiveSimpson2D(
            [&](double cosTheta, double phi) {
              return albedo.loss(sphericalDirection(safeSqrt(1.0 - cosTheta * cosTheta), cosTheta, phi)) *
                     cosTheta;
            },
            0.0, 1.0, -Pi, Pi, options) /
        Pi;
    EXPECT_NEAR(albedo.averageLoss() / integral, 1.0, 1e-6) << name(type) << " " << ax << " x " << ay;
  }
}

// Issue: "single-scatter GGX with F = 1 at alpha 0.09 loses about 1.8% averaged over a
// sphere's directions". The loss averaged over a sphere seen in a white furnace (pixels uniform
// over its projected disk, so mu cosine-weighted) is 1 - E_avg = 2 int_0^1 (1 - E) mu dmu.
// Computed here by nested quadrature of the generator's E (no table), it is 2.35%; other
// readings of "averaged over directions": uniform over the hemisphere 4.00%, cos^2-weighted
// 1.69%. The 1.8% is not reproduced by any of them (reported to the lead). Asserted:
// the quadrature value, and that the table's 1 - E_avg agrees with it within the interpolation
// bound.
TEST(WhiteMicrofacetAlbedoTable, LossOfGgxAtAlpha0p09AveragedOverTheHemisphere) {
  const GgxDistribution<double> ggx(0.09, 0.09);
  QuadratureOptions lossOptions = whiteAlbedoQuadrature();
  lossOptions.relativeTolerance = lossOptions.absoluteTolerance = 1e-6;
  const auto loss = [&](double mu) {
    return 1.0 - whiteMicrofacetAlbedo(ggx, Vec3d(safeSqrt(1.0 - mu * mu), 0.0, mu), lossOptions);
  };
  QuadratureOptions outer;
  outer.relativeTolerance = 1e-5;
  outer.absoluteTolerance = 1e-8;
  outer.minDepth = 3;
  const double cosineWeighted =
      2.0 * adaptiveSimpson([&](double mu) { return loss(mu) * mu; }, 0.0, 1.0, outer);
  const double uniform = adaptiveSimpson(loss, 0.0, 1.0, outer);
  std::printf("GGX alpha 0.09, F = 1: loss cosine-weighted (1 - E_avg) %.4f%%, uniform %.4f%%\n",
              100 * cosineWeighted, 100 * uniform);
  EXPECT_NEAR(cosineWeighted, 0.02349, 5e-5);
  EXPECT_NEAR(uniform, 0.04000, 5e-5);
  EXPECT_NEAR(WhiteMicrofacetAlbedo(MicrofacetType::Ggx, 0.09, 0.09).averageLoss(), cosineWeighted,
              GgxInterpolationBound);
}

TEST(WhiteMicrofacetAlbedoTable, LookupsAreInRangeAndRejectRoughnessBeyondTheTable) {
  CounterRng rng(3, 0);
  for (const auto& [ax, ay] :
       std::vector<std::pair<double, double>>{{0.001, 0.001}, {1.0, 1.0}, {0.001, 1.0}}) {
    const WhiteMicrofacetAlbedo albedo(MicrofacetType::Beckmann, ax, ay);
    for (int n = 0; n < 2000; ++n) {
      const Vec3d w = sampleUniformHemisphere(rng.uniform2D());
      const double e = albedo(w);
      ASSERT_TRUE(e >= 0.0 && e <= 1.0) << e;
    }
    EXPECT_EQ(albedo(Vec3d(1, 0, 0)), 1.0);
    EXPECT_EQ(albedo(Vec3d(0, 0, -1)), 1.0);
  }
  EXPECT_THROW(WhiteMicrofacetAlbedo(MicrofacetType::Ggx, 1.2, 0.5), std::invalid_argument);
  EXPECT_THROW(WhiteMicrofacetAlbedo(MicrofacetType::Ggx, 0.0, 0.5), std::invalid_argument);
  // Shared: one object per distribution and roughness.
  EXPECT_EQ(WhiteMicrofacetAlbedo::shared(MicrofacetType::Ggx, 0.2, 0.2).get(),
            WhiteMicrofacetAlbedo::shared(MicrofacetType::Ggx, 0.2, 0.2).get());
}

}  // namespace white_microfacet_albedo_test
}  // namespace scatterlab
