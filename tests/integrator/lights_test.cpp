// Sphere lights and the sun: their direction samplers draw exactly their pdfs (chi-square
// kit, with a negative control), sample and pdf agree, and the sun's radiance integrates to
// its irradiance.
#include <gtest/gtest.h>

#include "integrator/lights.h"
#include "materials/core/quadrature.h"
#include "validation/chi_square.h"

namespace scatterlab {
namespace lights_test {

// 4 tests at family-wise 1%.
const double Threshold = sidakSignificance(0.01, 4);

ChiSquareOptions kitOptions() {
  ChiSquareOptions o;
  o.grid = {64, 128};
  o.sampleCount = 500'000;
  o.seed = 13;
  o.threshold = Threshold;
  return o;
}

template <typename SampleFn> auto drawWith(const SampleFn& sample) {
  return [&sample](CounterRng& rng) -> std::optional<DirectionSample> {
    const std::optional<LightSample> s = sample(rng.uniform2D());
    if (!s) return std::nullopt;
    return DirectionSample{s->direction, s->pdf};
  };
}

// The sphere's cone seen from p: the pdf of a direction that hits the sphere.
double coneDensity(const SphereLight& light, const Vec3d& p, const Vec3d& w) {
  return light.sphere.intersect(Ray{p, w}, 0.0, Infinity) < Infinity ? light.pdf(p) : 0.0;
}

TEST(SphereLightChiSquare, SamplerDrawsItsPdf) {
  const SphereLight light{Sphere{Vec3d(1.0, 2.0, 0.5), 0.9}, Rgb(1.0)};
  const Vec3d p(0.2, -0.3, 0.1);
  const auto sample = [&](const Vec2d& u) { return light.sample(p, u); };
  const auto r = sphericalChiSquareTest(
      drawWith(sample), [&](const Vec3d& w) { return coneDensity(light, p, w); }, kitOptions());
  EXPECT_TRUE(r.passed) << "chi2 " << r.statistic << " dof " << r.dof << " p " << r.pValue << " "
                        << r.failure;
}

TEST(SphereLightChiSquare, RejectsTheConeOfAnotherSphere) {
  const SphereLight light{Sphere{Vec3d(1.0, 2.0, 0.5), 0.9}, Rgb(1.0)};
  const SphereLight smaller{Sphere{Vec3d(1.0, 2.0, 0.5), 0.8}, Rgb(1.0)};
  const Vec3d p(0.2, -0.3, 0.1);
  const auto sample = [&](const Vec2d& u) { return light.sample(p, u); };
  const auto r = sphericalChiSquareTest(
      drawWith(sample), [&](const Vec3d& w) { return coneDensity(smaller, p, w); }, kitOptions());
  EXPECT_FALSE(r.passed);
}

TEST(SphereLight, SamplesLieOnTheVisibleSurface) {
  const SphereLight light{Sphere{Vec3d(0, 5, 0), 0.01}, Rgb(2.0)};  // a small cone: the sin^2 branch
  const Vec3d p(0.0);
  CounterRng rng(3, 0);
  for (int i = 0; i < 1000; ++i) {
    const auto s = light.sample(p, rng.uniform2D());
    ASSERT_TRUE(s);
    const Vec3d q = p + s->direction * s->distance;
    EXPECT_NEAR(glm::length(q - light.sphere.center), light.sphere.radius, 1e-12);
    EXPECT_LE(glm::dot(q - light.sphere.center, s->direction), 1e-12);  // facing p
    EXPECT_DOUBLE_EQ(s->pdf, light.pdf(p));
  }
  EXPECT_FALSE(light.sample(light.sphere.center, {0.5, 0.5}));  // inside: nothing
  EXPECT_EQ(light.pdf(light.sphere.center), 0.0);
}

TEST(SunChiSquare, SamplerDrawsItsPdf) {
  const SunLight sun(Vec3d(0.3, -0.5, 1.0), Rgb(1.0), 12.0);
  const auto sample = [&](const Vec2d& u) { return sun.sample(u); };
  const auto r = sphericalChiSquareTest(
      drawWith(sample), [&](const Vec3d& w) { return sun.pdf(w); }, kitOptions());
  EXPECT_TRUE(r.passed) << "chi2 " << r.statistic << " dof " << r.dof << " p " << r.pValue << " "
                        << r.failure;
}

TEST(SunChiSquare, RejectsAWiderCone) {
  const SunLight sun(Vec3d(0.3, -0.5, 1.0), Rgb(1.0), 12.0), wider(Vec3d(0.3, -0.5, 1.0), Rgb(1.0), 13.0);
  const auto sample = [&](const Vec2d& u) { return sun.sample(u); };
  const auto r = sphericalChiSquareTest(
      drawWith(sample), [&](const Vec3d& w) { return wider.pdf(w); }, kitOptions());
  EXPECT_FALSE(r.passed);
}

// E = integral over the disk of L cos theta: by quadrature in the sun's own frame.
TEST(Sun, RadianceIntegratesToItsIrradiance) {
  for (const double degrees : {0.27, 5.0, 30.0}) {
    const Vec3d axis = glm::normalize(Vec3d(0.2, 0.1, 1.0));
    const SunLight sun(axis, Rgb(2.0, 1.0, 0.5), degrees);
    const double cosMax = std::cos(radians(degrees));
    const Framed frame = Framed::fromNormal(axis);
    QuadratureOptions q;
    q.relativeTolerance = 1e-10;
    const double e = adaptiveSimpson2D(
        [&](double cosTheta, double phi) {
          const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
          const Vec3d w = frame.toWorld(Vec3d(sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta));
          return sun.eval(w * (1.0 - 1e-15)).x * cosTheta;  // strictly inside the rim
        },
        cosMax, 1.0, 0.0, 2.0 * Pi, q);
    EXPECT_NEAR(e, 2.0, 2.0 * 1e-8) << degrees << " degrees";
  }
}

TEST(Sun, DeltaSunGivesItsIrradianceAlongItsDirection) {
  const SunLight sun(Vec3d(0, 0, 2), Rgb(3.0), 0.0);
  ASSERT_TRUE(sun.isDelta());
  const auto s = sun.sample({0.1, 0.9});
  ASSERT_TRUE(s);
  EXPECT_TRUE(s->isDelta);
  EXPECT_EQ(s->direction, Vec3d(0, 0, 1));
  EXPECT_EQ(s->radiance, Rgb(3.0));
  EXPECT_EQ(sun.eval(Vec3d(0, 0, 1)), Rgb(0.0));  // no solid angle: never hit
  EXPECT_THROW(SunLight(Vec3d(0.0), Rgb(1.0)), std::invalid_argument);
  EXPECT_THROW(SunLight(Vec3d(0, 0, 1), Rgb(-1.0)), std::invalid_argument);
  EXPECT_THROW(SunLight(Vec3d(0, 0, 1), Rgb(1.0), 90.0), std::invalid_argument);
}

}  // namespace lights_test
}  // namespace scatterlab
