#include "materials/bsdf/conductor.h"

#include <stdexcept>
#include <vector>

#include <ceres/jet.h>
#include <gtest/gtest.h>

#include "materials/core/quadrature.h"
#include "materials/core/rng.h"
#include "materials/core/warp.h"

namespace scatterlab {
namespace conductor_test {

// Gold-like RGB index: strongly coloured Fresnel, so a channel mix-up shows.
const Rgb GoldEta(0.2, 0.9, 1.4), GoldK(3.9, 2.4, 1.6);

struct Configuration {
  MicrofacetType type;
  double alphaX, alphaY;
  MicrofacetSampling sampling;
};

std::string describe(const Configuration& c) {
  return std::string(c.type == MicrofacetType::Ggx ? "ggx" : "beckmann") + " alpha (" +
         std::to_string(c.alphaX) + ", " + std::to_string(c.alphaY) + ") " +
         (c.sampling == MicrofacetSampling::Visible ? "visible" : "classic");
}

std::vector<Configuration> configurations() {
  std::vector<Configuration> all;
  for (const MicrofacetType type : {MicrofacetType::Ggx, MicrofacetType::Beckmann})
    for (const MicrofacetSampling sampling : {MicrofacetSampling::Visible, MicrofacetSampling::Classic})
      for (const auto& [ax, ay] : {std::pair{0.001, 0.001}, std::pair{0.01, 0.01}, std::pair{0.3, 0.3},
                                   std::pair{1.0, 1.0}, std::pair{0.05, 0.8}})
        all.push_back({type, ax, ay, sampling});
  return all;
}

std::unique_ptr<BsdfModel> make(const Configuration& c, const Rgb& eta = GoldEta, const Rgb& k = GoldK) {
  return makeMicrofacetConductor(c.type, c.alphaX, c.alphaY, eta, k, c.sampling);
}

std::vector<Vec3d> incidentDirections() {
  return {directionFromDegrees(0, 0), directionFromDegrees(30, 20), directionFromDegrees(60, 90),
          directionFromDegrees(85, 37), directionFromDegrees(89.9, 63)};
}

double maxRelativeDifference(const Rgb& a, const Rgb& b) {
  return std::max({relativeDifference(a.x, b.x), relativeDifference(a.y, b.y), relativeDifference(a.z, b.z)});
}

TEST(MicrofacetConductor, EvalIsReciprocal) {
  for (const Configuration& c : configurations()) {
    const auto model = make(c);
    CounterRng rng(7, 0);
    for (int i = 0; i < 2000; ++i) {
      const Vec3d wi = sampleUniformHemisphere(rng.uniform2D()),
                  wo = sampleUniformHemisphere(rng.uniform2D());
      ASSERT_LE(maxRelativeDifference(model->eval(wi, wo), model->eval(wo, wi)), 1e-12) << describe(c);
    }
  }
}

// docs/validation.md section 2, per sample: weight == f |cos wo| / pdf and the sample's pdf is
// pdf(wi, wo). Relative 1e-10: the weight is computed in a cancelled closed form, so only
// round-off separates the two.
TEST(MicrofacetConductor, SampleWeightAndPdfAreConsistentWithEvalAndPdf) {
  for (const Configuration& c : configurations()) {
    const auto model = make(c);
    for (const Vec3d& wi : incidentDirections()) {
      CounterRng rng(11, 0);
      int accepted = 0;
      for (int i = 0; i < 4000; ++i) {
        const auto s = model->sample(wi, rng.uniform(), rng.uniform2D());
        if (!s) continue;
        ++accepted;
        ASSERT_GT(s->wo.z, 0.0);
        ASSERT_NEAR(glm::length(s->wo), 1.0, 1e-12);
        ASSERT_EQ(s->lobe, LobeFlags::GlossyReflection);
        const double pdf = model->pdf(wi, s->wo);
        ASSERT_LE(relativeDifference(s->pdf, pdf), 1e-10) << describe(c);
        const Rgb expected = model->eval(wi, s->wo) * s->wo.z / pdf;
        ASSERT_LE(maxRelativeDifference(s->weight, expected), 1e-10) << describe(c);
      }
      EXPECT_GT(accepted, 1000) << describe(c);  // the sampler does not fail wholesale
    }
  }
}

TEST(MicrofacetConductor, ZeroBelowTheHorizon) {
  for (const Configuration& c : configurations()) {
    const auto model = make(c);
    const Vec3d up = directionFromDegrees(30, 10), down(0.3, 0.2, -std::sqrt(1.0 - 0.13));
    const Vec3d horizon(1, 0, 0);
    for (const auto& [wi, wo] : {std::pair{up, down}, std::pair{down, up}, std::pair{down, down},
                                 std::pair{up, horizon}, std::pair{horizon, up}}) {
      EXPECT_EQ(model->eval(wi, wo), Rgb(0.0)) << describe(c);
      EXPECT_EQ(model->pdf(wi, wo), 0.0) << describe(c);
    }
    EXPECT_FALSE(model->sample(down, 0.5, Vec2d(0.3, 0.6)).has_value());
    EXPECT_FALSE(model->sample(horizon, 0.5, Vec2d(0.3, 0.6)).has_value());
  }
}

TEST(MicrofacetConductor, FiniteAtGrazingIncidenceAndTinyRoughness) {
  for (const MicrofacetType type : {MicrofacetType::Ggx, MicrofacetType::Beckmann}) {
    for (const MicrofacetSampling sampling : {MicrofacetSampling::Visible, MicrofacetSampling::Classic}) {
      const Configuration c{type, 0.001, 0.001, sampling};
      const auto model = make(c);
      const Vec3d wi = directionFromDegrees(89.99, 25);
      CounterRng rng(3, 0);
      for (int i = 0; i < 20000; ++i) {
        const Vec3d wo = sampleUniformHemisphere(rng.uniform2D());
        ASSERT_TRUE(isFinite(model->eval(wi, wo)) && std::isfinite(model->pdf(wi, wo))) << describe(c);
        const auto s = model->sample(wi, rng.uniform(), rng.uniform2D());
        if (s) {
          ASSERT_TRUE(isFinite(s->weight) && std::isfinite(s->pdf) && s->pdf > 0) << describe(c);
        }
      }
      // The mirror direction itself, where D peaks at 1 / (pi alpha^2).
      const Vec3d mirror(-wi.x, -wi.y, wi.z);
      ASSERT_TRUE(isFinite(model->eval(wi, mirror)) && std::isfinite(model->pdf(wi, mirror)));
    }
  }
}

// A near-perfect mirror (F = 1 - 4e-8 from k = 1e4, alpha 0.001) at normal incidence reflects
// everything: Lambda(wi) = 0, and masking of wo and normals steep enough to send wo below the
// horizon both cost O(alpha^2) = 1e-6, so the directional albedo, the mean sample weight, is
// 1 well within 1e-4.
TEST(MicrofacetConductor, SmoothPerfectConductorHasUnitAlbedo) {
  const Configuration c{MicrofacetType::Ggx, 0.001, 0.001, MicrofacetSampling::Visible};
  const auto model = make(c, Rgb(1.0), Rgb(1e4));
  CounterRng rng(5, 0);
  const int n = 100000;
  Rgb sum(0.0);
  for (int i = 0; i < n; ++i)
    if (const auto s = model->sample(Vec3d(0, 0, 1), rng.uniform(), rng.uniform2D())) sum += s->weight;
  const Rgb albedo = sum / double(n);
  for (int channel = 0; channel < 3; ++channel) EXPECT_NEAR(albedo[channel], 1.0, 1e-4);
}

// The two sampling schemes draw different densities, yet each pdf integrates, over the
// upper hemisphere, to the fraction of samples that do not fail (docs/validation.md section 3),
// and both give the same directional albedo as deterministic quadrature of f |cos|.
TEST(MicrofacetConductor, ClassicAndVisibleSamplingAreBothNormalised) {
  for (const MicrofacetType type : {MicrofacetType::Ggx, MicrofacetType::Beckmann}) {
    const auto visible = make({type, 0.5, 0.3, MicrofacetSampling::Visible});
    const auto classic = make({type, 0.5, 0.3, MicrofacetSampling::Classic});
    const Vec3d wi = directionFromDegrees(70, 30);
    const Vec3d probe = directionFromDegrees(40, -120);
    EXPECT_GT(relativeDifference(visible->pdf(wi, probe), classic->pdf(wi, probe)), 0.05);

    QuadratureOptions options;
    options.relativeTolerance = 1e-8;
    options.minDepth = 4;
    const auto overHemisphere = [&](const auto& f) {
      return adaptiveSimpson2D(
          [&](double cosTheta, double phi) {
            return f(sphericalDirection(safeSqrt(1.0 - cosTheta * cosTheta), cosTheta, phi));
          },
          0.0, 1.0, -Pi, Pi, options);
    };
    const Rgb albedo = overHemisphere([&](const Vec3d& wo) { return visible->eval(wi, wo) * wo.z; });

    for (const BsdfModel* model : {visible.get(), classic.get()}) {
      const double pdfIntegral = overHemisphere([&](const Vec3d& wo) { return model->pdf(wi, wo); });
      const int n = 400000;
      CounterRng rng(13, 0);
      int failures = 0;
      Rgb weightSum(0.0);
      for (int i = 0; i < n; ++i) {
        const auto s = model->sample(wi, rng.uniform(), rng.uniform2D());
        if (s) {
          weightSum += s->weight;
        } else {
          ++failures;
        }
      }
      const double accepted = 1.0 - double(failures) / n;
      // Binomial standard error of the failure fraction; 5 sigma.
      EXPECT_NEAR(pdfIntegral, accepted, 5.0 * std::sqrt(accepted * (1.0 - accepted) / n) + 1e-6)
          << (model == visible.get() ? "visible" : "classic");
      EXPECT_LT(pdfIntegral, 1.0);
      // Relative standard errors of these means are 0.06% (visible) and 0.18% (classic):
      // 1% is more than 5 of them.
      const Rgb estimate = weightSum / double(n);
      for (int channel = 0; channel < 3; ++channel)
        EXPECT_NEAR(estimate[channel] / albedo[channel], 1.0, 0.01)
            << (model == visible.get() ? "visible" : "classic");
    }
  }
}

TEST(MicrofacetConductor, FactoryRejectsNonPositiveRoughness) {
  EXPECT_THROW(makeMicrofacetConductor(MicrofacetType::Ggx, 0.0, 0.1, GoldEta, GoldK), std::invalid_argument);
  EXPECT_THROW(makeMicrofacetConductor(MicrofacetType::Beckmann, 0.1, -1.0, GoldEta, GoldK),
               std::invalid_argument);
  EXPECT_THROW(makeMicrofacetConductor(MicrofacetType::Ggx, std::nan(""), 0.1, GoldEta, GoldK),
               std::invalid_argument);
  const auto model = makeMicrofacetConductor(MicrofacetType::Ggx, 0.1, 0.2, GoldEta, GoldK);
  EXPECT_EQ(model->flags(), LobeFlags::GlossyReflection);
  EXPECT_FALSE(model->isLossless());
  EXPECT_TRUE(model->isReciprocal());
}

// The kernel with T = ceres::Jet, differentiated with respect to alpha and eta: the value the
// BSDF evaluates, and finite derivatives, also at the mirror direction of alpha 0.001 at
// grazing incidence.
TEST(MicrofacetConductor, KernelWithJetsMatchesDoubleAndHasFiniteDerivatives) {
  using Jet = ceres::Jet<double, 2>;
  const auto toJet = [](const Vec3d& v) { return Vec3<Jet>(Jet(v.x), Jet(v.y), Jet(v.z)); };
  for (const double alpha : {0.001, 0.3, 1.0}) {
    const GgxDistribution<Jet> ggx(Jet(alpha, 0), Jet(alpha, 0));
    const BeckmannDistribution<Jet> beckmann(Jet(alpha, 0), Jet(alpha, 0));
    const RgbT<Jet> eta(Jet(GoldEta.x, 1), Jet(GoldEta.y, 1), Jet(GoldEta.z, 1));
    const RgbT<Jet> k(Jet(GoldK.x), Jet(GoldK.y), Jet(GoldK.z));
    const auto ggxModel = makeMicrofacetConductor(MicrofacetType::Ggx, alpha, alpha, GoldEta, GoldK);
    const auto beckmannModel =
        makeMicrofacetConductor(MicrofacetType::Beckmann, alpha, alpha, GoldEta, GoldK);
    for (const Vec3d& wi : incidentDirections()) {
      const Vec3d wos[] = {Vec3d(-wi.x, -wi.y, wi.z), directionFromDegrees(45, 200)};
      for (const Vec3d& wo : wos) {
        const RgbT<Jet> fGgx = microfacetConductorEval<Jet>(ggx, eta, k, toJet(wi), toJet(wo));
        const RgbT<Jet> fBeckmann = microfacetConductorEval<Jet>(beckmann, eta, k, toJet(wi), toJet(wo));
        const Rgb refGgx = ggxModel->eval(wi, wo), refBeckmann = beckmannModel->eval(wi, wo);
        for (int ch = 0; ch < 3; ++ch) {
          ASSERT_TRUE(ceres::isfinite(fGgx[ch]) && ceres::isfinite(fBeckmann[ch]));
          EXPECT_NEAR(fGgx[ch].a, refGgx[ch], 1e-13 * std::max(1.0, refGgx[ch]));
          EXPECT_NEAR(fBeckmann[ch].a, refBeckmann[ch], 1e-13 * std::max(1.0, refBeckmann[ch]));
        }
      }
    }
  }
}

}  // namespace conductor_test
}  // namespace scatterlab
