// One answer from three estimators (docs/validation.md section 7): BSDF sampling only, light
// sampling only and their combination by MIS are unbiased estimators of the same image, so
// their renders (independent seeds) differ only by noise.
//
// The statistic: the image is cut into 4 x 4 pixel blocks, and the blocks where every pixel
// sees a surface (the first-hit normal layer is nonzero there; the sky, seen directly, is
// weighted 1 by every estimator and would test nothing) are compared. A block's mean has variance
// sum(pixel variances) / 16^2 (pixels are independent: each has its own random numbers), so
// z_b = (A_b - B_b) / sqrt(var A_b + var B_b) is standard normal for unbiased A and B, and
// sum z_b^2 over the blocks is chi-square with one degree of freedom per block. Each colour
// channel is tested on its own (channels are correlated). The lights are broad and the
// environment smooth (render_test_support.h), so that every estimator's per-pixel variance
// is well estimated from 128 samples; the scene has a sphere light and a finite sun besides
// the environment, and a diffuse checkered ground, so NEE, MIS weights of every light kind
// and multiple bounces all take part.
//
// The test rejects when p < 0.01 / 18 (Sidak over 2 materials x 3 pairs x 3 channels), and
// a negative control shows that it has the power to: the MIS image of a scene whose lights
// are all 5% brighter (what a light pdf or MIS weight off by a few percent would do) fails.
#include <gtest/gtest.h>

#include <iostream>

#include "render_test_support.h"
#include "validation/chi_square.h"

namespace scatterlab {
namespace estimator_agreement_test {

using nlohmann::json;
using namespace render_test;

constexpr int Size = 64, Block = 4, Spp = 128;
const double Threshold = sidakSignificance(0.01, 18);

Scene testScene(const json& material, double lightScale) {
  Scene scene;
  scene.addSphere(Sphere{Vec3d(0.0), 1.0, Vec3d(0, 0, 1)}, scene.addMaterial(makeBsdf(material)));
  const int ground = scene.addCheckerMaterial(makeBsdf({{"type", "lambertian"}, {"albedo", 0.7}}),
                                              makeBsdf({{"type", "lambertian"}, {"albedo", 0.3}}), 0.5);
  scene.addPlane(Plane{Vec3d(0, 0, -1), Vec3d(0, 0, 1), Vec3d(1, 0, 0)}, ground);
  scene.setEnvironment(Environment::fromMap(smoothSkyMap(32), lightScale));
  // Subtends ~30 degrees from the sphere: broad enough for BSDF sampling alone to find it.
  scene.addSphereLight(Sphere{Vec3d(-2.0, -1.5, 1.5), 0.8}, Rgb(3.0, 2.5, 2.0) * lightScale);
  scene.addSun(SunLight(Vec3d(1, -0.5, 1.2), Rgb(1.0, 0.9, 0.8) * lightScale, 10.0));
  scene.setCamera(
      PinholeCamera::lookAt(Vec3d(0, -4.5, 1.2), Vec3d(0, 0, -0.2), Vec3d(0, 0, 1), 45.0, Size, Size));
  return scene;
}

RenderResult renderWith(const json& material, Estimator estimator, uint64_t seed, double lightScale = 1.0) {
  RenderSettings settings = settingsWith(Spp, seed);
  settings.integrator.estimator = estimator;
  settings.normalLayer = true;
  return render(testScene(material, lightScale), settings);
}

// Blocks where every pixel sees a surface (the first-hit normal layer is nonzero).
Agreement compareSurfaceBlocks(const RenderResult& a, const RenderResult& b, int channel) {
  return compareBlocks(a, b, channel, Block, [&](int x, int y) {
    return glm::length(a.normal.rgb(x, y)) > 0.9 && glm::length(b.normal.rgb(x, y)) > 0.9;
  });
}

struct MaterialCase {
  std::string name;
  json material;
};
void PrintTo(const MaterialCase& c, std::ostream* os) { *os << c.name; }

class EstimatorAgreement : public ::testing::TestWithParam<MaterialCase> {};

TEST_P(EstimatorAgreement, BsdfLightAndMisAgree) {
  const json& material = GetParam().material;
  const RenderResult mis = renderWith(material, Estimator::Mis, 101);
  const RenderResult bsdf = renderWith(material, Estimator::BsdfOnly, 202);
  const RenderResult light = renderWith(material, Estimator::LightOnly, 303);
  const std::pair<const char*, std::pair<const RenderResult*, const RenderResult*>> pairs[] = {
      {"mis-bsdf", {&mis, &bsdf}}, {"mis-light", {&mis, &light}}, {"bsdf-light", {&bsdf, &light}}};
  for (const auto& [name, images] : pairs)
    for (int channel = 0; channel < 3; ++channel) {
      const Agreement r = compareSurfaceBlocks(*images.first, *images.second, channel);
      EXPECT_GE(r.pValue, Threshold) << name << " channel " << channel << ": chi2 " << r.chi2 << " dof "
                                     << r.dof;
      std::cout << "[ agree    ] " << GetParam().name << " " << name << " channel " << channel << ": chi2 "
                << r.chi2 << " dof " << r.dof << " p " << r.pValue << "\n";
    }
}

// Negative control: the same comparison between MIS and BSDF sampling, with every light 5%
// brighter for MIS, must reject.
TEST_P(EstimatorAgreement, RejectsAFivePercentBias) {
  const json& material = GetParam().material;
  const RenderResult biased = renderWith(material, Estimator::Mis, 101, 1.05);
  const RenderResult bsdf = renderWith(material, Estimator::BsdfOnly, 202);
  for (int channel = 0; channel < 3; ++channel) {
    const Agreement r = compareSurfaceBlocks(biased, bsdf, channel);
    EXPECT_LT(r.pValue, Threshold) << "channel " << channel << ": chi2 " << r.chi2 << " dof " << r.dof;
    std::cout << "[ control  ] " << GetParam().name << " channel " << channel << ": chi2 " << r.chi2 << " p "
              << r.pValue << "\n";
  }
}

std::string caseName(const ::testing::TestParamInfo<MaterialCase>& info) { return info.param.name; }
INSTANTIATE_TEST_SUITE_P(Materials, EstimatorAgreement,
                         ::testing::Values(MaterialCase{
                             "rough_plastic",
                             {{"type", "rough-plastic"}, {"alpha", 0.25}, {"diffuse", {0.6, 0.3, 0.2}}}}),
                         caseName);
// Transmission through a rough sphere: long paths, slow under the sanitizers, which skip Grid/.
INSTANTIATE_TEST_SUITE_P(Grid, EstimatorAgreement,
                         ::testing::Values(MaterialCase{
                             "rough_glass", {{"type", "rough-dielectric"}, {"alpha", 0.3}, {"eta", 1.5}}}),
                         caseName);

}  // namespace estimator_agreement_test
}  // namespace scatterlab
