// The caustic a glass sphere (smooth, eta 1.5) focuses on the ground of the caustic scene
// (docs/validation.md section 7): light tracing, BDPT and SPPM against the path tracer's
// high-sample reference, and what each costs for a given noise.
//
// The camera of the caustic scene is narrowed onto the caustic (causticCloseUp: 12 degrees
// around the point C where the light's line through the sphere's centre meets the ground,
// 16 x 12 pixels), so that every sample lands there. The region compared is the ground within 0.35 of C,
// inside the sphere's shadow: no direct light reaches it, only light through the glass.
//
// Light tracing and BDPT are unbiased: their region means agree with the reference within the
// sum of their variances (z test, Sidak over the two). SPPM is consistent, not unbiased: its
// photon density estimate at a visible point is the irradiance averaged over the disk of its
// gather radius r, so its expectation is the reference blurred by that disk, and the bias of
// a region mean is the blur's (Hachisuka & Jensen 2009, sec. 4; Knaus & Zwicker 2011: the
// bias falls with r^2). The radius only shrinks from r0, so the bias is at most the blur at
// r0, which the test measures with the path tracer itself: the radiance at a point jittered
// uniformly over the disk of radius r0 around the visible point (an unbiased estimate of the
// blurred image). SPPM passes when
//     |SPPM - reference| <= |blurred - reference| + t sqrt(var SPPM + var reference + var blurred),
// with var SPPM from 8 independent runs and t the Student-t quantile for 7 degrees of freedom
// at a two-sided 0.001 (5.41).
//
// Equal time: each estimator's efficiency is 1 / (relative variance of the region mean x
// seconds); SPPM's uses its mean squared error against the reference (bias included). The
// printed ratios to the path tracer's are the variance ratios at equal time quoted in the
// README.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>

#include <unsupported/Eigen/SpecialFunctions>

#include "integrator/path_tracer.h"
#include "integrator/sppm.h"
#include "materials/core/warp.h"
#include "render_test_support.h"
#include "validation/chi_square.h"

namespace scatterlab {
namespace caustic_test {

using nlohmann::json;
using namespace render_test;

constexpr int Width = 16, Height = 12;
constexpr double RegionRadius = 0.35;
const double GroundZ = -MaterialSphereSetup::SphereRadius;

Scene causticScene() {
  Scene scene = makePresetScene(ScenePreset::Caustic, makeBsdf({{"type", "dielectric"}, {"eta", 1.5}}),
                                presetLighting(ScenePreset::Caustic, std::nullopt), Width, Height);
  scene.setCamera(causticCloseUp(Width, Height));
  return scene;
}

// Pixels whose centre ray meets the ground within RegionRadius of the caustic's centre.
std::vector<bool> causticRegion(const Scene& scene) {
  std::vector<bool> out(size_t(Width) * Height, false);
  for (int y = 0; y < Height; ++y)
    for (int x = 0; x < Width; ++x) {
      const std::optional<SurfaceInteraction> hit =
          scene.intersect(scene.camera().generateRay(Vec2d(x + 0.5, y + 0.5)));
      out[size_t(y) * Width + x] = hit && std::abs(hit->point.z - GroundZ) < 1e-9 &&
                                   glm::length(hit->point - causticCentre()) < RegionRadius;
    }
  return out;
}

// The region's mean and the variance of that mean.
struct RegionMean {
  double mean = 0.0, variance = 0.0;
  double seconds = 0.0;
  double relativeVariance() const { return variance / (mean * mean); }
};

RegionMean regionMean(const RenderResult& r, const std::vector<bool>& region) {
  RegionMean out;
  int n = 0;
  for (int y = 0; y < Height; ++y)
    for (int x = 0; x < Width; ++x)
      if (region[size_t(y) * Width + x]) {
        out.mean += luminance(r.color.rgb(x, y));
        if (!r.variance.empty()) out.variance += luminance(r.variance.rgb(x, y));
        ++n;
      }
  out.mean /= n;
  out.variance /= double(n) * n;  // luminance of a variance: the channels are one colour here (grey)
  out.seconds = r.statistics.seconds;
  return out;
}

RenderResult renderWith(const Scene& scene, IntegratorKind kind, int spp, uint64_t seed,
                        bool variance = true) {
  RenderSettings settings = settingsWith(spp, seed, variance);
  settings.integratorKind = kind;
  settings.sppm.initialRadiusPixels = 1.0;
  return render(scene, settings);
}

// The reference blurred by SPPM's initial gather disk: per sample, the camera ray's ground point
// moved uniformly within the disk of radius r0 on the ground, and the path tracer's radiance
// leaving the moved point toward the eye (the ground is Lambertian: toward any direction).
RegionMean blurredReference(const Scene& scene, const std::vector<bool>& region, double r0, int spp) {
  IntegratorSettings settings;
  RegionMean out;
  int n = 0;
  for (int y = 0; y < Height; ++y)
    for (int x = 0; x < Width; ++x) {
      if (!region[size_t(y) * Width + x]) continue;
      double sum = 0, sumSquares = 0;
      for (int s = 0; s < spp; ++s) {
        SampleStream random(77, uint64_t(y) * Width + x, uint64_t(s));
        const Ray camera = scene.camera().generateRay(Vec2d(x, y) + random.next2D());
        const std::optional<SurfaceInteraction> hit = scene.intersect(camera);
        double value = 0;
        if (hit && std::abs(hit->point.z - GroundZ) < 1e-9) {
          const Vec2d d = r0 * sampleConcentricDisk(random.next2D());
          const Vec3d moved = hit->point + Vec3d(d.x, d.y, 0.0);
          const Ray onto{moved + Vec3d(0, 0, 1e-6), Vec3d(0, 0, -1)};
          value = luminance(tracePath(scene, onto, random, settings).radiance);
        }
        sum += value;
        sumSquares += value * value;
      }
      const double mean = sum / spp;
      out.mean += mean;
      out.variance += (sumSquares / spp - mean * mean) / (spp - 1);
      ++n;
    }
  out.mean /= n;
  out.variance /= double(n) * n;
  return out;
}

// The Student-t quantile: t with P(|T| > t) = alpha for nu degrees of freedom, by bisection on
// its distribution function, 1 - I_{nu / (nu + t^2)}(nu / 2, 1 / 2) / 2 (Abramowitz & Stegun
// 26.7.1 with 26.5.27).
double studentT(double alpha, double nu) {
  double lo = 0, hi = 100;
  for (int i = 0; i < 200; ++i) {
    const double t = 0.5 * (lo + hi);
    const double tail = Eigen::numext::betainc(nu / 2, 0.5, nu / (nu + t * t));  // P(|T| > t)
    (tail > alpha ? lo : hi) = t;
  }
  return 0.5 * (lo + hi);
}

struct CausticCase {
  std::string name;
};
void PrintTo(const CausticCase& c, std::ostream* out) { *out << c.name; }

class Caustic : public ::testing::TestWithParam<CausticCase> {};

TEST_P(Caustic, EstimatorsAgreeWithThePathTracersReference) {
  const Scene scene = causticScene();
  const std::vector<bool> region = causticRegion(scene);
  const int pixels = int(std::count(region.begin(), region.end(), true));
  // The disk of radius 0.35 seen at 27 degrees elevation through 12 degrees of view covers about
  // 9 x 4 pixels of the 16 x 12; fewer would mean the camera or the light moved off the caustic.
  ASSERT_GE(pixels, 24);

  const RegionMean reference = regionMean(renderWith(scene, IntegratorKind::Path, 8192, 1), region);
  const RegionMean path = regionMean(renderWith(scene, IntegratorKind::Path, 256, 2), region);
  const RegionMean light = regionMean(renderWith(scene, IntegratorKind::Light, 256, 3), region);
  const RegionMean bdpt = regionMean(renderWith(scene, IntegratorKind::Bdpt, 64, 4), region);
  std::printf("caustic region (%d pixels): reference %.5f +- %.5f\n", pixels, reference.mean,
              std::sqrt(reference.variance));

  for (const auto& [name, r] : {std::pair{"light", light}, std::pair{"bdpt", bdpt}}) {
    const double z = zScore(r.mean, r.variance, reference.mean, reference.variance);
    std::printf("  %-5s %.5f +- %.5f  z %+.2f\n", name, r.mean, std::sqrt(r.variance), z);
    EXPECT_GE(Eigen::numext::igammac(0.5, 0.5 * z * z), sidakSignificance(0.001, 2)) << name;
  }

  // SPPM: 8 runs of 64 iterations, r0 one pixel footprint at the scene's centre.
  constexpr int Runs = 8;
  double sum = 0, sumSquares = 0, seconds = 0, squaredError = 0;
  for (int run = 0; run < Runs; ++run) {
    const RegionMean s = regionMean(renderWith(scene, IntegratorKind::Sppm, 64, 100 + run, false), region);
    sum += s.mean;
    sumSquares += s.mean * s.mean;
    seconds += s.seconds;
    squaredError += sqr(s.mean - reference.mean);
  }
  const double sppmMean = sum / Runs, sppmVariance = (sumSquares / Runs - sppmMean * sppmMean) / (Runs - 1);
  SppmSettings sppmSettings;
  sppmSettings.initialRadiusPixels = 1.0;
  const double r0 = sppmInitialRadius(causticScene(), sppmSettings);
  const RegionMean blurred = blurredReference(scene, region, r0, 2048);
  const double bias = std::abs(blurred.mean - reference.mean);
  const double tolerance = bias + studentT(0.001, Runs - 1) *
                                      std::sqrt(sppmVariance / Runs + reference.variance + blurred.variance);
  std::printf(
      "  sppm  %.5f +- %.5f (%d runs); r0 %.4f: blurred reference %.5f, bound on the bias %.5f, tolerance "
      "%.5f\n",
      sppmMean, std::sqrt(sppmVariance / Runs), Runs, r0, blurred.mean, bias, tolerance);
  EXPECT_LE(std::abs(sppmMean - reference.mean), tolerance);

  // Equal time: 1 / (relative variance x seconds), and the ratio to the path tracer's.
  const auto efficiency = [&](double relativeError2, double time) { return 1.0 / (relativeError2 * time); };
  const double pathEfficiency = efficiency(path.relativeVariance(), path.seconds);
  std::printf(
      "  variance at equal time, path / estimator: light %.1f, bdpt %.1f, sppm (mean squared error) %.1f\n",
      efficiency(light.relativeVariance(), light.seconds) / pathEfficiency,
      efficiency(bdpt.relativeVariance(), bdpt.seconds) / pathEfficiency,
      efficiency(squaredError / Runs / sqr(reference.mean), seconds / Runs) / pathEfficiency);
}

std::string caseName(const ::testing::TestParamInfo<CausticCase>& info) { return info.param.name; }
INSTANTIATE_TEST_SUITE_P(Grid, Caustic, ::testing::Values(CausticCase{"glass_sphere"}), caseName);

}  // namespace caustic_test
}  // namespace scatterlab
