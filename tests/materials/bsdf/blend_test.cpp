// The blend of two materials (blend.h): the mixture's value and density against its
// components, the lobe choice and the remapped random number, delta lobes (a smooth dielectric
// and a smooth conductor blended with a Lambertian), the build-time rules, and the registry's
// nested materials (defaults, completion, errors that name the nested key).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "fixed_pairs.h"
#include "materials/bsdf/blend.h"
#include "materials/bsdf/conductor.h"
#include "materials/bsdf/lambertian.h"
#include "materials/bsdf/metals.h"
#include "materials/bsdf/smooth_conductor.h"
#include "materials/bsdf/smooth_dielectric.h"
#include "materials/core/rng.h"
#include "materials/registry/material_file.h"
#include "materials/registry/model_list.h"
#include "materials/registry/spec_validation.h"
#include "tests/test_names.h"

namespace scatterlab {
namespace blend_test {

using nlohmann::json;

std::unique_ptr<BsdfModel> gold(double alpha) {
  const MetalIor* au = findMetal("Au");
  return makeMicrofacetConductor(MicrofacetType::Ggx, alpha, alpha, au->eta, au->k);
}

TEST(Blend, ValueAndDensityAreTheComponentsMixed) {
  const Rgb w(0.3, 0.5, 0.9);
  const BlendBsdf blend(std::make_unique<LambertianBsdf>(Rgb(0.8, 0.6, 0.4)), gold(0.2), w);
  const LambertianBsdf a(Rgb(0.8, 0.6, 0.4));
  const auto b = gold(0.2);
  const double wbar = (0.3 + 0.5 + 0.9) / 3.0;
  EXPECT_DOUBLE_EQ(blend.firstProbability(), wbar);
  for (const DirectionPair& p : reflectionPairs()) {
    const Rgb fa = a.eval(p.wi, p.wo), fb = b->eval(p.wi, p.wo), f = blend.eval(p.wi, p.wo);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(f[c], w[c] * fa[c] + (1 - w[c]) * fb[c], 1e-14 * f[c]) << c;
    const double expected = wbar * a.pdf(p.wi, p.wo) + (1 - wbar) * b->pdf(p.wi, p.wo);
    EXPECT_NEAR(blend.pdf(p.wi, p.wo), expected, 1e-14 * expected);
  }
}

// Weight 1 (0) is the first (second) model exactly, and its samples are that model's.
TEST(Blend, WeightOneOrZeroIsOneComponent) {
  const BlendBsdf onlyFirst(std::make_unique<LambertianBsdf>(Rgb(0.5)), gold(0.3), Rgb(1.0));
  const BlendBsdf onlySecond(std::make_unique<LambertianBsdf>(Rgb(0.5)), gold(0.3), Rgb(0.0));
  const LambertianBsdf lambertian(Rgb(0.5));
  const auto conductor = gold(0.3);
  for (const DirectionPair& p : reflectionPairs()) {
    EXPECT_EQ(onlyFirst.eval(p.wi, p.wo), lambertian.eval(p.wi, p.wo));
    EXPECT_EQ(onlyFirst.pdf(p.wi, p.wo), lambertian.pdf(p.wi, p.wo));
    EXPECT_EQ(onlySecond.eval(p.wi, p.wo), conductor->eval(p.wi, p.wo));
    EXPECT_EQ(onlySecond.pdf(p.wi, p.wo), conductor->pdf(p.wi, p.wo));
  }
  const Vec3d wi = directionFromDegrees(40, 10);
  for (double uLobe : {0.0, 0.5, 0.999999}) {
    const auto s = onlySecond.sample(wi, uLobe, {0.3, 0.7});
    const auto t = conductor->sample(wi, uLobe, {0.3, 0.7});
    ASSERT_TRUE(s && t);
    EXPECT_EQ(s->wo, t->wo);
    EXPECT_NEAR(s->pdf, t->pdf, 1e-12 * t->pdf);
  }
}

// A component that records the lobe number it is given: the chosen model must get uLobe
// remapped onto [0, 1) (a fresh uniform number), not the raw one.
class LobeRecorder final : public BsdfModel {
 public:
  mutable double lastULobe = -1;
  Rgb eval(const Vec3d& wi, const Vec3d& wo, TransportMode) const override { return base_.eval(wi, wo); }
  double pdf(const Vec3d& wi, const Vec3d& wo, TransportMode) const override { return base_.pdf(wi, wo); }
  std::optional<BsdfSample> sample(const Vec3d& wi, double uLobe, const Vec2d& u,
                                   TransportMode) const override {
    lastULobe = uLobe;
    return base_.sample(wi, uLobe, u);
  }
  LobeFlags flags() const override { return base_.flags(); }

 private:
  LambertianBsdf base_{Rgb(0.5)};
};

TEST(Blend, ChosenModelGetsAFreshUniformNumber) {
  auto first = std::make_unique<LobeRecorder>();
  auto second = std::make_unique<LobeRecorder>();
  const LobeRecorder* a = first.get();
  const LobeRecorder* b = second.get();
  const BlendBsdf blend(std::move(first), std::move(second), Rgb(0.2, 0.3, 0.4));  // wbar = 0.3
  const Vec3d wi = directionFromDegrees(30, 0);
  ASSERT_TRUE(blend.sample(wi, 0.15, {0.4, 0.4}));
  EXPECT_NEAR(a->lastULobe, 0.5, 1e-15);
  ASSERT_TRUE(blend.sample(wi, 0.65, {0.4, 0.4}));
  EXPECT_NEAR(b->lastULobe, 0.5, 1e-15);
  ASSERT_TRUE(blend.sample(wi, std::nextafter(1.0, 0.0), {0.4, 0.4}));
  EXPECT_LT(b->lastULobe, 1.0);
}

// Non-delta samples carry the mixture's density and value (the other component evaluated at
// the sampled direction), and each component is chosen with probability wbar.
TEST(Blend, SamplesReportTheMixture) {
  const BlendBsdf blend(std::make_unique<LambertianBsdf>(Rgb(0.7)), gold(0.1), Rgb(0.25));
  const Vec3d wi = directionFromDegrees(50, 30);
  size_t glossy = 0, total = 0;
  for (uint64_t i = 0; i < 20000; ++i) {
    CounterRng rng(5, i);
    const double uLobe = rng.uniform();
    const auto s = blend.sample(wi, uLobe, rng.uniform2D());
    if (!s) continue;
    ++total;
    glossy += s->lobe == LobeFlags::GlossyReflection;
    const double density = blend.pdf(wi, s->wo);
    EXPECT_NEAR(s->pdf, density, 1e-12 * density);
    const Rgb expected = blend.eval(wi, s->wo) * s->wo.z / density;
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(s->weight[c], expected[c], 1e-12 * expected[c] + 1e-300);
  }
  // Conductor samples that fall below the horizon fail; the rest are ~75% of the draws.
  const double fraction = double(glossy) / double(total);
  EXPECT_NEAR(fraction, 0.75, 0.02);
}

// A delta sample of one component: probability wbar P_delta, weight (w / wbar) times the
// component's, and the other component's density does not add to it. The smooth dielectric
// reflects with probability F and refracts with 1 - F.
TEST(Blend, DeltaSamplesHaveTheMixturesDiscreteProbability) {
  const double eta = 1.5;
  const Rgb w(0.2, 0.4, 0.6);  // wbar = 0.4
  const BlendBsdf blend(std::make_unique<SmoothDielectricBsdf>(eta),
                        std::make_unique<LambertianBsdf>(Rgb(0.5)), w);
  const SmoothDielectricBsdf dielectric(eta);
  const Vec3d wi = directionFromDegrees(45, 0);
  for (double uInside : {0.01, 0.5, 0.99}) {
    const double uLobe = 0.4 * uInside;  // chooses the dielectric, which then sees uInside
    const auto s = blend.sample(wi, uLobe, {0.3, 0.6});
    const auto d = dielectric.sample(wi, uInside, {0.3, 0.6});
    ASSERT_TRUE(s && d);
    ASSERT_TRUE(s->isDelta());
    EXPECT_EQ(s->lobe, d->lobe);
    EXPECT_NEAR(glm::length(s->wo - d->wo), 0.0, 1e-15);
    EXPECT_NEAR(s->pdf, 0.4 * d->pdf, 1e-15);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(s->weight[c], w[c] / 0.4 * d->weight[c], 1e-14);
    EXPECT_EQ(s->eta, d->eta);
  }
  // eval and pdf at the delta directions are the Lambertian part only (delta lobes give 0).
  const Vec3d mirror(-wi.x, -wi.y, wi.z);
  const Rgb f = blend.eval(wi, mirror);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(f[c], (1 - w[c]) * 0.5 * InvPi, 1e-15);
  EXPECT_NEAR(blend.pdf(wi, mirror), 0.6 * mirror.z * InvPi, 1e-15);
}

TEST(Blend, SmoothConductorDeltaWeightIsScaledByTheChannelWeight) {
  const MetalIor* au = findMetal("Au");
  const Rgb w(1.0, 0.5, 0.0);  // wbar = 0.5
  const BlendBsdf blend(std::make_unique<SmoothConductorBsdf>(au->eta, au->k),
                        std::make_unique<LambertianBsdf>(Rgb(0.9)), w);
  const Vec3d wi = directionFromDegrees(20, 60);
  const auto s = blend.sample(wi, 0.2, {0.5, 0.5});
  const auto d = SmoothConductorBsdf(au->eta, au->k).sample(wi, 0.4, {0.5, 0.5});
  ASSERT_TRUE(s && d && s->isDelta());
  EXPECT_NEAR(s->pdf, 0.5 * d->pdf, 1e-15);
  EXPECT_NEAR(s->weight.x, 2.0 * d->weight.x, 1e-14);
  EXPECT_NEAR(s->weight.y, d->weight.y, 1e-14);
  EXPECT_EQ(s->weight.z, 0.0);
}

TEST(Blend, FlagsLosslessReciprocalAndInteriorIndex) {
  const BlendBsdf glass(std::make_unique<LambertianBsdf>(Rgb(1.0)),
                        std::make_unique<SmoothDielectricBsdf>(1.33), Rgb(0.5));
  EXPECT_TRUE(glass.isReciprocal());
  EXPECT_EQ(glass.interiorIndex(), 1.33);
  EXPECT_EQ(glass.flags(), LobeFlags::DiffuseReflection | SmoothDielectricBsdf(1.33).flags());
  // Both components are lossless, but the one-sided Lambertian reflects nothing from below:
  // half of the light arriving there is lost.
  EXPECT_FALSE(glass.isLossless());
  const Vec3d below = directionFromDegrees(150, 0);
  size_t failed = 0;
  for (int i = 0; i < 1000; ++i) failed += !glass.sample(below, (i + 0.5) / 1000, {0.3, 0.3}).has_value();
  EXPECT_EQ(failed, 500u);
  const BlendBsdf white(std::make_unique<LambertianBsdf>(Rgb(1.0)),
                        std::make_unique<LambertianBsdf>(Rgb(1.0)), Rgb(0.2, 0.5, 0.7));
  EXPECT_TRUE(white.isLossless());
  const BlendBsdf lossy(std::make_unique<LambertianBsdf>(Rgb(1.0)), gold(0.3), Rgb(0.5));
  EXPECT_FALSE(lossy.isLossless());
  EXPECT_EQ(lossy.interiorIndex(), 1.0);
  EXPECT_EQ(lossy.flags(), LobeFlags::DiffuseReflection | LobeFlags::GlossyReflection);
}

TEST(Blend, RejectsTwoDeltaModelsDifferentMediaAndBadWeights) {
  const MetalIor* au = findMetal("Au");
  EXPECT_THROW(BlendBsdf(std::make_unique<SmoothDielectricBsdf>(1.5),
                         std::make_unique<SmoothConductorBsdf>(au->eta, au->k), Rgb(0.5)),
               std::invalid_argument);
  EXPECT_THROW(
      makeBsdf({{"type", "blend"},
                {"materials",
                 {{{"type", "dielectric"}, {"eta", 1.5}}, {{"type", "rough-dielectric"}, {"eta", 1.33}}}}}),
      MaterialError);
  EXPECT_NO_THROW(
      makeBsdf({{"type", "blend"},
                {"materials",
                 {{{"type", "dielectric"}, {"eta", 1.5}}, {{"type", "rough-dielectric"}, {"eta", 1.5}}}}}));
  EXPECT_THROW(BlendBsdf(std::make_unique<LambertianBsdf>(Rgb(0.5)), gold(0.1), Rgb(0.5, 1.2, 0.5)),
               std::invalid_argument);
  EXPECT_THROW(BlendBsdf(nullptr, gold(0.1), Rgb(0.5)), std::invalid_argument);
}

// ---- Registry: nested materials -------------------------------------------------------------

std::string materialErrorOf(const json& material) {
  try {
    makeBsdf(material);
  } catch (const MaterialError& error) {
    return error.what();
  }
  return "";
}

TEST(BlendRegistry, DefaultsBuildAndCompleteTheNestedMaterials) {
  const auto model = makeBsdf({{"type", "blend"}});
  const auto* blend = dynamic_cast<const BlendBsdf*>(model.get());
  ASSERT_NE(blend, nullptr);
  EXPECT_EQ(blend->weight(), Rgb(0.5));
  EXPECT_NE(dynamic_cast<const LambertianBsdf*>(&blend->first()), nullptr);
  const json lambertian{{"type", "lambertian"}};
  const json conductor{{"type", "conductor"}, {"alpha", 0.2}};
  const json given{{"type", "blend"}, {"weight", 0.3}, {"materials", json::array({lambertian, conductor})}};
  const json completed = completeMaterial(given);
  EXPECT_EQ(completed["weight"], 0.3);
  EXPECT_EQ(completed["materials"][0], (json{{"type", "lambertian"}, {"albedo", 0.8}}));
  EXPECT_EQ(completed["materials"][1], completeMaterial(conductor));
  EXPECT_EQ(completed["materials"][1]["distribution"], "ggx");  // a default filled in
  EXPECT_EQ(completed["materials"][1]["alpha"], 0.2);           // the value given kept
  // What is printed is what is built: the completed material builds the same model.
  const Vec3d wi = directionFromDegrees(30, 0), wo = directionFromDegrees(40, 170);
  EXPECT_EQ(makeBsdf(completed)->eval(wi, wo), makeBsdf(given)->eval(wi, wo));
  EXPECT_EQ(completeMaterial(completed), completed);
}

TEST(BlendRegistry, NestedBlendsBuild) {
  const json inner{{"type", "blend"},
                   {"weight", 0.5},
                   {"materials", {{{"type", "lambertian"}}, {{"type", "oren-nayar"}}}}};
  const auto model = makeBsdf({{"type", "blend"}, {"materials", {inner, {{"type", "rough-plastic"}}}}});
  EXPECT_GT(model->pdf(directionFromDegrees(20, 0), directionFromDegrees(30, 100)), 0.0);
  EXPECT_EQ(
      completeMaterial({{"type", "blend"},
                        {"materials", {inner, {{"type", "lambertian"}}}}})["materials"][0]["materials"][1],
      (json{{"type", "oren-nayar"}, {"albedo", 0.8}, {"sigma", 0.35}}));
}

struct NestedError {
  const char* what;
  json material;
  std::vector<std::string> messageContains;
  // Found when the blend is built (its components' lobes and media), not by completeMaterial,
  // which validates descriptions without building models.
  bool atBuild = false;
};
void PrintTo(const NestedError& e, std::ostream* os) { *os << e.what; }

class BlendRegistryErrors : public ::testing::TestWithParam<NestedError> {};

TEST_P(BlendRegistryErrors, NameTheNestedKeyPath) {
  const std::string message = materialErrorOf(GetParam().material);
  ASSERT_FALSE(message.empty()) << GetParam().material.dump();
  for (const std::string& fragment : GetParam().messageContains)
    EXPECT_NE(message.find(fragment), std::string::npos)
        << "\"" << fragment << "\" missing from: " << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  if (!GetParam().atBuild) {
    EXPECT_THROW(completeMaterial(GetParam().material), MaterialError);
  }
}

json blendOf(json first, json second) {
  return {{"type", "blend"}, {"materials", {std::move(first), std::move(second)}}};
}

INSTANTIATE_TEST_SUITE_P(
    Cases, BlendRegistryErrors,
    ::testing::Values(
        NestedError{"out of range",
                    blendOf({{"type", "lambertian"}}, {{"type", "conductor"}, {"alpha", 2}}),
                    {"material key \"materials[1].alpha\": 2 is out of range; allowed: ", "[0.001, 1]"}},
        NestedError{"unknown nested key",
                    blendOf({{"type", "lambertian"}, {"roughness", 1}}, {{"type", "lambertian"}}),
                    {"material key \"materials[0].roughness\"", "\"lambertian\"", "\"albedo\""}},
        NestedError{"nested type missing",
                    blendOf({{"albedo", 0.5}}, {{"type", "lambertian"}}),
                    {"material key \"materials[0].type\" is missing", "\"lambertian\""}},
        NestedError{"nested type unknown",
                    blendOf({{"type", "lambertian"}}, {{"type", "plastic"}}),
                    {"material key \"materials[1].type\": \"plastic\" is not a known model"}},
        NestedError{"nested not an object",
                    blendOf(42, {{"type", "lambertian"}}),
                    {"material key \"materials[0]\": 42 is not a JSON object"}},
        NestedError{"one material",
                    {{"type", "blend"}, {"materials", {{{"type", "lambertian"}}}}},
                    {"material key \"materials\"", "wrong number of materials", "exactly 2 materials"}},
        NestedError{
            "three materials",
            {{"type", "blend"},
             {"materials", {{{"type", "lambertian"}}, {{"type", "lambertian"}}, {{"type", "lambertian"}}}}},
            {"material key \"materials\"", "wrong number of materials"}},
        NestedError{"materials not an array",
                    {{"type", "blend"}, {"materials", {{"type", "lambertian"}}}},
                    {"material key \"materials\"", "wrong type", "exactly 2 materials"}},
        NestedError{"deeper nesting",
                    blendOf(blendOf({{"type", "lambertian"}}, {{"type", "lambertian"}, {"albedo", -1}}),
                            {{"type", "lambertian"}}),
                    {"material key \"materials[0].materials[1].albedo\": -1 is out of range"}},
        NestedError{"weight out of range",
                    {{"type", "blend"}, {"weight", {0.5, 1.5, 0.5}}},
                    {"material key \"weight\"", "g = 1.5", "[0, 1]"}},
        NestedError{"two delta models",
                    blendOf({{"type", "dielectric"}}, {{"type", "smooth-conductor"}}),
                    {"material key \"materials\"", "cannot be blended", "delta"},
                    true},
        NestedError{
            "different interior indices",
            blendOf({{"type", "dielectric"}, {"eta", 1.5}}, {{"type", "rough-dielectric"}, {"eta", 1.33}}),
            {"material key \"materials\"", "cannot be blended", "interior indices"},
            true}),
    [](const ::testing::TestParamInfo<NestedError>& info) {
      return test_names::readableTestName(info.param.what);
    });

TEST(BlendRegistry, TooDeepNestingIsAnErrorNotACrash) {
  json material{{"type", "lambertian"}};
  for (int i = 0; i < 12; ++i) material = blendOf(material, {{"type", "lambertian"}});
  const std::string message = materialErrorOf(material);
  EXPECT_NE(message.find("nests materials too deeply"), std::string::npos) << message;
  EXPECT_NE(message.find("materials[0].materials[0]"), std::string::npos) << message;
}

TEST(BlendRegistry, CatalogDescribesTheNestedKind) {
  EXPECT_EQ(toString(ParameterKind::Materials), "materials");
  const MaterialModel* blend = findMaterialModel("blend");
  ASSERT_NE(blend, nullptr);
  const ParameterSpec* materials = blend->findParameter("materials");
  ASSERT_NE(materials, nullptr);
  EXPECT_NE(materials->allowed().find("exactly 2 materials"), std::string::npos) << materials->allowed();
  for (const json& model : materialCatalogJson()) {
    if (model["type"] != "blend") continue;
    for (const json& parameter : model["parameters"]) {
      if (parameter["name"] != "materials") continue;
      EXPECT_EQ(parameter["kind"], "materials");
      EXPECT_EQ(parameter["count"], 2);
      EXPECT_FALSE(parameter.contains("min"));
      return;
    }
  }
  ADD_FAILURE() << "blend.materials missing from the catalog";
}

TEST(BlendRegistry, ExampleMaterialBuilds) {
  const auto path = std::filesystem::path(SCATTERLAB_DATA_DIR) / "materials" / "blend-varnished-gold.json";
  const auto model = makeBsdf(loadMaterialArgument(path.string()));
  EXPECT_NE(dynamic_cast<const BlendBsdf*>(model.get()), nullptr);
}

}  // namespace blend_test
}  // namespace scatterlab
