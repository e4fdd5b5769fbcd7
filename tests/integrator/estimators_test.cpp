// What light tracing, BDPT and SPPM share with the path tracer (integrator/render.h): the same
// bits for a seed whatever the thread count, the same refusals, and the pieces they are built
// from: the camera seen from the other side, the pixel filter as a density, light emission
// (emission.h) with lights at infinity over an infinite ground.
#include <gtest/gtest.h>

#include <iostream>

#include <unsupported/Eigen/SpecialFunctions>

#include "integrator/emission.h"
#include "materials/bsdf/lambertian.h"
#include "materials/bssrdf/subsurface_registry.h"
#include "render_test_support.h"
#include "validation/chi_square.h"

namespace scatterlab {
namespace estimators_test {

using nlohmann::json;
using namespace render_test;

const IntegratorKind NewEstimators[] = {IntegratorKind::Light, IntegratorKind::Bdpt, IntegratorKind::Sppm};

RenderResult renderPreview(IntegratorKind kind, int threads, uint64_t seed) {
  // Glass on the checkered ground under a map and the light, a Gaussian filter (splats spread
  // over several pixels).
  const Scene scene =
      makePresetScene(ScenePreset::Preview, makeBsdf({{"type", "rough-dielectric"}, {"alpha", 0.2}}),
                      Environment::fromMap(smoothSkyMap(16)), 24, 18);
  RenderSettings settings = settingsWith(8, seed, kind != IntegratorKind::Sppm);
  settings.integratorKind = kind;
  settings.threads = threads;
  settings.filter = PixelFilter::gaussian();
  settings.albedoLayer = settings.normalLayer = true;
  return render(scene, settings);
}

TEST(Estimators, OneAndTwoThreadsGiveTheSameBits) {
  for (const IntegratorKind kind : NewEstimators) {
    const RenderResult one = renderPreview(kind, 1, 5), two = renderPreview(kind, 2, 5);
    EXPECT_EQ(one.color.data(), two.color.data()) << toString(kind);
    EXPECT_EQ(one.variance.data(), two.variance.data()) << toString(kind);
    EXPECT_EQ(one.albedo.data(), two.albedo.data()) << toString(kind);
    EXPECT_EQ(one.normal.data(), two.normal.data()) << toString(kind);
    EXPECT_EQ(one.statistics.vertices, two.statistics.vertices) << toString(kind);
    EXPECT_EQ(one.statistics.droppedSamples(), 0u) << toString(kind);
    EXPECT_NE(one.color.data(), renderPreview(kind, 2, 6).color.data()) << toString(kind);
  }
}

TEST(Estimators, NamesRoundTrip) {
  for (const std::string& name : integratorNames()) EXPECT_EQ(toString(*findIntegrator(name)), name);
  EXPECT_FALSE(findIntegrator("photon"));
}

// Subsurface materials are BSSRDFs, which only the path tracer renders; the others refuse them
// (and SPPM has no variance layer) with a message naming what is allowed.
TEST(Estimators, RefuseWhatTheyCannotRender) {
  const Scene skin = makePresetScene(ScenePreset::MaterialSphere, makeSubsurface({{"type", "subsurface"}}),
                                     SubsurfaceMode::Diffusion, Environment(), 4, 4);
  for (const IntegratorKind kind : NewEstimators) {
    RenderSettings settings = settingsWith(1, 1, false);
    settings.integratorKind = kind;
    try {
      render(skin, settings);
      ADD_FAILURE() << toString(kind) << " rendered a subsurface material";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("subsurface"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("\"path\""), std::string::npos) << e.what();
    }
  }
  RenderSettings sppm = settingsWith(1, 1, true);
  sppm.integratorKind = IntegratorKind::Sppm;
  const Scene glass =
      makePresetScene(ScenePreset::Preview, makeBsdf({{"type", "dielectric"}}), Environment(), 4, 4);
  EXPECT_THROW(render(glass, sppm), std::invalid_argument);
}

// The camera seen from the other side: filmPoint inverts generateRay, and a pixel's importance
// integrates to 1 over the directions through it (midpoint rule on 64 x 64 points of the pixel,
// mapped to solid angle by d omega = cos^3 theta dA a; its error is far below 1e-6 for a pixel
// of 0.0015 rad).
TEST(Estimators, CameraImportanceIntegratesToOneOverAPixel) {
  const PinholeCamera camera =
      PinholeCamera::lookAt(Vec3d(0.3, -4, 1), Vec3d(0, 0, 0), Vec3d(0, 0, 1), 50.0, 40, 30);
  for (const Vec2d film : {Vec2d(0.5, 0.5), Vec2d(17.25, 9.75), Vec2d(39.9, 29.1)}) {
    const std::optional<FilmPoint> back = camera.filmPoint(camera.generateRay(film).direction);
    ASSERT_TRUE(back);
    EXPECT_NEAR(back->position.x, film.x, 1e-9);
    EXPECT_NEAR(back->position.y, film.y, 1e-9);
  }
  EXPECT_FALSE(camera.filmPoint(-camera.forward()));
  EXPECT_FALSE(camera.filmPoint(camera.generateRay(Vec2d(-0.5, 3)).direction));
  EXPECT_TRUE(camera.filmPoint(camera.generateRay(Vec2d(-0.5, 3)).direction, 1.0));
  for (const Vec2d pixel : {Vec2d(0, 0), Vec2d(20, 15), Vec2d(39, 7)}) {
    constexpr int N = 64;
    double sum = 0;
    for (int j = 0; j < N; ++j)
      for (int i = 0; i < N; ++i) {
        const Vec3d w = camera.generateRay(pixel + Vec2d((i + 0.5) / N, (j + 0.5) / N)).direction;
        const double cosTheta = glm::dot(w, camera.forward());
        const double dOmega = std::pow(cosTheta, 3) * sqr(camera.pixelAngle()) / (N * N);
        sum += camera.pixelImportance(cosTheta) * dOmega;
      }
    EXPECT_NEAR(sum, 1.0, 1e-9);
    EXPECT_NEAR(camera.directionPdf(1.0) * 40 * 30, camera.pixelImportance(1.0), 1e-9);
  }
}

// The pixel filter's density integrates to 1 (midpoint rule, 400 x 400 points over its
// support: the Gaussian's error is below 1e-5) and matches sampleOffset's histogram.
TEST(Estimators, PixelFilterDensityIsNormalised) {
  for (const PixelFilter& filter :
       {PixelFilter::box(), PixelFilter::gaussian(), PixelFilter::gaussian(0.7, 2.0)}) {
    constexpr int N = 400;
    const double r = filter.radius(), step = 2 * r / N;
    double sum = 0;
    for (int j = 0; j < N; ++j)
      for (int i = 0; i < N; ++i) sum += filter.density(Vec2d(-r + (i + 0.5) * step, -r + (j + 0.5) * step));
    EXPECT_NEAR(sum * step * step, 1.0, 1e-5) << filter.radius();
    EXPECT_EQ(filter.density(Vec2d(r * 1.01, 0)), 0.0);
  }
}

// Light from infinity reaches every point of an infinite ground: the density of a ray's point on
// the plane perpendicular to it is R / (2 pi (R^2 + rho^2)^(3/2)) (emission.h), whose
// distribution function is 1 - R / sqrt(R^2 + rho^2). The chi-square of 40 equal-probability
// bins of that function over 40,000 rays (Sidak over this file's 2 such tests), and the
// density the emitter reports is the formula's.
TEST(Estimators, LightFromInfinityCoversThePlane) {
  Scene scene;
  scene.addSphere(Sphere{Vec3d(1, 2, 0), 1.5}, scene.addMaterial(std::make_unique<LambertianBsdf>(Rgb(0.5))));
  scene.addPlane(Plane{Vec3d(0, 0, -1.5), Vec3d(0, 0, 1), Vec3d(1, 0, 0)},
                 scene.addMaterial(std::make_unique<LambertianBsdf>(Rgb(0.5))));
  scene.setEnvironment(Environment::constant(Rgb(1.0)));
  const LightEmission emission(scene);
  const Sphere bounds = scene.finiteBounds();
  constexpr int Bins = 40, Rays = 40000;
  std::vector<double> counts(Bins, 0.0);
  for (int i = 0; i < Rays; ++i) {
    SampleStream random(3, uint64_t(i), 0);
    const std::optional<EmittedRay> ray = emission.sample(random);
    ASSERT_TRUE(ray);
    ASSERT_TRUE(ray->atInfinity);
    // The line's distance from the bounds' centre.
    const Vec3d offset = bounds.center - ray->ray.origin;
    const Vec3d along = ray->ray.direction * glm::dot(offset, ray->ray.direction);
    const double rho = glm::length(offset - along);
    // The density at the line's point nearest the centre (BDPT asks it at scene points); the
    // origin lies far back along the line (past the ground, for a grazing ray), so that point
    // carries a round-off of ~1e-16 times the distance back, far below this tolerance.
    const Vec3d nearest = ray->ray.origin + along;
    EXPECT_NEAR(ray->pdfNext, emission.perpendicularPdf(nearest, ray->ray.direction), 1e-6 * ray->pdfNext);
    const double cdf = 1.0 - bounds.radius / std::sqrt(sqr(bounds.radius) + rho * rho);
    counts[std::min(int(cdf * Bins), Bins - 1)] += 1.0;
    // The ray starts before everything on its line: nothing lies behind its origin.
    EXPECT_FALSE(scene.intersect(Ray{ray->ray.origin, -ray->ray.direction}));
  }
  double chi2 = 0;
  for (const double c : counts) chi2 += sqr(c - double(Rays) / Bins) / (double(Rays) / Bins);
  const double p = Eigen::numext::igammac(0.5 * (Bins - 1), 0.5 * chi2);
  EXPECT_GE(p, sidakSignificance(0.01, 2)) << "chi2 " << chi2;
}

// Emission's weights carry the light's power: under a constant environment of radiance L the
// irradiance on an upward disk on the ground is pi L. A ray's weight is L / (pdf(direction)
// pdf(point on the perpendicular plane)), and the disk covers A |cos| of that plane, so the
// weights of the rays that cross it, summed over the disk's area A and the number of rays,
// estimate the flux per unit area, the irradiance (4 standard errors of that mean). A sphere light's weight
// is its power pi L 4 pi r^2 over its selection probability.
TEST(Estimators, EmissionCarriesTheLightsPower) {
  Scene scene;
  scene.addPlane(Plane{Vec3d(0, 0, 0), Vec3d(0, 0, 1), Vec3d(1, 0, 0)},
                 scene.addMaterial(std::make_unique<LambertianBsdf>(Rgb(0.5))));
  scene.setEnvironment(Environment::constant(Rgb(2.0)));
  const LightEmission emission(scene);
  const Vec3d disk(1.5, 0.5, 1e-6);
  constexpr double DiskRadius = 0.5;
  constexpr int Rays = 400000;
  double sum = 0, sumSquares = 0;
  for (int i = 0; i < Rays; ++i) {
    SampleStream random(9, uint64_t(i), 0);
    const std::optional<EmittedRay> ray = emission.sample(random);
    if (!ray || !(ray->ray.direction.z < 0)) continue;
    const double t = (disk.z - ray->ray.origin.z) / ray->ray.direction.z;
    const Vec3d hit = ray->ray.at(t);
    if (glm::length(hit - disk) > DiskRadius) continue;
    const double value = ray->weight.x / (Pi * DiskRadius * DiskRadius);
    sum += value;
    sumSquares += value * value;
  }
  const double mean = sum / Rays, error = std::sqrt((sumSquares / Rays - mean * mean) / Rays);
  EXPECT_NEAR(mean, Pi * 2.0, 4 * error) << "+- " << error;

  Scene lit;
  lit.addSphereLight(Sphere{Vec3d(0, 0, 2), 0.4}, Rgb(3.0));
  const LightEmission sphere(lit);
  SampleStream random(1, 0, 0);
  const std::optional<EmittedRay> ray = sphere.sample(random);
  ASSERT_TRUE(ray);
  EXPECT_NEAR(ray->weight.x, Pi * 3.0 * 4 * Pi * 0.16, 1e-9);
}

}  // namespace estimators_test
}  // namespace scatterlab
