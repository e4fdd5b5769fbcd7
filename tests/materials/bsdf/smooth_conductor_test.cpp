// The smooth conductor (smooth_conductor.h): the mirror's reflectance against the Fresnel
// equations in complex arithmetic (written out here with std::complex, independent of
// fresnel.h's real-arithmetic form), the delta conventions, the kit, and the registry entry,
// whose index parameters are the conductor's.
//
// Negative controls: as for every delta model (delta_dielectric_test.cpp), the kit's four
// controls change only pdf(), which is 0 here: they are reported "not applicable". The one
// statistical error a one-lobe delta sampler can make is a discrete probability other than
// 1, which the chi-square's count check rejects (tests/validation/delta_lobe_test.cpp).
#include <gtest/gtest.h>

#include <complex>

#include "catalog_suite.h"
#include "materials/bsdf/metals.h"
#include "materials/bsdf/smooth_conductor.h"
#include "materials/registry/material_file.h"
#include "materials/registry/model_list.h"
#include "materials/registry/spec_validation.h"

namespace scatterlab {
namespace smooth_conductor_test {

using nlohmann::json;

// Born & Wolf section 14.2 with the complex index n = eta + i k:
// r_s = (cos - sqrt(n^2 - sin^2)) / (cos + sqrt(n^2 - sin^2)),
// r_p = (n^2 cos - sqrt(n^2 - sin^2)) / (n^2 cos + sqrt(n^2 - sin^2)), R = (|r_s|^2 + |r_p|^2) / 2.
double complexFresnel(double cosTheta, double eta, double k) {
  const std::complex<double> n(eta, k), n2 = n * n;
  const double sin2 = 1 - cosTheta * cosTheta;
  const std::complex<double> root = std::sqrt(n2 - sin2);
  const std::complex<double> rs = (cosTheta - root) / (cosTheta + root);
  const std::complex<double> rp = (n2 * cosTheta - root) / (n2 * cosTheta + root);
  return (std::norm(rs) + std::norm(rp)) / 2;
}

TEST(SmoothConductor, ReflectanceIsTheComplexFresnelEquations) {
  const MetalIor* gold = findMetal("Au");
  const Rgb coloredEta(0.2, 1.1, 3.0), coloredK(3.9, 2.0, 0.0);
  for (const auto& [eta, k] : {std::pair{gold->eta, gold->k}, std::pair{coloredEta, coloredK}}) {
    const SmoothConductorBsdf model(eta, k);
    for (const double theta : {0.0, 30.0, 60.0, 85.0, 89.9}) {
      const Vec3d wi = directionFromDegrees(theta, 40);
      const auto s = model.sample(wi, 0.5, {0.5, 0.5});
      ASSERT_TRUE(s.has_value());
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(s->weight[c], complexFresnel(wi.z, eta[c], k[c]), 1e-12)
            << "theta " << theta << " channel " << c;
    }
  }
}

TEST(SmoothConductor, PerfectMirrorDeltaLobeOneSided) {
  const MetalIor* silver = findMetal("Ag");
  const SmoothConductorBsdf model(silver->eta, silver->k);
  const Vec3d wi = directionFromDegrees(50, 120);
  for (const TransportMode mode : {TransportMode::Radiance, TransportMode::Importance}) {
    const auto s = model.sample(wi, 0.9, {0.1, 0.7}, mode);
    ASSERT_TRUE(s.has_value());
    EXPECT_EQ(s->wo, Vec3d(-wi.x, -wi.y, wi.z));
    EXPECT_EQ(s->pdf, 1.0);
    EXPECT_EQ(s->lobe, LobeFlags::SpecularReflection);
    EXPECT_EQ(s->eta, 1.0);
    EXPECT_EQ(model.eval(wi, s->wo, mode), Rgb(0.0));
    EXPECT_EQ(model.pdf(wi, s->wo, mode), 0.0);
  }
  EXPECT_FALSE(model.sample(Vec3d(0.6, 0, -0.8), 0.5, {0.5, 0.5}).has_value());
  EXPECT_FALSE(model.isLossless());
  EXPECT_EQ(model.flags(), LobeFlags::SpecularReflection);
}

TEST(SmoothConductor, RegistrySharesTheConductorsIndexParameters) {
  const MaterialModel* smooth = findMaterialModel("smooth-conductor");
  const MaterialModel* rough = findMaterialModel("conductor");
  ASSERT_TRUE(smooth && rough);
  EXPECT_EQ(smooth->alternatives, rough->alternatives);
  for (const char* key : {"metal", "eta", "k"}) {
    const ParameterSpec* a = smooth->findParameter(key);
    const ParameterSpec* b = rough->findParameter(key);
    ASSERT_TRUE(a && b) << key;
    EXPECT_EQ(a->allowed(), b->allowed()) << key;
    EXPECT_EQ(a->defaultValue, b->defaultValue) << key;
    EXPECT_EQ(a->description, b->description) << key;
  }
  EXPECT_EQ(smooth->parameters.size(), 3u);
}

TEST(SmoothConductor, RegistryBuildsFromAMetalOrFromEtaAndK) {
  const Vec3d wi = directionFromDegrees(45, 0);
  const auto defaults = makeBsdf({{"type", "smooth-conductor"}});  // gold
  const MetalIor* gold = findMetal("Au");
  EXPECT_EQ(defaults->sample(wi, 0.5, {0.5, 0.5})->weight, fresnelConductor(wi.z, gold->eta, gold->k));
  const auto direct =
      makeBsdf({{"type", "smooth-conductor"}, {"eta", {0.2, 0.9, 1.4}}, {"k", {3.9, 2.4, 1.6}}});
  EXPECT_NEAR(direct->sample(wi, 0.5, {0.5, 0.5})->weight.x, complexFresnel(wi.z, 0.2, 3.9), 1e-12);
  EXPECT_THROW(makeBsdf({{"type", "smooth-conductor"}, {"metal", "Au"}, {"eta", 1.0}, {"k", 1.0}}),
               MaterialError);
  EXPECT_THROW(makeBsdf({{"type", "smooth-conductor"}, {"eta", 1.0}}), MaterialError);  // k missing
  EXPECT_THROW(makeBsdf({{"type", "smooth-conductor"}, {"eta", 0.0}, {"k", 1.0}}), MaterialError);
  EXPECT_THROW(makeBsdf({{"type", "smooth-conductor"}, {"metal", "Unobtainium"}}), MaterialError);
  EXPECT_THROW(makeBsdf({{"type", "smooth-conductor"}, {"alpha", 0.1}}), MaterialError);
  const auto path = std::filesystem::path(SCATTERLAB_DATA_DIR) / "materials" / "silver-mirror.json";
  EXPECT_NO_THROW(makeBsdf(loadMaterialArgument(path.string())));
}

// One-sided: the kit's angles from above only (no transmission, so none are added).
const std::vector<double> KitAngles{0, 60, 89.9};
// Two materials at each angle.
const catalog_suite::ChiSquareSuite Suite{"smooth-conductor-kit", 2 * int(KitAngles.size())};

TEST(SmoothConductorKit, PassesEveryCheck) {
  for (const json& material :
       {json{{"type", "smooth-conductor"}, {"metal", "Cu"}},
        json{{"type", "smooth-conductor"}, {"eta", {0.2, 1.1, 3.0}}, {"k", {3.9, 2.0, 0.0}}}}) {
    const auto model = makeBsdf(material);
    BsdfCheckOptions o = Suite.options();
    o.wiThetaDeg = KitAngles;
    o.samples = 200'000;  // one delta direction: the test is its count
    o.thetaBins = 32;
    o.phiBins = 64;
    const CheckReport report = runBsdfChecks(*model, material.dump(), o);
    EXPECT_TRUE(report.passed()) << formatTable(report);
    EXPECT_EQ(chiSquareTestCount(o, *model), int(KitAngles.size()));
  }
}

TEST(SmoothConductorKit, GenericControlsAreReportedNotApplicable) {
  const auto model = makeBsdf({{"type", "smooth-conductor"}});
  BsdfCheckOptions o = Suite.options();
  o.wiThetaDeg = {30};
  o.samples = 100000;
  o.imageDir.reset();
  for (const CheckRow& row : runNegativeControls(*model, nullptr, "smooth-conductor", o).rows) {
    EXPECT_TRUE(row.passed) << row.test;
    EXPECT_EQ(row.note.rfind("not applicable", 0), 0u) << row.test << ": " << row.note;
  }
}

}  // namespace smooth_conductor_test
}  // namespace scatterlab
