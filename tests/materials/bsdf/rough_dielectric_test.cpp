// The rough dielectric (rough_dielectric.h) at fixed directions against Walter et al. 2007's
// equations written out here from the paper's notation (eq. 13 and 16 for the half vectors,
// 20 and 21 for f, 22 for Fresnel, 33 and 25 for D), with Smith's Lambda from Heitz 2014 and
// the Beta function from std::lgamma: reflection and refraction, from outside and inside,
// both transport modes. Then total internal reflection, the generalised reciprocity, the
// sampler's pieces, Jet derivatives, the smooth limit of the albedo, and the registry.
#include "materials/bsdf/rough_dielectric.h"

#include <ceres/jet.h>
#include <gtest/gtest.h>

#include "materials/bsdf/rough_dielectric_albedo.h"
#include "materials/core/rng.h"
#include "materials/core/warp.h"
#include "materials/registry/material_file.h"
#include "materials/registry/spec_validation.h"

namespace scatterlab {
namespace rough_dielectric_test {

// ---- Walter et al. 2007, independently ----

struct Roughness {
  MicrofacetType type;
  double ax, ay;
};

// tan^2 theta_m (cos^2 phi / ax^2 + sin^2 phi / ay^2) from the angles of m.
double slopeTerm(const Roughness& r, const Vec3d& m) {
  const double theta = std::acos(m.z), phi = std::atan2(m.y, m.x);
  return std::pow(std::tan(theta), 2) *
         (std::pow(std::cos(phi) / r.ax, 2) + std::pow(std::sin(phi) / r.ay, 2));
}

// GGX: 1 / (pi ax ay cos^4 (1 + t)^2) (eq. 33); Beckmann: exp(-t) / (pi ax ay cos^4) (eq. 25).
double walterD(const Roughness& r, const Vec3d& m) {
  const double t = slopeTerm(r, m), cos4 = std::pow(m.z, 4);
  return r.type == MicrofacetType::Ggx ? 1 / (Pi * r.ax * r.ay * cos4 * std::pow(1 + t, 2))
                                       : std::exp(-t) / (Pi * r.ax * r.ay * cos4);
}

// Heitz 2014: with a = 1 / (alpha(phi) tan theta), alpha(phi)^2 = cos^2 phi ax^2 + sin^2 phi ay^2,
// GGX Lambda = (-1 + sqrt(1 + 1 / a^2)) / 2, Beckmann (erf(a) - 1) / 2 + exp(-a^2) / (2 a sqrt(pi)).
double smithLambda(const Roughness& r, const Vec3d& w) {
  const double theta = std::acos(std::abs(w.z)), phi = std::atan2(w.y, w.x);
  if (theta == 0) return 0;
  const double alpha = std::sqrt(std::pow(std::cos(phi) * r.ax, 2) + std::pow(std::sin(phi) * r.ay, 2));
  const double a = 1 / (alpha * std::tan(theta));
  return r.type == MicrofacetType::Ggx ? (-1 + std::sqrt(1 + 1 / (a * a))) / 2
                                       : (std::erf(a) - 1) / 2 + std::exp(-a * a) / (2 * a * SqrtPi);
}

// Height-correlated masking-shadowing: 1 / (1 + Li + Lo) for reflection (Heitz eq. 99),
// B(1 + Li, 1 + Lo) for refraction (Heitz section 6.3).
double smithG2(const Roughness& r, const Vec3d& i, const Vec3d& o) {
  const double li = smithLambda(r, i), lo = smithLambda(r, o);
  if (i.z * o.z > 0) return 1 / (1 + li + lo);
  return std::exp(std::lgamma(1 + li) + std::lgamma(1 + lo) - std::lgamma(2 + li + lo));
}

// Walter eq. 22 with c = |i.m|, relative index eta_t / eta_i: g^2 = eta^2 - 1 + c^2,
// F = (g - c)^2 / (2 (g + c)^2) (1 + (c (g + c) - 1)^2 / (c (g - c) + 1)^2); 1 if g^2 < 0.
double walterFresnel(double c, double etaRel) {
  const double g2 = etaRel * etaRel - 1 + c * c;
  if (g2 < 0) return 1;
  const double g = std::sqrt(g2);
  return std::pow(g - c, 2) / (2 * std::pow(g + c, 2)) *
         (1 + std::pow(c * (g + c) - 1, 2) / std::pow(c * (g - c) + 1, 2));
}

// Walter's f_s(i, o) for light arriving from i and leaving toward o (radiance BSDF), with the
// interior index eta below the surface: eq. 20 (h_r = sign(i.n) (i + o) normalised, eq. 13)
// or eq. 21 (h_t = -(n_i i + n_o o) normalised, eq. 16).
double walterBsdf(const Roughness& r, double eta, const Vec3d& i, const Vec3d& o) {
  const double ni = i.z > 0 ? 1 : eta, no = o.z > 0 ? 1 : eta;
  if (i.z * o.z > 0) {
    Vec3d h = (i.z > 0 ? 1.0 : -1.0) * glm::normalize(i + o);
    const double c = std::abs(glm::dot(i, h));
    // D is of the facet's upward normal.
    const Vec3d m = h.z > 0 ? h : -h;
    return walterFresnel(c, (i.z > 0 ? eta : 1 / eta)) * smithG2(r, i, o) * walterD(r, m) /
           (4 * std::abs(i.z * o.z));
  }
  const Vec3d ht = -glm::normalize(ni * i + no * o);
  const double ih = glm::dot(i, ht), oh = glm::dot(o, ht);
  const Vec3d m = ht.z > 0 ? ht : -ht;
  // A facet seen from behind by either direction scatters nothing (Walter section 5.3).
  if (glm::dot(i, m) * i.z <= 0 || glm::dot(o, m) * o.z <= 0) return 0;
  const double fresnel = walterFresnel(std::abs(ih), no / ni);
  return std::abs(ih) * std::abs(oh) / std::abs(i.z * o.z) * no * no * (1 - fresnel) * smithG2(r, i, o) *
         walterD(r, m) / std::pow(ni * ih + no * oh, 2);
}

// scatterlab's arguments: radiance mode has light arriving from wo and leaving toward wi;
// importance mode the reverse (bsdf.h).
double expectedEval(const Roughness& r, double eta, const Vec3d& wi, const Vec3d& wo, TransportMode mode) {
  return mode == TransportMode::Radiance ? walterBsdf(r, eta, wo, wi) : walterBsdf(r, eta, wi, wo);
}

std::unique_ptr<BsdfModel> make(const Roughness& r, double eta) {
  return makeRoughDielectric(r.type, r.ax, r.ay, eta);
}

const std::vector<Roughness> Roughnesses{{MicrofacetType::Ggx, 0.3, 0.3},
                                         {MicrofacetType::Ggx, 0.5, 0.15},
                                         {MicrofacetType::Beckmann, 0.25, 0.25},
                                         {MicrofacetType::Beckmann, 0.1, 0.4}};

struct Pair {
  Vec3d wi, wo;
};
// Reflection above and below, refraction down and up, one near grazing.
const std::vector<Pair>& fixedPairs() {
  static const std::vector<Pair> pairs{
      {directionFromDegrees(30, 10), directionFromDegrees(40, 200)},    // reflection, outside
      {directionFromDegrees(150, 20), directionFromDegrees(135, 210)},  // internal reflection
      {directionFromDegrees(30, 10), directionFromDegrees(160, 185)},   // refraction into the medium
      {directionFromDegrees(45, 0), directionFromDegrees(150, 200)},
      {directionFromDegrees(165, 30), directionFromDegrees(20, 220)},  // refraction out of it
      {directionFromDegrees(170, 0), directionFromDegrees(60, 170)},
      {directionFromDegrees(85, 60), directionFromDegrees(120, 250)},  // grazing
  };
  return pairs;
}

TEST(RoughDielectric, EvalIsWaltersEquationsFromBothSidesInBothModes) {
  int refractionPairsWithValue = 0;
  for (const Roughness& r : Roughnesses)
    for (const double eta : {1.1, 1.5, 2.4}) {
      const auto model = make(r, eta);
      for (const Pair& p : fixedPairs())
        for (const TransportMode mode : {TransportMode::Radiance, TransportMode::Importance}) {
          const double expected = expectedEval(r, eta, p.wi, p.wo, mode);
          const double f = model->eval(p.wi, p.wo, mode).x;
          EXPECT_NEAR(f, expected, 1e-10 * expected + 1e-300)
              << "eta " << eta << " alpha (" << r.ax << ", " << r.ay << ") wi.z " << p.wi.z << " wo.z "
              << p.wo.z;
          if (p.wi.z * p.wo.z < 0 && expected > 0) ++refractionPairsWithValue;
        }
    }
  // The refraction pairs are not all facets seen from behind: most carry light.
  EXPECT_GT(refractionPairsWithValue, 60);
}

// Radiance through a refraction carries 1 / etaRel^2 relative to importance, etaRel = n(wo) /
// n(wi) (Veach 1997 section 5.2); reflection is the same in both modes.
TEST(RoughDielectric, RadianceIsImportanceOverEtaRelSquared) {
  const double eta = 1.5;
  const auto model = make(Roughnesses[1], eta);
  for (const Pair& p : fixedPairs()) {
    const double radiance = model->eval(p.wi, p.wo, TransportMode::Radiance).x;
    const double importance = model->eval(p.wi, p.wo, TransportMode::Importance).x;
    const double etaRel = p.wi.z * p.wo.z > 0 ? 1.0 : (p.wi.z > 0 ? eta : 1 / eta);
    EXPECT_NEAR(radiance, importance / (etaRel * etaRel), 1e-14 * importance);
  }
}

// Veach 1997 eq. 5.14 in scatterlab's conventions (validation/reciprocity.h).
TEST(RoughDielectric, GeneralisedReciprocity) {
  const double eta = 2.4;
  const auto model = make(Roughnesses[3], eta);
  CounterRng rng(3, 0);
  int tested = 0;
  for (int k = 0; k < 4000; ++k) {
    const Vec3d wi = sampleUniformSphere(rng.uniform2D()), wo = sampleUniformSphere(rng.uniform2D());
    const double ni = wi.z > 0 ? 1 : eta, no = wo.z > 0 ? 1 : eta;
    const double fI = model->eval(wi, wo, TransportMode::Importance).x;
    if (fI == 0) continue;
    ++tested;
    // The reversed pair computes h from wo + wi / etaRel instead of wi + etaRel wo: equal up
    // to rounding, which Beckmann's exp(-tan^2 / alpha^2) amplifies in its far tail (1e-200).
    EXPECT_LT(
        relativeDifference(fI / (no * no), model->eval(wo, wi, TransportMode::Importance).x / (ni * ni)),
        1e-10);
    EXPECT_LT(relativeDifference(model->eval(wi, wo, TransportMode::Radiance).x / (ni * ni),
                                 model->eval(wo, wi, TransportMode::Radiance).x / (no * no)),
              1e-10);
    EXPECT_LT(relativeDifference(model->eval(wi, wo, TransportMode::Radiance).x,
                                 model->eval(wo, wi, TransportMode::Importance).x),
              1e-10);
  }
  EXPECT_GT(tested, 1000);
}

// From inside beyond the critical angle (41.8 degrees for eta 1.5) a facet near the normal
// reflects everything: F = 1 (Walter's g^2 < 0), refraction impossible, f of the internal
// reflection is Walter's with F = 1; only facets tilted back below the critical angle refract.
TEST(RoughDielectric, TotalInternalReflection) {
  const double eta = 1.5;
  const Roughness r{MicrofacetType::Ggx, 0.02, 0.02};
  const auto model = make(r, eta);
  const GgxDistribution<double> ggx(r.ax, r.ay);
  const Vec3d wi = directionFromDegrees(180 - 60, 30);  // 60 degrees inside
  const Vec3d m(0, 0, 1);
  EXPECT_EQ(fresnelDielectric(glm::dot(wi, m), eta), 1.0);
  EXPECT_FALSE(scatterRoughDielectric(ggx, eta, wi, m, true, TransportMode::Radiance).has_value());
  const auto reflected = scatterRoughDielectric(ggx, eta, wi, m, false, TransportMode::Radiance);
  ASSERT_TRUE(reflected.has_value());
  EXPECT_NEAR(model->eval(wi, reflected->wo).x,
              smithG2(r, wi, reflected->wo) * walterD(r, m) / (4 * wi.z * reflected->wo.z),
              1e-9 * model->eval(wi, reflected->wo).x);
  // With alpha 0.02 the visible facets are within a few degrees of the normal, but GGX's long
  // tail holds a few tilted by more than 18 degrees, where the local incidence is below the
  // critical angle: a refracted sample must have come through such a facet, and they are rare.
  const double cosCritical = std::cos(std::asin(1 / eta));
  int refracted = 0;
  const int n = 20000;
  for (uint64_t i = 0; i < n; ++i) {
    CounterRng g(5, i);
    const double uLobe = g.uniform();
    const auto s = model->sample(wi, uLobe, g.uniform2D());
    if (!s || s->lobe != LobeFlags::GlossyTransmission) continue;
    ++refracted;
    const Vec3d h = generalizedHalfVector(wi, s->wo, 1 / eta);
    EXPECT_GT(std::abs(glm::dot(wi, h)), cosCritical);
  }
  EXPECT_LT(refracted, n / 100);
  EXPECT_LT(roughDielectricAlbedo(ggx, eta, wi, TransportMode::Importance).transmission, 0.01);
  // Below the critical angle, refraction is back.
  const Vec3d before = directionFromDegrees(180 - 30, 30);
  EXPECT_GT(roughDielectricAlbedo(ggx, eta, before, TransportMode::Importance).transmission, 0.9);
}

// The sampler's weight is f |cos wo| / pdf in closed form, G2 / G1(wi) (/ etaRel^2 for
// radiance through a refraction), its pdf is pdf(), and eta the relative index; the kit
// checks this on a million samples, here a few fixed ones from both sides.
TEST(RoughDielectric, SampleMatchesEvalAndPdf) {
  const double eta = 1.5;
  const auto model = make(Roughnesses[1], eta);
  for (const double theta : {0.0, 40.0, 80.0, 100.0, 140.0, 180.0})
    for (const TransportMode mode : {TransportMode::Radiance, TransportMode::Importance}) {
      const Vec3d wi = directionFromDegrees(theta, 70);
      int reflections = 0, refractions = 0;
      for (uint64_t i = 0; i < 500; ++i) {
        CounterRng g(9, i);
        const double uLobe = g.uniform();
        const auto s = model->sample(wi, uLobe, g.uniform2D(), mode);
        if (!s) continue;
        const double pdf = model->pdf(wi, s->wo, mode);
        EXPECT_EQ(s->pdf, pdf);
        const double f = model->eval(wi, s->wo, mode).x;
        EXPECT_NEAR(s->weight.x, f * std::abs(s->wo.z) / pdf, 1e-10 * s->weight.x);
        const bool refracted = s->wo.z * wi.z < 0;
        EXPECT_EQ(s->lobe, refracted ? LobeFlags::GlossyTransmission : LobeFlags::GlossyReflection);
        EXPECT_EQ(s->eta, refracted ? (wi.z > 0 ? eta : 1 / eta) : 1.0);
        (refracted ? refractions : reflections) += 1;
      }
      // 80 degrees inside (100) is beyond the critical angle: only steep facets refract.
      if (theta != 100.0) {
        EXPECT_GT(refractions, 0) << theta;
      }
      EXPECT_GT(reflections, 0) << theta;
    }
}

// As alpha -> 0 the facets are the macro-surface and G -> 1: the reflection albedo is the
// smooth interface's Fresnel reflectance and the transmission albedo (importance) the rest,
// from both sides. alpha = 0.001 leaves ~alpha tan(theta) of masking.
TEST(RoughDielectric, SmoothLimitAlbedoIsFresnel) {
  const double eta = 1.5;
  const GgxDistribution<double> ggx(0.001, 0.001);
  for (const double theta : {0.0, 30.0, 60.0, 150.0, 170.0}) {
    const Vec3d wi = directionFromDegrees(theta, 20);
    const LobeAlbedo e = roughDielectricAlbedo(ggx, eta, wi, TransportMode::Importance);
    const double r = fresnelDielectric(wi.z, eta);
    EXPECT_NEAR(e.reflection, r, 2e-4) << theta;
    EXPECT_NEAR(e.transmission, 1 - r, 2e-3) << theta;
    // Radiance: the transmitted part scaled by 1 / etaRel^2.
    const double etaRel = wi.z > 0 ? eta : 1 / eta;
    const LobeAlbedo radiance = roughDielectricAlbedo(ggx, eta, wi, TransportMode::Radiance);
    EXPECT_NEAR(radiance.transmission, e.transmission / (etaRel * etaRel), 1e-6) << theta;
  }
}

// The kernel with T = ceres::Jet, differentiated with respect to (alphaX, alphaY, eta): the
// same value as double, derivatives equal to central differences (what fitting relies on).
TEST(RoughDielectricJet, DerivativesMatchCentralDifferences) {
  using Jet = ceres::Jet<double, 3>;
  const double ax = 0.3, ay = 0.12, eta = 1.45, h = 1e-6;
  const auto toJet = [](const Vec3d& v) { return Vec3<Jet>(Jet(v.x), Jet(v.y), Jet(v.z)); };
  for (const bool beckmann : {false, true})
    for (const Pair& p : fixedPairs())
      for (const TransportMode mode : {TransportMode::Radiance, TransportMode::Importance}) {
        const auto evalDouble = [&](double x, double y, double e) {
          return beckmann
                     ? roughDielectricEval<double>(BeckmannDistribution<double>(x, y), e, p.wi, p.wo, mode)
                     : roughDielectricEval<double>(GgxDistribution<double>(x, y), e, p.wi, p.wo, mode);
        };
        const Jet jx(ax, 0), jy(ay, 1), je(eta, 2);
        const Jet f = beckmann ? roughDielectricEval<Jet>(BeckmannDistribution<Jet>(jx, jy), je, toJet(p.wi),
                                                          toJet(p.wo), mode)
                               : roughDielectricEval<Jet>(GgxDistribution<Jet>(jx, jy), je, toJet(p.wi),
                                                          toJet(p.wo), mode);
        const double value = evalDouble(ax, ay, eta);
        ASSERT_TRUE(ceres::isfinite(f));
        EXPECT_NEAR(f.a, value, 1e-13 * std::max(1.0, value));
        const double d[] = {(evalDouble(ax + h, ay, eta) - evalDouble(ax - h, ay, eta)) / (2 * h),
                            (evalDouble(ax, ay + h, eta) - evalDouble(ax, ay - h, eta)) / (2 * h),
                            (evalDouble(ax, ay, eta + h) - evalDouble(ax, ay, eta - h)) / (2 * h)};
        for (int k = 0; k < 3; ++k)
          EXPECT_NEAR(f.v[k], d[k], 1e-5 * std::max(1.0, std::abs(d[k])))
              << "parameter " << k << " wi.z " << p.wi.z;
      }
}

TEST(RoughDielectric, FlagsIndexAndEnergyHonesty) {
  const auto model = make(Roughnesses[0], 1.5);
  EXPECT_EQ(model->flags(), LobeFlags::GlossyReflection | LobeFlags::GlossyTransmission);
  EXPECT_EQ(model->interiorIndex(), 1.5);
  EXPECT_FALSE(model->isLossless());  // single scattering: rough_dielectric_energy_test.cpp
  EXPECT_EQ(model->eval(Vec3d(1, 0, 0), directionFromDegrees(30, 0)), Rgb(0.0));
  EXPECT_FALSE(model->sample(Vec3d(1, 0, 0), 0.5, {0.5, 0.5}).has_value());
  EXPECT_THROW(makeRoughDielectric(MicrofacetType::Ggx, 0.1, 0.1, 1.0), std::invalid_argument);
  EXPECT_THROW(makeRoughDielectric(MicrofacetType::Ggx, 0.0, 0.1, 1.5), std::invalid_argument);
  EXPECT_THROW(makeRoughDielectric(MicrofacetType::Beckmann, 0.1, 0.1, NAN), std::invalid_argument);
}

TEST(RoughDielectric, RegistryDefaultsRangesAndExampleFiles) {
  const auto defaults = makeBsdf({{"type", "rough-dielectric"}});
  EXPECT_EQ(defaults->interiorIndex(), 1.5);
  EXPECT_EQ(completeMaterial({{"type", "rough-dielectric"}}), (nlohmann::json{{"type", "rough-dielectric"},
                                                                              {"distribution", "ggx"},
                                                                              {"alpha", 0.1},
                                                                              {"eta", 1.5},
                                                                              {"multiscatter", "none"}}));
  EXPECT_NO_THROW(makeBsdf(
      {{"type", "rough-dielectric"}, {"distribution", "beckmann"}, {"alpha", {0.001, 1.0}}, {"eta", 4.0}}));
  EXPECT_THROW(makeBsdf({{"type", "rough-dielectric"}, {"eta", 1.0}}), MaterialError);
  // Below 1.02 the refracted lobe is too narrow for the kit to check
  // (materials/bsdf/dielectric_index_spec.h).
  EXPECT_NO_THROW(makeBsdf({{"type", "rough-dielectric"}, {"eta", 1.02}}));
  try {
    makeBsdf({{"type", "rough-dielectric"}, {"eta", 1.01}});
    ADD_FAILURE() << "eta 1.01 accepted";
  } catch (const MaterialError& error) {
    EXPECT_NE(std::string(error.what()).find("in [1.02, 4]"), std::string::npos) << error.what();
  }
  EXPECT_THROW(makeBsdf({{"type", "rough-dielectric"}, {"alpha", 0.0005}}), MaterialError);
  EXPECT_THROW(makeBsdf({{"type", "rough-dielectric"}, {"alpha", {0.1, 1.5}}}), MaterialError);
  EXPECT_THROW(makeBsdf({{"type", "rough-dielectric"}, {"distribution", "phong"}}), MaterialError);
  EXPECT_THROW(makeBsdf({{"type", "rough-dielectric"}, {"metal", "Au"}}), MaterialError);
  const auto rougher = withMismatchedRoughness({{"type", "rough-dielectric"}, {"alpha", 0.2}}, 1.1);
  ASSERT_TRUE(rougher.has_value());
  EXPECT_DOUBLE_EQ((*rougher)["alpha"].get<double>(), 0.22);
  for (const char* file : {"frosted-glass-ggx.json", "diamond-brushed-beckmann.json"}) {
    SCOPED_TRACE(file);
    const auto path = std::filesystem::path(SCATTERLAB_DATA_DIR) / "materials" / file;
    const auto model = makeBsdf(loadMaterialArgument(path.string()));
    EXPECT_GT(model->pdf(directionFromDegrees(30, 0), directionFromDegrees(160, 180)), 0.0);
  }
}

}  // namespace rough_dielectric_test
}  // namespace scatterlab
