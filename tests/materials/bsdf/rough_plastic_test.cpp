// Rough plastic (rough_plastic.h) and its two shared pieces: the diffuse Fresnel reflectance
// (diffuse_fresnel.h) and the coating's directional albedo E (microfacet_albedo.h). Each
// quantity is checked against an independent computation: a different quadrature, a
// physical identity, the smooth-coating limit, or the formula written out here.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "fixed_pairs.h"
#include "materials/bsdf/diffuse_fresnel.h"
#include "materials/bsdf/microfacet_albedo.h"
#include "materials/bsdf/rough_plastic.h"
#include "materials/core/quadrature.h"
#include "materials/core/rng.h"
#include "materials/registry/material_file.h"
#include "materials/registry/spec_validation.h"

namespace scatterlab {
namespace rough_plastic_test {

using Ggx = GgxDistribution<double>;
using Beckmann = BeckmannDistribution<double>;

// Unpolarised Fresnel reflectance written out from Snell's law, for the tests.
double fresnelByHand(double cosI, double eta) {
  const double sinT2 = (1.0 - cosI * cosI) / (eta * eta);
  if (sinT2 >= 1.0) return 1.0;
  const double cosT = std::sqrt(1.0 - sinT2);
  const double rs = (cosI - eta * cosT) / (cosI + eta * cosT);
  const double rp = (eta * cosI - cosT) / (eta * cosI + cosT);
  return 0.5 * (rs * rs + rp * rp);
}

// ---- Diffuse Fresnel reflectance ----------------------------------------------------------

// 2 integral_0^1 F(mu) mu dmu by the midpoint rule with 200000 steps, an independent
// quadrature of the hand-written Fresnel formula. From the rarer side in theta. From the
// denser side, F = 1 beyond the critical angle (that part is 1 - eta^2 exactly) and below it
// F has a square-root kink at the critical angle, so the rule runs over the transmitted angle
// theta_t instead, sin theta = eta sin theta_t, where the integrand is smooth; error ~1e-11.
double diffuseFresnelByMidpoint(double eta) {
  constexpr int Steps = 200000;
  const double h = PiOver2 / Steps;
  double sum = 0;
  for (int i = 0; i < Steps; ++i) {
    const double angle = (i + 0.5) * h;
    if (eta >= 1.0) {
      sum += 2.0 * fresnelByHand(std::cos(angle), eta) * std::cos(angle) * std::sin(angle);
    } else {
      const double theta = std::asin(eta * std::sin(angle));
      // 2 F cos sin dtheta with dtheta = eta cos theta_t / cos theta dtheta_t.
      sum += 2.0 * fresnelByHand(std::cos(theta), eta) * std::sin(theta) * eta * std::cos(angle);
    }
  }
  return sum * h + (eta < 1.0 ? 1.0 - eta * eta : 0.0);
}

TEST(DiffuseFresnel, MatchesAnIndependentQuadratureFromBothSides) {
  for (double eta : {1.1, 1.33, 1.5, 2.4}) {
    SCOPED_TRACE(eta);
    EXPECT_NEAR(diffuseFresnelReflectance(eta), diffuseFresnelByMidpoint(eta), 1e-9);
    EXPECT_NEAR(diffuseFresnelReflectance(1.0 / eta), diffuseFresnelByMidpoint(1.0 / eta), 1e-9);
  }
  EXPECT_EQ(diffuseFresnelReflectance(1.0), 0.0);
  EXPECT_THROW(diffuseFresnelReflectance(0.0), std::invalid_argument);
  EXPECT_THROW(diffuseFresnelReflectance(NAN), std::invalid_argument);
}

// Diffuse light crossing the interface: 1 - Fdr(eta) = eta^2 (1 - Fdr(1/eta)) (etendue).
TEST(DiffuseFresnel, TransmittancesFromTheTwoSidesObeyTheEtendueIdentity) {
  for (double eta : {1.05, 1.2, 1.5, 1.8, 2.4, 3.0}) {
    SCOPED_TRACE(eta);
    EXPECT_NEAR(1.0 - diffuseFresnelReflectance(eta),
                eta * eta * (1.0 - diffuseFresnelReflectance(1.0 / eta)), 1e-10);
  }
}

// Egan & Hilgeman's fit (docs/references.md, "Fresnel"; as Jensen et al. 2001 use it for the internal
// reflectance) agrees to its accuracy: 0.52% at eta 1.1, less above.
TEST(DiffuseFresnel, InternalReflectanceAgreesWithEganHilgemansFit) {
  for (double eta : {1.1, 1.3, 1.5, 2.0, 2.4}) {
    const double fit = -1.440 / (eta * eta) + 0.710 / eta + 0.668 + 0.0636 * eta;
    EXPECT_NEAR(diffuseFresnelReflectance(1.0 / eta), fit, 6e-3 * fit) << eta;
  }
}

// ---- The coating's albedo E ---------------------------------------------------------------

// E by an independent route: the importance-sampling estimator of the classic (D cos) scheme
// integrated over its unit square, weight F G2 (wo.h) / (cos_i h.z), u.x = v^2 so that the
// radial square root is smooth, by nested adaptive Simpson.
template <typename Distribution>
double albedoByClassicQuadrature(const Distribution& d, double eta, const Vec3d& wi) {
  const auto weight = [&](double v, double uy) {
    const Vec3d m = d.sampleClassic(Vec2d(v * v, uy));
    const Vec3d wo = reflect(wi, m);
    if (!(wo.z > 0) || !(glm::dot(wi, m) > 0)) return 0.0;
    return 2.0 * v * fresnelByHand(glm::dot(wi, m), eta) * d.G2(wi, wo) * glm::dot(wo, m) / (wi.z * m.z);
  };
  QuadratureOptions o;
  o.relativeTolerance = 1e-7;
  o.maxDepth = 30;  // at 89.9 degrees the weight has features ~1e-7 wide in u
  return adaptiveSimpson2D(weight, 0.0, 1.0, 0.0, 1.0, o);
}

TEST(CoatingAlbedo, QuadratureAgreesWithTheClassicSamplersIntegral) {
  struct Case {
    double alpha, eta, thetaDeg;
  };
  for (const Case c :
       {Case{0.3, 1.5, 0}, Case{0.3, 1.5, 70}, Case{1.0, 2.4, 45}, Case{1.0, 1.1, 85}, Case{0.1, 1.5, 30},
        Case{0.001, 2.4, 89.9}, Case{0.01, 1.8, 89.9}, Case{0.05, 2.4, 89.9}}) {
    SCOPED_TRACE(::testing::Message() << "alpha " << c.alpha << " eta " << c.eta << " theta " << c.thetaDeg);
    const Vec3d wi = directionFromDegrees(c.thetaDeg, 0);
    EXPECT_NEAR(dielectricReflectionAlbedo(Ggx(c.alpha, c.alpha), c.eta, wi),
                albedoByClassicQuadrature(Ggx(c.alpha, c.alpha), c.eta, wi), 2e-6);
    EXPECT_NEAR(dielectricReflectionAlbedo(Beckmann(c.alpha, c.alpha), c.eta, wi),
                albedoByClassicQuadrature(Beckmann(c.alpha, c.alpha), c.eta, wi), 2e-6);
  }
}

// A nearly smooth coating reflects F; toward grazing, masking (and F's curvature over the
// lobe) lower it a little: 4e-5 at 80 degrees for alpha 0.001 (the classic integral agrees).
TEST(CoatingAlbedo, TendsToFresnelForASmoothCoating) {
  for (double eta : {1.1, 1.5, 2.4})
    for (const auto& [theta, tolerance] : {std::pair{0.0, 2e-6}, {30.0, 2e-6}, {60.0, 5e-6}, {80.0, 1e-4}}) {
      const Vec3d wi = directionFromDegrees(theta, 20);
      EXPECT_NEAR(dielectricReflectionAlbedo(Ggx(0.001, 0.001), eta, wi), fresnelByHand(wi.z, eta), tolerance)
          << eta << " " << theta;
    }
}

// The table against the quadrature it interpolates, over the hard corners of roughness and
// index (1.1 to the registry's maximum 4), at cosines from 1e-4 (with 89.9 degrees) to 1. The
// bound is what the model's albedo <= 1 rests on (the kit allows 1e-4).
TEST(CoatingAlbedo, TableIsWithin3e5OfTheQuadrature) {
  for (const double alpha : {0.001, 0.1, 1.0})
    for (const double eta : {1.1, 2.4, 4.0}) {
      const auto check = [&](const auto& d, const char* name) {
        const auto table = sharedDielectricReflectionAlbedo(d, eta);
        double worst = 0.0;
        for (int k = 0; k <= 40; ++k) {
          const double mu = k == 0 ? std::cos(radians(89.9)) : std::pow(10.0, -4.0 + 4.0 * k / 40.0);
          const Vec3d wi(std::sqrt(1 - mu * mu), 0, mu);
          worst = std::max(worst, std::abs((*table)(wi)-dielectricReflectionAlbedo(d, eta, wi)));
        }
        EXPECT_LT(worst, 3e-5) << name << " alpha " << alpha << " eta " << eta;
      };
      check(Ggx(alpha, alpha), "ggx");
      check(Beckmann(alpha, alpha), "beckmann");
    }
}

// Ebar of a nearly smooth coating is the diffuse Fresnel reflectance, and the model's internal
// reflectance 1 - (1 - Ebar) / eta^2 is then Fdr(1/eta) (rough_plastic.h, step 5).
TEST(CoatingAlbedo, SmoothLimitOfTheAverageIsTheDiffuseFresnelReflectance) {
  for (double eta : {1.1, 1.5, 2.4}) {
    const RoughPlasticBsdf<Ggx> smooth(Ggx(0.001, 0.001), Rgb(0.5), eta);
    EXPECT_NEAR(smooth.coatingAlbedoAverage(), diffuseFresnelReflectance(eta), 2e-5) << eta;
    EXPECT_NEAR(smooth.internalDiffuseReflectance(), diffuseFresnelReflectance(1.0 / eta), 2e-5) << eta;
  }
}

TEST(CoatingAlbedo, TableRejectsAnisotropyAndIndicesBelowOne) {
  EXPECT_THROW(DielectricReflectionAlbedoTable(Ggx(0.1, 0.2), 1.5), std::invalid_argument);
  EXPECT_THROW(DielectricReflectionAlbedoTable(Ggx(0.1, 0.1), 0.9), std::invalid_argument);
  const DielectricReflectionAlbedoTable matched(Ggx(0.1, 0.1), 1.0);
  EXPECT_EQ(matched(directionFromDegrees(30, 0)), 0.0);
  EXPECT_EQ(matched.hemisphericalAverage(), 0.0);
}

// ---- The model ----------------------------------------------------------------------------

// GGX D, Smith height-correlated G2 and the Fresnel term written out (Walter et al. 2007 eq.
// 33; Heitz 2014 eq. 99 with Lambda = (sqrt(1 + alpha^2 tan^2) - 1) / 2), plus the diffuse term
// with the coating albedos the model reports (their values are tested above).
TEST(RoughPlastic, EvalMatchesTheFormulaWrittenOut) {
  const double alpha = 0.25, eta = 1.6;
  const Rgb kd(0.9, 0.4, 0.1);
  const RoughPlasticBsdf<Ggx> model(Ggx(alpha, alpha), kd, eta);
  const auto lambda = [&](const Vec3d& w) {
    const double tan2 = (1 - w.z * w.z) / (w.z * w.z);
    return 0.5 * (std::sqrt(1 + alpha * alpha * tan2) - 1);
  };
  for (const DirectionPair& p : reflectionPairs()) {
    const Vec3d h = glm::normalize(p.wi + p.wo);
    const double tan2h = (1 - h.z * h.z) / (h.z * h.z);
    const double D = 1.0 / (Pi * alpha * alpha * std::pow(h.z, 4) * std::pow(1 + tan2h / (alpha * alpha), 2));
    const double G2 = 1.0 / (1.0 + lambda(p.wi) + lambda(p.wo));
    const double specular = D * fresnelByHand(glm::dot(p.wi, h), eta) * G2 / (4 * p.wi.z * p.wo.z);
    const double Ei = model.coatingAlbedo(p.wi), Eo = model.coatingAlbedo(p.wo),
                 Ebar = model.coatingAlbedoAverage();
    const double fdrInt = 1.0 - (1.0 - Ebar) / (eta * eta);
    const Rgb f = model.eval(p.wi, p.wo);
    for (int c = 0; c < 3; ++c) {
      const double diffuse = kd[c] * (1 - Ei) * (1 - Eo) / (Pi * eta * eta * (1 - kd[c] * fdrInt));
      EXPECT_NEAR(f[c], specular + diffuse, 1e-10 * (specular + diffuse)) << c;
    }
  }
}

// With an almost smooth coating the diffuse term is Mitsuba 0.6's smooth plastic,
// (1 - F(wi)) (1 - F(wo)) kd / (pi eta^2 (1 - kd Fdr(1/eta))).
TEST(RoughPlastic, DiffuseTermOfASmoothCoatingIsTheSmoothPlasticOne) {
  const double eta = 1.5;
  const Rgb kd(0.5, 0.8, 1.0);
  const RoughPlasticBsdf<Beckmann> model(Beckmann(0.001, 0.001), kd, eta);
  const double fdrInt = diffuseFresnelReflectance(1.0 / eta);
  for (const DirectionPair& p : reflectionPairs()) {
    // Off the specular direction, f is the diffuse term alone.
    const Rgb f = model.eval(p.wi, p.wo);
    for (int c = 0; c < 3; ++c) {
      const double smooth = (1 - fresnelByHand(p.wi.z, eta)) * (1 - fresnelByHand(p.wo.z, eta)) * kd[c] /
                            (Pi * eta * eta * (1 - kd[c] * fdrInt));
      EXPECT_NEAR(f[c], smooth, 1e-4 * smooth) << c;
    }
  }
}

// Directional albedo of the model, independently of the table: E by the quadrature (within 2e-6
// of the classic sampler's integral, tested above, grazing included) plus the diffuse part
// integrated over the hemisphere of wo by nested adaptive Simpson.
template <typename Distribution> Rgb albedoOf(const RoughPlasticBsdf<Distribution>& model, const Vec3d& wi) {
  QuadratureOptions o;
  o.relativeTolerance = 1e-8;
  const auto diffuse = [&](double cosO, double phi) {
    const double sinO = safeSqrt(1 - cosO * cosO);
    const Vec3d wo(sinO * std::cos(phi), sinO * std::sin(phi), cosO);
    return glm::dvec3(roughPlasticDiffuseEval<double>(model.diffuse(), model.eta(), model.coatingAlbedo(wi),
                                                      model.coatingAlbedo(wo), model.coatingAlbedoAverage()) *
                      cosO);
  };
  const glm::dvec3 d = adaptiveSimpson2D(diffuse, 0.0, 1.0, 0.0, 2.0 * Pi, o);
  return Rgb(dielectricReflectionAlbedo(model.distribution(), model.eta(), wi)) + Rgb(d.x, d.y, d.z);
}

// The energy bound (rough_plastic.h): with a white base the albedo is E(wi) + (1 - E(wi)) = 1
// up to the table's error, the largest any base gives (next test). Bound: 3e-5 (table) + 2e-6
// (quadrature). Every index 1.1..2.4 and roughness
// 0.001..1 of both distributions, from normal to 89.9 degrees.
TEST(RoughPlastic, WhiteBaseReflectsAtMostEverythingAtEveryRoughnessAndIndex) {
  constexpr double Bound = 3.2e-5;
  double worst = -1.0;
  for (double eta : {1.1, 1.5, 1.8, 2.4})
    for (double alpha : {0.001, 0.01, 0.05, 0.1, 0.3, 1.0})
      for (double theta : {0.0, 45.0, 75.0, 85.0, 89.9}) {
        const Vec3d wi = directionFromDegrees(theta, 0);
        const RoughPlasticBsdf<Ggx> ggx(Ggx(alpha, alpha), Rgb(1.0), eta);
        const RoughPlasticBsdf<Beckmann> beckmann(Beckmann(alpha, alpha), Rgb(1.0), eta);
        for (const double a : {albedoOf(ggx, wi).x, albedoOf(beckmann, wi).x}) {
          EXPECT_LE(a, 1.0 + Bound) << "eta " << eta << " alpha " << alpha << " theta " << theta;
          EXPECT_GE(a, 1.0 - Bound) << "eta " << eta << " alpha " << alpha << " theta " << theta;
          worst = std::max(worst, a);
        }
      }
  RecordProperty("max_albedo", std::to_string(worst));
}

// Any other base reflects less: the diffuse albedo kd (1 - Ebar) / (eta^2 (1 - kd) + kd (1 -
// Ebar)) grows with kd up to 1.
TEST(RoughPlastic, DarkerBasesReflectLess) {
  const Vec3d wi = directionFromDegrees(50, 0);
  const RoughPlasticBsdf<Ggx> white(Ggx(0.2, 0.2), Rgb(1.0), 1.5);
  const RoughPlasticBsdf<Ggx> coloured(Ggx(0.2, 0.2), Rgb(0.0, 0.5, 0.99), 1.5);
  const Rgb w = albedoOf(white, wi), c = albedoOf(coloured, wi);
  const double E = albedoByClassicQuadrature(Ggx(0.2, 0.2), 1.5, wi);
  EXPECT_NEAR(c.x, E, 1e-9);  // a black base: the coating's reflection alone
  EXPECT_LT(c.y, c.z);
  EXPECT_LT(c.z, w.z);
}

TEST(RoughPlastic, ReciprocalOneSidedAndFinite) {
  const RoughPlasticBsdf<Beckmann> model(Beckmann(0.15, 0.15), Rgb(0.7, 0.3, 0.9), 1.7);
  for (uint64_t i = 0; i < 2000; ++i) {
    CounterRng rng(17, i);
    const Vec3d a = sampleCosineHemisphere(rng.uniform2D()), b = sampleCosineHemisphere(rng.uniform2D());
    const Rgb ab = model.eval(a, b), ba = model.eval(b, a);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(ab[c], ba[c], 1e-12 * ab[c]);
  }
  const Vec3d below(0, 0.6, -0.8), above = directionFromDegrees(40, 0);
  EXPECT_EQ(model.eval(below, above), Rgb(0.0));
  EXPECT_EQ(model.eval(above, below), Rgb(0.0));
  EXPECT_EQ(model.pdf(below, above), 0.0);
  EXPECT_FALSE(model.sample(below, 0.5, {0.3, 0.3}).has_value());
  // Exactly grazing and exactly normal directions stay finite.
  const Rgb f = model.eval(Vec3d(1, 0, 0), above) + model.eval(Vec3d(0, 0, 1), Vec3d(0, 0, 1));
  for (int c = 0; c < 3; ++c) EXPECT_TRUE(std::isfinite(f[c]));
}

// The lobe choice is the ratio of the lobes' albedos at wi.
TEST(RoughPlastic, SpecularSamplingProbabilityIsTheAlbedoRatio) {
  const Vec3d wi = directionFromDegrees(60, 0);
  const RoughPlasticBsdf<Ggx> black(Ggx(0.1, 0.1), Rgb(0.0), 1.5);
  EXPECT_EQ(black.specularSamplingProbability(wi), 1.0);
  const RoughPlasticBsdf<Ggx> matched(Ggx(0.1, 0.1), Rgb(0.5), 1.0);
  EXPECT_EQ(matched.specularSamplingProbability(wi), 0.0);
  const RoughPlasticBsdf<Ggx> white(Ggx(0.1, 0.1), Rgb(1.0), 1.5);
  const double E = white.coatingAlbedo(wi);
  EXPECT_NEAR(white.specularSamplingProbability(wi), E, 1e-15);  // E / (E + (1 - E) 1)
}

TEST(RoughPlastic, LosslessExactlyForAWhiteBase) {
  EXPECT_TRUE(RoughPlasticBsdf<Ggx>(Ggx(0.1, 0.1), Rgb(1.0), 1.5).isLossless());
  EXPECT_FALSE(RoughPlasticBsdf<Ggx>(Ggx(0.1, 0.1), Rgb(1.0, 1.0, 0.99), 1.5).isLossless());
}

// ---- Registry -----------------------------------------------------------------------------

TEST(RoughPlastic, RegistryDefaultsAndRanges) {
  const auto model = makeBsdf({{"type", "rough-plastic"}});
  const auto* plastic = dynamic_cast<const RoughPlasticBsdf<Ggx>*>(model.get());
  ASSERT_NE(plastic, nullptr);
  EXPECT_EQ(plastic->diffuse(), Rgb(0.5));
  EXPECT_EQ(plastic->eta(), 1.5);
  EXPECT_EQ(plastic->distribution().alphaX(), 0.1);
  EXPECT_NE(dynamic_cast<const RoughPlasticBsdf<Beckmann>*>(
                makeBsdf({{"type", "rough-plastic"}, {"distribution", "beckmann"}}).get()),
            nullptr);
  for (const nlohmann::json& bad : {nlohmann::json{{"type", "rough-plastic"}, {"alpha", 0.0}},
                                    {{"type", "rough-plastic"}, {"alpha", 1.5}},
                                    {{"type", "rough-plastic"}, {"alpha", {0.1, 0.2}}},
                                    {{"type", "rough-plastic"}, {"eta", 1.0}},
                                    {{"type", "rough-plastic"}, {"eta", 4.5}},
                                    {{"type", "rough-plastic"}, {"diffuse", {0.5, 1.2, 0.5}}},
                                    {{"type", "rough-plastic"}, {"distribution", "phong"}}}) {
    EXPECT_THROW(makeBsdf(bad), MaterialError) << bad.dump();
  }
  try {
    makeBsdf({{"type", "rough-plastic"}, {"eta", 4.5}});
    ADD_FAILURE() << "eta 4.5 accepted";
  } catch (const MaterialError& e) {
    EXPECT_NE(std::string(e.what()).find("\"eta\""), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("(1, 4]"), std::string::npos) << e.what();
  }
}

TEST(RoughPlastic, ExampleMaterialBuilds) {
  const auto path = std::filesystem::path(SCATTERLAB_DATA_DIR) / "materials" / "rough-plastic-red.json";
  const auto model = makeBsdf(loadMaterialArgument(path.string()));
  EXPECT_GT(model->pdf(directionFromDegrees(30, 0), directionFromDegrees(30, 180)), 0.0);
}

}  // namespace rough_plastic_test
}  // namespace scatterlab
