// The fit model: --model parsing, which parameters are fitted or held, their bounds from the
// registry, and refusals that name the component and the reason.
#include <gtest/gtest.h>

#include <algorithm>

#include "fitting_test_support.h"

namespace scatterlab::fitting::test {
namespace fit_model_test {

std::vector<std::string> names(const FitModel& model) {
  std::vector<std::string> out;
  for (const FitParameter& p : model.parameters()) out.push_back(p.name);
  return out;
}

const FitParameter& parameter(const FitModel& model, const std::string& name) {
  for (const FitParameter& p : model.parameters())
    if (p.name == name) return p;
  throw std::runtime_error("no parameter " + name);
}

void expectRefused(const std::string& spec, const std::vector<std::string>& fragments, int lobes = 1) {
  try {
    const FitModel model(parseModelSpec(spec, lobes), false);
    ADD_FAILURE() << spec << " was accepted";
  } catch (const MaterialError& error) {
    for (const std::string& fragment : fragments)
      EXPECT_NE(std::string(error.what()).find(fragment), std::string::npos)
          << fragment << " not in: " << error.what();
  }
}

TEST(ModelSpec, SplitsAtTopLevelPlusSignsOnly) {
  const auto parts = parseModelSpec(R"(lambertian + {"type":"conductor","eta":1,"k":1e+8})");
  ASSERT_EQ(parts.size(), 2u);
  EXPECT_EQ(parts[0], json({{"type", "lambertian"}}));
  EXPECT_EQ(parts[1]["k"], 1e8);
  const auto array = parseModelSpec(R"([{"type":"lambertian"},{"type":"ward"}])", 2);
  ASSERT_EQ(array.size(), 3u);
  EXPECT_EQ(array[2]["type"], "ward");
}

TEST(ModelSpec, SumOfLambertianAndCookTorranceFitsAlbedosAndShape) {
  const FitModel model(parseModelSpec("lambertian+ngan-cook-torrance"), false);
  EXPECT_EQ(names(model),
            (std::vector<std::string>{"lambertian.albedo.r", "lambertian.albedo.g", "lambertian.albedo.b",
                                      "ngan-cook-torrance.albedo.r", "ngan-cook-torrance.albedo.g",
                                      "ngan-cook-torrance.albedo.b", "ngan-cook-torrance.eta",
                                      "ngan-cook-torrance.roughness"}));
  // Bounds are the registry's ranges.
  EXPECT_EQ(parameter(model, "ngan-cook-torrance.roughness").lower, 0.001);
  EXPECT_EQ(parameter(model, "ngan-cook-torrance.roughness").upper, 1.0);
  EXPECT_EQ(parameter(model, "lambertian.albedo.g").upper, 1.0);
  EXPECT_EQ(parameter(model, "ngan-cook-torrance.roughness").spacing, GridSpacing::Log);
}

TEST(ModelSpec, GivenValuesAreHeldAndPerChannelShapesMultiply) {
  const FitModel held(parseModelSpec(R"(lambertian+{"type":"ngan-cook-torrance","eta":0.5})"), false);
  EXPECT_EQ(held.parameterCount(), 7u);
  const FitModel perChannel(parseModelSpec("lambertian+ngan-cook-torrance"), true);
  EXPECT_EQ(perChannel.parameterCount(), 12u);
  EXPECT_NO_THROW(parameter(perChannel, "ngan-cook-torrance.roughness.b"));
  EXPECT_TRUE(perChannel.components()[1].perChannel);
  EXPECT_FALSE(perChannel.components()[0].perChannel);  // nothing to evaluate per channel
}

TEST(ModelSpec, IsotropicDataTiesPairsAndLafortunesCxy) {
  const FitModel lafortune(parseModelSpec("lafortune"), false);
  EXPECT_EQ(names(lafortune),
            (std::vector<std::string>{"lafortune.kd.r", "lafortune.kd.g", "lafortune.kd.b", "lafortune.ks.r",
                                      "lafortune.ks.g", "lafortune.ks.b", "lafortune.cx", "lafortune.cz",
                                      "lafortune.exponent"}));
  const FitComponent& comp = lafortune.components()[0];
  EXPECT_EQ(comp.slotParameter[0][0], comp.slotParameter[0][1]);  // cy follows cx
  const FitModel ward(parseModelSpec("ward"), false);
  EXPECT_EQ(ward.parameterCount(), 4u);  // albedo and one alpha for both axes
  const FitModel disney(parseModelSpec("disney"), false);
  EXPECT_EQ(disney.parameterCount(), 12u);  // anisotropic held at 0
  EXPECT_THROW(parameter(disney, "disney.anisotropic"), std::runtime_error);
}

TEST(ModelSpec, ConductorWithAGivenIndexCarriesAScale) {
  const FitModel white(parseModelSpec(std::string("lambertian+") + WhiteConductorSpec), false);
  EXPECT_EQ(names(white),
            (std::vector<std::string>{"lambertian.albedo.r", "lambertian.albedo.g", "lambertian.albedo.b",
                                      "conductor.scale.r", "conductor.scale.g", "conductor.scale.b",
                                      "conductor.alpha"}));
  EXPECT_EQ(white.components()[1].description["k"], 1e8);
  const FitModel copper(parseModelSpec(R"({"type":"conductor","metal":"Cu","distribution":"beckmann"})"),
                        false);
  EXPECT_FALSE(copper.components()[0].description.contains("metal"));
  EXPECT_TRUE(std::holds_alternative<ConductorKernel<BeckmannDistribution>>(copper.components()[0].kernel));
}

TEST(ModelSpec, RepeatedLobesHoldTheirDiffuseTerm) {
  const FitModel model(parseModelSpec("blinn-phong", 2), false);
  ASSERT_EQ(model.components().size(), 2u);
  EXPECT_EQ(model.components()[0].label, "blinn-phong#1");
  EXPECT_EQ(model.components()[1].label, "blinn-phong#2");
  EXPECT_NO_THROW(parameter(model, "blinn-phong#1.kd.r"));
  EXPECT_THROW(parameter(model, "blinn-phong#2.kd.r"), std::runtime_error);
  EXPECT_NO_THROW(parameter(model, "blinn-phong#2.ks.r"));
}

TEST(ModelSpec, RefusalsNameTheComponentAndTheReason) {
  expectRefused("lambertian+ggx", {"\"ggx\" is not a known model", "allowed", "ngan-cook-torrance"});
  expectRefused("dielectric", {"\"dielectric\" cannot be fitted", "delta"});
  expectRefused("lambertian+blend", {"cannot be fitted", "joined by '+'"});
  expectRefused("measured", {"cannot be fitted", "data"});
  expectRefused("rough-plastic", {"cannot be fitted", "tables"});
  expectRefused("lambertian++ward", {"empty component"});
  expectRefused(R"(lambertian+{"type":"ward","alpha":2})", {"\"ward\"", "alpha", "[0.001, 1]"});
  expectRefused(R"(lambertian+{"type":"ward",)", {"not valid JSON"});
  expectRefused("lambertian+eon", {"eon", "only be fitted alone"});
  expectRefused(R"({"type":"conductor","multiscatter":"kulla-conty"})", {"multiscatter", "none"});
  expectRefused(R"({"type":"lambertian","colour":1})", {"colour", "not a key"});
}

TEST(ModelSpec, EveryFittableModelBuildsFromItsDefaults) {
  for (const std::string& type : fittableModels()) {
    EXPECT_NO_THROW(FitModel(parseModelSpec(type), false)) << type;
    EXPECT_NO_THROW(FitModel(parseModelSpec(type), true)) << type;
  }
}

}  // namespace fit_model_test
}  // namespace scatterlab::fitting::test
