// The fitted model written as one registry material: built by the registry, it evaluates to
// the fitted model everywhere (the blend chain is exact), or the writer says why not.
#include <gtest/gtest.h>

#include "fitting/material_writer.h"
#include "fitting_test_support.h"
#include "materials/core/warp.h"

namespace scatterlab::fitting::test {
namespace material_writer_test {

// Parameters inside their bounds; scales of `scale` per part (times a per-channel factor).
std::vector<double> pointOf(const FitModel& model, double scale) {
  std::vector<double> x = model.startValues();
  for (size_t j = 0; j < x.size(); ++j) {
    const FitParameter& p = model.parameters()[j];
    if (p.role == ParameterRole::Scale)
      x[j] = scale * (1.0 - 0.2 * std::max(p.channel, 0));
    else if (p.channel >= 0 && p.key != "albedo" && p.key != "rs" && p.key != "baseColor")
      x[j] = std::min(p.upper, x[j] * (1.0 + 0.3 * p.channel));  // per-channel shapes that differ
  }
  return x;
}

void expectWrittenMaterialMatches(const std::string& spec, bool perChannel, double scale, int lobes = 1) {
  const FitModel model(parseModelSpec(spec, lobes), perChannel);
  const std::vector<double> x = pointOf(model, scale);
  const WrittenMaterial written = writeMaterial(model.fittedParts(x.data()));
  ASSERT_TRUE(written.material) << spec << ": " << written.problem;
  const auto bsdf = makeBsdf(*written.material);
  CounterRng rng(5, 0);
  for (int i = 0; i < 200; ++i) {
    const Vec3d wi = sampleUniformHemisphere(rng.uniform2D()), wo = sampleUniformHemisphere(rng.uniform2D());
    double expected[3];
    model.evaluate<false>(x.data(), wi, wo, expected, nullptr);
    const Rgb f = bsdf->eval(wi, wo);
    for (int c = 0; c < 3; ++c)
      ASSERT_NEAR(f[c], expected[c], 1e-12 * std::max(1.0, std::abs(expected[c])))
          << spec << (perChannel ? " per channel" : "") << " channel " << c << "\n"
          << written.material->dump();
  }
}

TEST(MaterialWriter, WrittenMaterialEvaluatesToTheFittedModel) {
  expectWrittenMaterialMatches("lambertian+ngan-cook-torrance", false, 0.3);
  expectWrittenMaterialMatches("lambertian+ngan-ward", true, 0.25);
  expectWrittenMaterialMatches("lambertian+ngan-ashikhmin-shirley", false, 0.2);
  expectWrittenMaterialMatches(std::string("lambertian+") + WhiteConductorSpec, false, 0.4);
  expectWrittenMaterialMatches(R"(lambertian+{"type":"conductor","distribution":"beckmann","metal":"Cu"})",
                               true, 0.3);
  expectWrittenMaterialMatches(std::string("lambertian+") + WhiteConductorSpec, false, 0.2, 3);
  expectWrittenMaterialMatches("blinn-phong", false, 0.4);
  expectWrittenMaterialMatches("blinn-phong", true, 0.2, 2);
  expectWrittenMaterialMatches("phong", false, 0.4);
  expectWrittenMaterialMatches("lafortune", false, 0.3);
  expectWrittenMaterialMatches("oren-nayar+ward", false, 0.4);
  expectWrittenMaterialMatches("ashikhmin-shirley", false, 0.5);
  expectWrittenMaterialMatches("eon", false, 0.5);
  expectWrittenMaterialMatches("disney", false, 0.5);
  expectWrittenMaterialMatches("conductor", false, 0.6);
}

TEST(MaterialWriter, OneScalablePartIsWrittenAsItIs) {
  const FitModel model(parseModelSpec("blinn-phong"), false);
  const std::vector<double> x = pointOf(model, 0.3);
  const WrittenMaterial written = writeMaterial(model.fittedParts(x.data()));
  ASSERT_TRUE(written.material);
  EXPECT_EQ((*written.material)["type"], "blinn-phong");
  EXPECT_EQ((*written.material)["ks"][0], 0.3);
}

TEST(MaterialWriter, ScalesAddingUpToMoreThanOneCannotBeWritten) {
  const FitModel model(parseModelSpec("lambertian+ngan-cook-torrance"), false);
  std::vector<double> x = pointOf(model, 0.6);  // 0.6 + 0.6 in the red channel
  const WrittenMaterial written = writeMaterial(model.fittedParts(x.data()));
  EXPECT_FALSE(written.material);
  EXPECT_NE(written.problem.find("channel r"), std::string::npos) << written.problem;
  EXPECT_NE(written.problem.find("1.2"), std::string::npos) << written.problem;
}

}  // namespace material_writer_test
}  // namespace scatterlab::fitting::test
