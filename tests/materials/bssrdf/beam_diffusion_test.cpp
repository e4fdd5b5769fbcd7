#include <gtest/gtest.h>

#include "bssrdf_test_support.h"
#include "materials/bssrdf/beam_diffusion_profile.h"
#include "materials/bssrdf/photon_beam_diffusion.h"
#include "materials/core/quadrature.h"

namespace scatterlab {
namespace beam_diffusion_test {

const BeamDiffusionTable& table13() { return *BeamDiffusionTable::shared(0.0, 1.3); }

// Independent references: adaptive Simpson in ln(depth) to 1e-10 (the kernels use fixed
// Gauss-Legendre panels).
QuadratureOptions referenceQuadrature() {
  QuadratureOptions o;
  o.relativeTolerance = 1e-10;
  o.absoluteTolerance = 1e-300;
  o.minDepth = 6;
  o.maxDepth = 40;
  return o;
}

double referenceMultiple(double rho, double eta, double r) {
  const FresnelBoundary b = fresnelBoundary(eta);
  BetterDipole<double> source = makeBetterDipole(rho, 1 - rho, b);
  const double offset = 4 * b.A * source.D;
  return adaptiveSimpson(
      [&](double s) {
        const double z = std::exp(s), dr = std::sqrt(r * r + z * z);
        source.zr = z;
        source.zv = -z - offset;
        return z * std::exp(-z) * (1 - std::exp(-2 * (dr + z))) * betterDipoleProfile(source, r);
      },
      std::log(1e-12 * r), std::log(60.0), referenceQuadrature());
}

double referenceSingle(double rho, double eta, double r) {
  const double tc = r * std::sqrt(eta * eta - 1);
  return rho * adaptiveSimpson(
                   [&](double s) {
                     const double z = std::exp(s), t = tc + z, d = std::sqrt(r * r + t * t);
                     return z * std::exp(-(t + d)) / (d * d) * beamDiffusionExitFactor(t / d, 0.0, eta);
                   },
                   std::log(1e-12 * r), std::log(60.0), referenceQuadrature());
}

TEST(PhotonBeamDiffusion, KernelsMatchAdaptiveQuadrature) {
  for (const double r : {1e-3, 0.05, 1.0, 10.0}) {
    SCOPED_TRACE(r);
    // Gauss-Legendre panels of 1.5 in ln(depth): ~1e-6 relative at worst (measured 9e-7).
    EXPECT_NEAR(beamDiffusionMultiple(0.9, 0.0, fresnelBoundary(1.3), r) / referenceMultiple(0.9, 1.3, r),
                1.0, 3e-6);
    EXPECT_NEAR(beamDiffusionSingle(0.9, 0.0, 1.3, r) / referenceSingle(0.9, 1.3, r), 1.0, 3e-6);
  }
}

TEST(PhotonBeamDiffusion, SingleScatteringLimitAtTheBeam) {
  // r SS(r) -> its limit as the exit point approaches the beam (the e^(-r) factors ~1 - r).
  for (const double eta : {1.0, 1.3, 1.5}) {
    const double r = 1e-9;
    EXPECT_NEAR(r * beamDiffusionSingle(0.8, 0.3, eta, r) / beamDiffusionSingleLimit(0.8, 0.3, eta), 1.0,
                1e-6)
        << eta;
  }
}

TEST(BeamDiffusionTable, UsesPbrtsGrids) {
  const BeamDiffusionTable& t = table13();
  ASSERT_EQ(t.albedos().size(), 100u);
  ASSERT_EQ(t.radii().size(), 64u);
  EXPECT_EQ(t.albedos()[0], 0.0);
  EXPECT_DOUBLE_EQ(t.albedos()[99], 1.0);
  EXPECT_DOUBLE_EQ(t.albedos()[50], (1 - std::exp(-8.0 * 50 / 99)) / (1 - std::exp(-8.0)));
  EXPECT_EQ(t.radii()[0], 0.0);
  EXPECT_DOUBLE_EQ(t.radii()[1], 2.5e-3);
  for (int j = 2; j < 64; ++j) EXPECT_DOUBLE_EQ(t.radii()[size_t(j)], 1.2 * t.radii()[size_t(j) - 1]);
  EXPECT_NEAR(t.radii()[63], 2.5e-3 * std::pow(1.2, 62), 1e-9);
}

TEST(BeamDiffusionTable, NodesHoldTheKernelsAndTheirIntegral) {
  const BeamDiffusionTable& t = table13();
  const FresnelBoundary b = fresnelBoundary(1.3);
  for (const int i : {20, 70, 95}) {
    const double rho = t.albedos()[size_t(i)];
    for (const int j : {1, 20, 40}) {
      const double r = t.radii()[size_t(j)];
      EXPECT_NEAR(
          t.density(i, j),
          2 * Pi * r * (beamDiffusionMultiple(rho, 0.0, b, r) + beamDiffusionSingle(rho, 0.0, 1.3, r)),
          1e-13 * t.density(i, j));
    }
    // The row's cumulative at r_40 against adaptive quadrature of the reference kernels.
    const double r40 = t.radii()[40];
    QuadratureOptions o;
    o.relativeTolerance = 1e-8;
    o.minDepth = 4;
    const double reference = adaptiveSimpson(
        [&](double s) {
          const double r = std::exp(s);
          return r * 2 * Pi * r * (referenceMultiple(rho, 1.3, r) + referenceSingle(rho, 1.3, r));
        },
        std::log(1e-9), std::log(r40), o);
    EXPECT_NEAR(t.cumulative(i, 40) / reference, 1.0, 1e-5) << rho;
  }
}

TEST(BeamDiffusionTable, EffectiveAlbedoIncreasesAndInverts) {
  const BeamDiffusionTable& t = table13();
  EXPECT_EQ(t.effectiveAlbedo(0), 0.0);
  for (int i = 1; i < 100; ++i) EXPECT_GT(t.effectiveAlbedo(i), t.effectiveAlbedo(i - 1)) << i;
  for (const double rho : {0.05, 0.3, 0.77, 0.95, 0.999}) {
    EXPECT_NEAR(t.albedoForEffectiveAlbedo(t.effectiveAlbedo(rho)), rho, 1e-9) << rho;
  }
  // At the nodes, the interpolated row is the row.
  EXPECT_DOUBLE_EQ(t.effectiveAlbedo(t.albedos()[60]), t.effectiveAlbedo(60));
}

TEST(BeamDiffusionProfile, ScalesTheOpticalRowBySigmaT) {
  const BeamDiffusionTable& t = table13();
  const double rho = t.albedos()[80], sigmaT = 2.5;
  ScatteringMedium m;
  m.sigmaS = Rgb(rho * sigmaT);
  m.sigmaA = Rgb((1 - rho) * sigmaT);
  m.eta = 1.3;
  const BeamDiffusionProfile p(m);
  // sigma_s / sigma_t is rho to round-off, which moves the Catmull-Rom weights by ~1e-16.
  EXPECT_NEAR(p.totalReflectance().x, t.effectiveAlbedo(80), 1e-12);
  const double rOptical = t.radii()[30], r = rOptical / sigmaT;
  EXPECT_NEAR(p.eval(r).x, sigmaT * sigmaT * t.density(80, 30) / (2 * Pi * rOptical), 1e-12 * p.eval(r).x);
  EXPECT_NEAR(p.radiusCdf(0, r), t.cumulative(80, 30) / t.effectiveAlbedo(80), 1e-14);
  // Zero beyond the table's last radius.
  EXPECT_EQ(p.eval(1.01 * t.radii()[63] / sigmaT).x, 0.0);
}

}  // namespace beam_diffusion_test
}  // namespace scatterlab
