#include <gtest/gtest.h>

#include "catalog_suite.h"
#include "materials/bsdf/lambertian.h"

namespace scatterlab {
namespace lambertian_test {

TEST(Lambertian, EvalIsAlbedoOverPiAboveAndZeroBelow) {
  const LambertianBsdf model(Rgb(0.2, 0.4, 0.6));
  const Vec3d wi = directionFromDegrees(30, 0), wo = directionFromDegrees(70, 100);
  const Rgb f = model.eval(wi, wo);
  EXPECT_DOUBLE_EQ(f.x, 0.2 / Pi);
  EXPECT_DOUBLE_EQ(f.z, 0.6 / Pi);
  EXPECT_EQ(model.eval(wi, -wo), Rgb(0.0));
  EXPECT_EQ(model.eval(-wi, wo), Rgb(0.0));
  EXPECT_EQ(model.pdf(wi, -wo), 0.0);
}

TEST(Lambertian, SampleWeightIsAlbedo) {
  const LambertianBsdf model(Rgb(0.2, 0.4, 0.6));
  const auto s = model.sample(directionFromDegrees(50, 0), 0.5, {0.3, 0.7});
  ASSERT_TRUE(s);
  EXPECT_EQ(s->weight, Rgb(0.2, 0.4, 0.6));
  EXPECT_DOUBLE_EQ(s->pdf, s->wo.z / Pi);
  EXPECT_EQ(s->lobe, LobeFlags::DiffuseReflection);
}

TEST(Lambertian, DegenerateIncidentDirectionsFailCleanly) {
  const LambertianBsdf model(Rgb(0.5));
  EXPECT_FALSE(model.sample(Vec3d(1, 0, 0), 0.5, {0.5, 0.5}));   // on the horizon
  EXPECT_FALSE(model.sample(Vec3d(0, 0, -1), 0.5, {0.5, 0.5}));  // below
  EXPECT_EQ(model.pdf(Vec3d(1, 0, 0), Vec3d(0, 0, 1)), 0.0);
}

TEST(Lambertian, LosslessOnlyWhenWhite) {
  EXPECT_TRUE(LambertianBsdf(Rgb(1.0)).isLossless());
  EXPECT_FALSE(LambertianBsdf(Rgb(1.0, 1.0, 0.99)).isLossless());
}

const catalog_suite::ChiSquareSuite Suite{"lambertian-kit", int(catalog_suite::incidentAngles().size())};

TEST(Lambertian, PassesTheKitFromNormalToGrazing) {
  catalog_suite::expectPasses(LambertianBsdf(Rgb(1.0)), "lambertian-white", Suite.options());
}

TEST(Lambertian, TwoSidedWrapperFlipsBackfacingDirections) {
  const LambertianBsdf model(Rgb(0.5));
  const Bsdf bsdf(model, Framed::fromNormal({0, 0, 1}));
  const Vec3d wi(0, 0.6, -0.8), wo(0.6, 0, -0.8);  // both below: the back face
  EXPECT_DOUBLE_EQ(bsdf.eval(wi, wo).x, 0.5 / Pi);
  const auto s = bsdf.sample(wi, 0.5, {0.2, 0.9});
  ASSERT_TRUE(s);
  EXPECT_LT(s->wo.z, 0.0);
  const Bsdf oneSided(model, Framed::fromNormal({0, 0, 1}), false);
  EXPECT_EQ(oneSided.eval(wi, wo), Rgb(0.0));
}

}  // namespace lambertian_test
}  // namespace scatterlab
