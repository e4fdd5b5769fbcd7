// The far-field BRDF of a subsurface material (subsurface_far_field_brdf.h): the kit passes
// (cosine sampling against its pdf, weights, normalisation, reciprocity), the negative controls
// are rejected, its directional albedo is Ft(wi) Rd (the normalisation c of the separable
// BSSRDF), and the registry's makeFarFieldBsdf gives it for subsurface materials and the
// material's own BSDF otherwise.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "materials/bsdf/catalog_suite.h"
#include "materials/bssrdf/subsurface_far_field_brdf.h"
#include "materials/bssrdf/subsurface_registry.h"
#include "materials/core/quadrature.h"

namespace scatterlab {
namespace subsurface_far_field_brdf_test {

using nlohmann::json;

// Two media and two profiles: a smooth and a tinted Fresnel, the dipole's and Burley's Rd.
const json Materials[] = {
    {{"type", "subsurface"}, {"profile", "dipole"}, {"medium", "Skin1"}},
    {{"type", "subsurface"}, {"profile", "burley"}, {"medium", "Marble"}, {"eta", 1.5}},
};
constexpr int MaterialCount = 2;
// A cosine sampler needs neither the suite's grazing angles nor its 1e6 samples to be seen right.
const std::vector<double> KitAngles{0, 60, 85};
// The file's Sidak family: one chi-square test per material and angle (catalog_suite.h).
const catalog_suite::ChiSquareSuite Suite("far-field", MaterialCount* int(KitAngles.size()));

std::unique_ptr<BsdfModel> farField(const json& material) { return makeFarFieldBsdf(material); }

TEST(SubsurfaceFarFieldBrdf, PassesTheKit) {
  BsdfCheckOptions o = Suite.options();
  o.wiThetaDeg = KitAngles;
  o.samples = 200'000;
  for (const json& material : Materials) catalog_suite::expectPasses(*farField(material), material.dump(), o);
}

// PdfHighOnHalf can never be a no-op and must be rejected; the others may be not applicable
// (a cosine sampler has no roughness and a pdf without wi).
TEST(SubsurfaceFarFieldBrdf, NegativeControlsAreRejected) {
  const auto model = farField(Materials[0]);
  BsdfCheckOptions o = Suite.options();
  o.wiThetaDeg = {30};
  o.imageDir.reset();
  const CheckReport report = runNegativeControls(*model, nullptr, "far field", o);
  ASSERT_EQ(report.rows.size(), allNegativeControls().size());
  for (size_t i = 0; i < report.rows.size(); ++i) {
    const CheckRow& row = report.rows[i];
    EXPECT_TRUE(row.passed) << row.test << ": " << row.note;
    if (allNegativeControls()[i] == NegativeControl::PdfHighOnHalf) {
      EXPECT_EQ(row.note.rfind("rejected", 0), 0u) << row.test << ": " << row.note;
    }
  }
}

// Integral of f |cos wo| over the hemisphere = Ft(wi) Rd: f depends on wo through cos theta_o
// only, so the integral is 2 pi times one over mu = cos theta_o, by adaptive Simpson to 1e-12.
TEST(SubsurfaceFarFieldBrdf, DirectionalAlbedoIsTransmittedTotalReflectance) {
  for (const json& material : Materials) {
    const SubsurfaceMaterial subsurface = makeSubsurface(material);
    const SubsurfaceFarFieldBrdf model(subsurface.bssrdf());
    for (const double thetaDeg : {0.0, 45.0, 80.0}) {
      const Vec3d wi = directionFromDegrees(thetaDeg, 0);
      QuadratureOptions quadrature;
      quadrature.relativeTolerance = 1e-12;
      const Rgb albedo = 2.0 * Pi *
                         adaptiveSimpson(
                             [&](double mu) {
                               const Vec3d wo(std::sqrt(1 - mu * mu), 0, mu);
                               return model.eval(wi, wo) * mu;
                             },
                             0.0, 1.0, quadrature);
      const double ft = 1.0 - fresnelDielectric(wi.z, subsurface.medium.eta);
      const Rgb expected = ft * subsurface.profile->totalReflectance();
      // The quadrature's 1e-12 and fresnelMoment's 1e-12 (fresnel_moments.h) in c.
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(albedo[c], expected[c], 1e-10 * expected[c]) << material << " at " << thetaDeg;
    }
  }
}

TEST(SubsurfaceFarFieldBrdf, RegistryGivesItForSubsurfaceAndTheBsdfOtherwise) {
  const Vec3d wi = directionFromDegrees(30, 0), wo = directionFromDegrees(50, 140);
  const json subsurface = Materials[0];
  const SubsurfaceFarFieldBrdf direct(makeSubsurface(subsurface).bssrdf());
  EXPECT_EQ(farField(subsurface)->eval(wi, wo), direct.eval(wi, wo));
  const json conductor{{"type", "conductor"}, {"alpha", 0.3}};
  EXPECT_EQ(farField(conductor)->eval(wi, wo), makeBsdf(conductor)->eval(wi, wo));
  EXPECT_THROW(farField(json{{"type", "subsurface"}, {"scale", -1}}), MaterialError);
}

}  // namespace subsurface_far_field_brdf_test
}  // namespace scatterlab
