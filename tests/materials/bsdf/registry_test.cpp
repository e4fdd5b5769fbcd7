#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>

#include "materials/bsdf/lambertian.h"
#include "materials/bsdf/metals.h"
#include "materials/bssrdf/subsurface_registry.h"
#include "materials/registry/material_file.h"
#include "materials/registry/model_list.h"
#include "materials/registry/spec_validation.h"
#include "tests/test_names.h"

namespace scatterlab {
namespace registry_test {

using nlohmann::json;
namespace fs = std::filesystem;

// The message of the MaterialError that building `material` throws ("" if none is thrown).
std::string materialErrorOf(const json& material) {
  try {
    makeBsdf(material);
  } catch (const MaterialError& error) {
    return error.what();
  }
  return "";
}

std::string loadErrorOf(const std::string& argument) {
  try {
    loadMaterialArgument(argument);
  } catch (const MaterialError& error) {
    return error.what();
  }
  return "";
}

fs::path testOutputDir() {
  const fs::path dir = fs::path(SCATTERLAB_TEST_OUTPUT_DIR) / "registry";
  fs::create_directories(dir);
  return dir;
}

void writeFile(const fs::path& path, const std::string& contents) { std::ofstream(path) << contents; }

Rgb albedoOf(const json& material) {
  const auto model = makeBsdf(material);
  const auto* lambertian = dynamic_cast<const LambertianBsdf*>(model.get());
  EXPECT_NE(lambertian, nullptr);
  return lambertian ? lambertian->albedo() : Rgb(-1.0);
}

// ---- Defaults -------------------------------------------------------------------------

// Models with a required parameter (a measured file) cannot be built from their type alone.
bool hasRequiredParameter(const MaterialModel& model) {
  return std::any_of(model.parameters.begin(), model.parameters.end(),
                     [](const ParameterSpec& spec) { return spec.required; });
}

TEST(MaterialRegistry, EveryModelBuildsFromItsTypeAlone) {
  const Vec3d wi = directionFromDegrees(40, 10), wo = directionFromDegrees(35, 200);
  for (const MaterialModel& model : materialModels()) {
    SCOPED_TRACE(model.type);
    if (model.kind != MaterialKind::Bsdf) continue;  // subsurface_registry_test.cpp
    if (hasRequiredParameter(model)) {
      EXPECT_THROW(makeBsdf(json{{"type", model.type}}), MaterialError);
      continue;
    }
    const auto bsdf = makeBsdf(json{{"type", model.type}});
    ASSERT_NE(bsdf, nullptr);
    // Delta lobes only (a mirror, smooth glass): eval and pdf are 0 for every pair (bsdf.h),
    // so the model must produce a sample instead.
    if (!hasAny(bsdf->flags(), LobeFlags::Diffuse | LobeFlags::Glossy)) {
      const auto s = bsdf->sample(wi, 0.5, {0.5, 0.5});
      ASSERT_TRUE(s.has_value());
      EXPECT_TRUE(s->isDelta() && s->pdf > 0 && std::isfinite(s->weight.x));
      continue;
    }
    const Rgb f = bsdf->eval(wi, wo);
    for (int c = 0; c < 3; ++c)
      EXPECT_TRUE(std::isfinite(f[c]) && f[c] > 0) << "channel " << c << ": " << f[c];
    EXPECT_GT(bsdf->pdf(wi, wo), 0.0);
  }
}

TEST(MaterialRegistry, CompleteMaterialFillsEveryDefault) {
  for (const MaterialModel& model : materialModels()) {
    SCOPED_TRACE(model.type);
    // Subsurface defaults depend on other keys (a medium's eta): subsurface_registry_test.cpp.
    if (hasRequiredParameter(model) || model.completeDependent) continue;
    const json completed = completeMaterial(json{{"type", model.type}});
    EXPECT_EQ(completed["type"], model.type);
    for (const ParameterSpec& spec : model.parameters) {
      if (spec.defaultValue.is_null()) {
        EXPECT_FALSE(completed.contains(spec.name)) << spec.name;
      } else if (spec.kind == ParameterKind::Materials) {
        // Nested materials are completed as well.
        json expected = json::array();
        for (const json& nested : spec.defaultValue) expected.push_back(completeMaterial(nested));
        EXPECT_EQ(completed.value(spec.name, json()), expected) << spec.name;
      } else {
        EXPECT_EQ(completed.value(spec.name, json()), spec.defaultValue) << spec.name;
      }
    }
  }
  const json conductorDefaults{{"type", "conductor"}, {"distribution", "ggx"}, {"alpha", 0.1},
                               {"metal", "Au"},       {"sampling", "visible"}, {"multiscatter", "none"}};
  EXPECT_EQ(completeMaterial(json{{"type", "conductor"}}), conductorDefaults);
  EXPECT_EQ(completeMaterial(json{{"type", "lambertian"}}), (json{{"type", "lambertian"}, {"albedo", 0.8}}));
}

TEST(MaterialRegistry, CompleteMaterialKeepsGivenValuesAndTheChosenAlternative) {
  const json material{{"type", "conductor"}, {"alpha", {0.3, 0.1}}, {"eta", {0.2, 0.4, 1.4}}, {"k", 3.0}};
  const json completed = completeMaterial(material);
  EXPECT_EQ(completed["alpha"], material["alpha"]);
  EXPECT_EQ(completed["eta"], material["eta"]);
  EXPECT_EQ(completed["k"], material["k"]);
  EXPECT_FALSE(completed.contains("metal"));  // eta and k replace it
  EXPECT_EQ(completed["distribution"], "ggx");
  EXPECT_EQ(completed["sampling"], "visible");
}

// ---- Values ---------------------------------------------------------------------------

TEST(MaterialRegistry, RgbGivenAsANumberBroadcasts) {
  EXPECT_EQ(albedoOf(json{{"type", "lambertian"}, {"albedo", 0.25}}), Rgb(0.25));
  EXPECT_EQ(albedoOf(json{{"type", "lambertian"}, {"albedo", 1}}), Rgb(1.0));  // an integer is a number too
  EXPECT_EQ(albedoOf(json{{"type", "lambertian"}, {"albedo", {0.1, 0.2, 0.3}}}), Rgb(0.1, 0.2, 0.3));
  EXPECT_EQ(albedoOf(json{{"type", "lambertian"}}), Rgb(0.8));
}

TEST(MaterialRegistry, NamedMetalAndItsExplicitIorBuildTheSameModel) {
  const MetalIor* gold = findMetal("Au");
  ASSERT_NE(gold, nullptr);
  const json explicitIor{{"type", "conductor"},
                         {"eta", {gold->eta.x, gold->eta.y, gold->eta.z}},
                         {"k", {gold->k.x, gold->k.y, gold->k.z}}};
  const auto named = makeBsdf(json{{"type", "conductor"}, {"metal", "Au"}});
  const auto given = makeBsdf(explicitIor);
  const Vec3d wi = directionFromDegrees(60, 30), wo = directionFromDegrees(45, 200);
  EXPECT_EQ(named->eval(wi, wo), given->eval(wi, wo));
  EXPECT_NE(named->eval(wi, wo), makeBsdf(json{{"type", "conductor"}, {"metal", "Ag"}})->eval(wi, wo));
}

TEST(MaterialRegistry, AnisotropicAlphaIsNotTheIsotropicOne) {
  const auto isotropic = makeBsdf(json{{"type", "conductor"}, {"alpha", 0.3}});
  const auto anisotropic = makeBsdf(json{{"type", "conductor"}, {"alpha", {0.3, 0.1}}});
  const auto sameAsIsotropic = makeBsdf(json{{"type", "conductor"}, {"alpha", {0.3, 0.3}}});
  const Vec3d wi = directionFromDegrees(40, 30), wo = directionFromDegrees(35, 250);
  EXPECT_EQ(isotropic->pdf(wi, wo), sameAsIsotropic->pdf(wi, wo));
  EXPECT_NE(isotropic->pdf(wi, wo), anisotropic->pdf(wi, wo));
}

// ---- Bad input: every message names the key, the value given and what is allowed -------

struct BadMaterial {
  const char* what;
  json material;
  std::vector<std::string> messageContains;
};

void PrintTo(const BadMaterial& bad, std::ostream* os) { *os << bad.what << ": " << bad.material.dump(); }

class BadMaterialTest : public ::testing::TestWithParam<BadMaterial> {};

TEST_P(BadMaterialTest, IsRejectedWithAMessageNamingKeyValueAndAllowed) {
  const BadMaterial& bad = GetParam();
  const std::string message = materialErrorOf(bad.material);
  ASSERT_FALSE(message.empty()) << bad.what << ": no MaterialError for " << bad.material.dump();
  for (const std::string& fragment : bad.messageContains)
    EXPECT_NE(message.find(fragment), std::string::npos)
        << "\"" << fragment << "\" missing from: " << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << "one line: " << message;
  // completeMaterial validates exactly as makeBsdf does.
  EXPECT_THROW(completeMaterial(bad.material), MaterialError);
}

const double NaN = std::numeric_limits<double>::quiet_NaN();
const double Infinity = std::numeric_limits<double>::infinity();

INSTANTIATE_TEST_SUITE_P(
    MaterialRegistry, BadMaterialTest,
    ::testing::Values(
        BadMaterial{"negative roughness",
                    {{"type", "conductor"}, {"alpha", -0.1}},
                    {"\"alpha\"", "-0.1", "out of range", "[0.001, 1]", "[alpha_x, alpha_y]"}},
        BadMaterial{
            "roughness above 1", {{"type", "conductor"}, {"alpha", 1.5}}, {"\"alpha\"", "1.5", "[0.001, 1]"}},
        BadMaterial{
            "NaN roughness", {{"type", "conductor"}, {"alpha", NaN}}, {"\"alpha\"", "NaN", "[0.001, 1]"}},
        BadMaterial{"infinite roughness",
                    {{"type", "conductor"}, {"alpha", Infinity}},
                    {"\"alpha\"", "inf", "[0.001, 1]"}},
        BadMaterial{"one anisotropic component out of range",
                    {{"type", "conductor"}, {"alpha", {0.3, -0.1}}},
                    {"\"alpha\"", "[0.3,-0.1]", "alpha_y = -0.1", "[0.001, 1]"}},
        BadMaterial{"pair of the wrong length",
                    {{"type", "conductor"}, {"alpha", {0.3}}},
                    {"\"alpha\"", "[0.3]", "wrong type", "[alpha_x, alpha_y]"}},
        BadMaterial{"roughness as a string",
                    {{"type", "conductor"}, {"alpha", "rough"}},
                    {"\"alpha\"", "\"rough\"", "wrong type", "[0.001, 1]"}},
        BadMaterial{"roughness null",
                    {{"type", "conductor"}, {"alpha", nullptr}},
                    {"\"alpha\"", "null", "wrong type"}},
        BadMaterial{
            "albedo above 1", {{"type", "lambertian"}, {"albedo", 1.5}}, {"\"albedo\"", "1.5", "[0, 1]"}},
        BadMaterial{"albedo channel negative",
                    {{"type", "lambertian"}, {"albedo", {0.5, -0.2, 0.5}}},
                    {"\"albedo\"", "[0.5,-0.2,0.5]", "g = -0.2", "[0, 1]"}},
        BadMaterial{"albedo with two channels",
                    {{"type", "lambertian"}, {"albedo", {0.5, 0.5}}},
                    {"\"albedo\"", "[0.5,0.5]", "wrong type", "[r, g, b]"}},
        BadMaterial{"albedo as a boolean",
                    {{"type", "lambertian"}, {"albedo", true}},
                    {"\"albedo\"", "true", "wrong type"}},
        BadMaterial{"eta zero",
                    {{"type", "conductor"}, {"eta", {1.0, 0.0, 1.0}}, {"k", 1.0}},
                    {"\"eta\"", "[1.0,0.0,1.0]", "g = 0", "> 0"}},
        BadMaterial{
            "negative k", {{"type", "conductor"}, {"eta", 1.0}, {"k", -1.0}}, {"\"k\"", "-1", ">= 0"}},
        BadMaterial{"unknown distribution",
                    {{"type", "conductor"}, {"distribution", "phong"}},
                    {"\"distribution\"", "\"phong\"", "one of \"ggx\", \"beckmann\""}},
        BadMaterial{"unknown metal",
                    {{"type", "conductor"}, {"metal", "Pt"}},
                    {"\"metal\"", "\"Pt\"", "\"Au\"", "\"Ag\"", "\"Al\"", "\"Cu\"", "\"Cr\""}},
        BadMaterial{"sampling as a number",
                    {{"type", "conductor"}, {"sampling", 3}},
                    {"\"sampling\"", "3", "wrong type", "\"visible\", \"classic\""}},
        BadMaterial{"unknown model",
                    {{"type", "plastic"}},
                    {"\"type\"", "\"plastic\"", "\"lambertian\"", "\"conductor\""}},
        BadMaterial{"type as a number", {{"type", 5}}, {"\"type\"", "5", "wrong type", "\"lambertian\""}},
        BadMaterial{"no type", {{"albedo", 0.5}}, {"\"type\"", "missing", "\"lambertian\"", "\"conductor\""}},
        BadMaterial{
            "unknown key",
            {{"type", "conductor"}, {"roughness", 0.1}},
            {"\"roughness\"", "0.1", "\"conductor\"", "\"alpha\"", "\"distribution\"", "\"sampling\""}},
        BadMaterial{"not an object", json::array({1, 2}), {"[1,2]", "object"}},
        BadMaterial{"metal together with eta and k",
                    {{"type", "conductor"}, {"metal", "Au"}, {"eta", 1.0}, {"k", 1.0}},
                    {"\"eta\"", "\"metal\"", "either \"metal\", or \"eta\" and \"k\" together"}},
        BadMaterial{"eta without k",
                    {{"type", "conductor"}, {"eta", {0.2, 0.4, 1.4}}},
                    {"\"eta\"", "[0.2,0.4,1.4]", "needs \"k\"", "\"eta\" and \"k\" together"}},
        BadMaterial{"k without eta", {{"type", "conductor"}, {"k", 3.0}}, {"\"k\"", "3", "needs \"eta\""}}),
    [](const ::testing::TestParamInfo<BadMaterial>& info) {
      return test_names::readableTestName(info.param.what);
    });

// ---- Roughness scaling for the negative control -----------------------------------------

TEST(MaterialRegistry, WithScaledRoughnessScalesScalarAlpha) {
  const auto scaled = withScaledRoughness(json{{"type", "conductor"}, {"alpha", 0.2}}, 1.1);
  ASSERT_TRUE(scaled.has_value());
  EXPECT_DOUBLE_EQ((*scaled)["alpha"].get<double>(), 0.22);
  EXPECT_EQ((*scaled)["metal"], "Au");  // completed
  EXPECT_NO_THROW(makeBsdf(*scaled));
}

TEST(MaterialRegistry, WithScaledRoughnessScalesEachComponentOfAPair) {
  const auto scaled = withScaledRoughness(json{{"type", "conductor"}, {"alpha", {0.3, 0.1}}}, 1.1);
  ASSERT_TRUE(scaled.has_value());
  EXPECT_DOUBLE_EQ((*scaled)["alpha"][0].get<double>(), 0.33);
  EXPECT_DOUBLE_EQ((*scaled)["alpha"][1].get<double>(), 0.11);
}

TEST(MaterialRegistry, WithScaledRoughnessScalesTheDefault) {
  const auto scaled = withScaledRoughness(json{{"type", "conductor"}}, 2.0);
  ASSERT_TRUE(scaled.has_value());
  EXPECT_DOUBLE_EQ((*scaled)["alpha"].get<double>(), 0.2);
}

TEST(MaterialRegistry, WithScaledRoughnessClampsToTheAllowedRange) {
  const auto up = withScaledRoughness(json{{"type", "conductor"}, {"alpha", {1.0, 0.5}}}, 1.1);
  ASSERT_TRUE(up.has_value());
  EXPECT_EQ((*up)["alpha"][0].get<double>(), 1.0);
  EXPECT_DOUBLE_EQ((*up)["alpha"][1].get<double>(), 0.55);
  const auto down = withScaledRoughness(json{{"type", "conductor"}, {"alpha", 0.001}}, 0.5);
  ASSERT_TRUE(down.has_value());
  EXPECT_EQ((*down)["alpha"].get<double>(), 0.001);
}

TEST(MaterialRegistry, WithScaledRoughnessIsEmptyForModelsWithoutRoughness) {
  EXPECT_FALSE(withScaledRoughness(json{{"type", "lambertian"}}, 1.1).has_value());
  EXPECT_THROW(withScaledRoughness(json{{"type", "conductor"}, {"alpha", -1}}, 1.1), MaterialError);
}

// An exponent narrows its lobe as it grows: "10% rougher" divides it.
TEST(MaterialRegistry, WithScaledRoughnessDividesAnExponent) {
  const auto rougher = withScaledRoughness(json{{"type", "phong"}, {"exponent", 110.0}}, 1.1);
  ASSERT_TRUE(rougher.has_value());
  EXPECT_DOUBLE_EQ((*rougher)["exponent"].get<double>(), 100.0);
}

TEST(MaterialRegistry, EveryDeclaredLobeWidthIsANumberOrPairParameter) {
  for (const MaterialModel& model : materialModels()) {
    if (model.lobeWidthParameter.empty()) continue;
    SCOPED_TRACE(model.type);
    const ParameterSpec* spec = model.findParameter(model.lobeWidthParameter);
    ASSERT_NE(spec, nullptr);
    EXPECT_TRUE(spec->kind == ParameterKind::Number || spec->kind == ParameterKind::Pair);
  }
}

// At the range limit, scaling up changes nothing; the mismatch then scales down instead.
TEST(MaterialRegistry, MismatchedRoughnessTurnsBackAtTheRangeLimit) {
  const auto atLimit = withMismatchedRoughness(json{{"type", "conductor"}, {"alpha", 1.0}}, 1.1);
  ASSERT_TRUE(atLimit.has_value());
  EXPECT_DOUBLE_EQ((*atLimit)["alpha"].get<double>(), 1.0 / 1.1);
  const auto inside = withMismatchedRoughness(json{{"type", "conductor"}, {"alpha", 0.5}}, 1.1);
  EXPECT_DOUBLE_EQ((*inside)["alpha"].get<double>(), 0.55);
  EXPECT_FALSE(withMismatchedRoughness(json{{"type", "lambertian"}}, 1.1).has_value());
}

// ---- Material arguments -----------------------------------------------------------------

TEST(MaterialArgument, InlineJson) {
  EXPECT_TRUE(isInlineMaterial(R"({"type": "lambertian"})"));
  EXPECT_TRUE(isInlineMaterial(R"(  {"type": "lambertian"})"));
  EXPECT_FALSE(isInlineMaterial("gold.json"));
  EXPECT_EQ(loadMaterialArgument(R"({"type": "conductor", "alpha": [0.3, 0.1]})"),
            (json{{"type", "conductor"}, {"alpha", {0.3, 0.1}}}));
}

TEST(MaterialArgument, File) {
  const fs::path path = testOutputDir() / "gold.json";
  writeFile(path, "{\n  \"type\": \"conductor\",\n  \"metal\": \"Au\"\n}\n");
  const json material = loadMaterialArgument(path.string());
  EXPECT_EQ(material, (json{{"type", "conductor"}, {"metal", "Au"}}));
  EXPECT_NO_THROW(makeBsdf(material));
}

TEST(MaterialArgument, MissingFileIsNamed) {
  const std::string path = (testOutputDir() / "no-such-material.json").string();
  const std::string message = loadErrorOf(path);
  EXPECT_NE(message.find(path), std::string::npos) << message;
  EXPECT_NE(message.find("not found"), std::string::npos) << message;
}

TEST(MaterialArgument, DirectoryIsNotAMaterialFile) {
  const std::string message = loadErrorOf(testOutputDir().string());
  EXPECT_NE(message.find("is a directory"), std::string::npos) << message;
}

TEST(MaterialArgument, ParseErrorInAFileNamesTheFileAndPosition) {
  const fs::path path = testOutputDir() / "broken.json";
  writeFile(path, "{\n  \"type\": \"conductor\",\n  \"alpha\": 0.1,\n}\n");
  const std::string message = loadErrorOf(path.string());
  EXPECT_NE(message.find(path.string()), std::string::npos) << message;
  EXPECT_NE(message.find("line 4, column 1"), std::string::npos) << message;
}

TEST(MaterialArgument, NaNInInlineJsonNamesTheKey) {
  const std::string message = loadErrorOf(R"({"type": "conductor", "alpha": NaN})");
  for (const char* fragment : {"\"alpha\"", "inline JSON", "line 1, column 32", "NaN"})
    EXPECT_NE(message.find(fragment), std::string::npos)
        << "\"" << fragment << "\" missing from: " << message;
}

TEST(MaterialArgument, NaNInsideAnArrayNamesTheKey) {
  const std::string message = loadErrorOf(R"({"type": "conductor", "alpha": [0.1, NaN]})");
  EXPECT_NE(message.find("material key \"alpha\""), std::string::npos) << message;
}

TEST(MaterialArgument, SyntaxErrorOutsideAValueNamesThePosition) {
  const std::string message = loadErrorOf(R"({"type": "conductor",)");
  EXPECT_NE(message.find("inline JSON, line 1, column 22"), std::string::npos) << message;
  EXPECT_EQ(message.find("material key"), std::string::npos) << message;
}

TEST(MaterialArgument, ShippedExamplesBuild) {
  int count = 0;
  for (const auto& entry : fs::directory_iterator(fs::path(SCATTERLAB_DATA_DIR) / "materials")) {
    if (entry.path().extension() != ".json") continue;
    SCOPED_TRACE(entry.path().string());
    const json material = loadMaterialArgument(entry.path().string());
    if (isSubsurfaceMaterial(material))
      EXPECT_NO_THROW(makeSubsurface(material));
    else
      EXPECT_NO_THROW(makeBsdf(material));
    ++count;
  }
  EXPECT_GE(count, 3);
}

// ---- Catalog ----------------------------------------------------------------------------

TEST(MaterialCatalog, ListsEveryModelWithParameterRanges) {
  const json catalog = materialCatalogJson();
  ASSERT_EQ(catalog.size(), materialModels().size());
  std::map<std::string, json> byType;
  for (const json& model : catalog) byType[model["type"]] = model;
  ASSERT_TRUE(byType.contains("lambertian"));
  ASSERT_TRUE(byType.contains("conductor"));
  for (const json& model : catalog) {
    EXPECT_FALSE(model["description"].get<std::string>().empty());
    EXPECT_FALSE(model["citation"].get<std::string>().empty());
  }
  std::map<std::string, json> conductor;
  for (const json& parameter : byType["conductor"]["parameters"]) conductor[parameter["name"]] = parameter;
  EXPECT_EQ(conductor["alpha"]["kind"], "pair");
  EXPECT_EQ(conductor["alpha"]["min"], 0.001);
  EXPECT_EQ(conductor["alpha"]["max"], 1.0);
  EXPECT_EQ(conductor["alpha"]["default"], 0.1);
  EXPECT_EQ(conductor["eta"]["min"], 0.0);
  EXPECT_EQ(conductor["eta"]["min_open"], true);
  EXPECT_TRUE(conductor["eta"]["max"].is_null());  // unbounded
  EXPECT_TRUE(conductor["eta"]["default"].is_null());
  EXPECT_EQ(conductor["metal"]["choices"], (json{"Au", "Ag", "Al", "Cu", "Cr"}));
  EXPECT_EQ(byType["conductor"]["alternatives"], (json{{"metal"}, {"eta", "k"}}));
}

TEST(MaterialCatalog, RangesDescribeTheirEnds) {
  EXPECT_EQ(ValueRange::closed(0.001, 1).describe(), "in [0.001, 1]");
  EXPECT_EQ(ValueRange::above(0).describe(), "> 0");
  EXPECT_EQ(ValueRange::atLeast(0).describe(), ">= 0");
  EXPECT_EQ((ValueRange{0, 90, false, true}).describe(), "in [0, 90)");
  EXPECT_TRUE((ValueRange{0, 90, false, true}).contains(0));
  EXPECT_FALSE((ValueRange{0, 90, false, true}).contains(90));
  EXPECT_FALSE(ValueRange::above(0).contains(0));
  EXPECT_GT(ValueRange::above(0).clamp(-1), 0.0);
}

}  // namespace registry_test
}  // namespace scatterlab

namespace scatterlab {
namespace registry_test {

// The typed value carries a material through the builders and the roughness-mismatch control
// without a second validation, and gives what the JSON route gives.
TEST(ValidatedMaterial, IsBuiltAndMadeRougherWithoutValidatingAgain) {
  const nlohmann::json material = {{"type", "conductor"}, {"alpha", {0.3, 0.2}}, {"metal", "Au"}};
  const uint64_t before = materialValidationCount();
  const ValidatedMaterial validated = validateMaterial(material);
  const auto bsdf = makeBsdf(validated);
  const auto rougher = withMismatchedRoughness(validated, 1.1);
  ASSERT_TRUE(rougher.has_value());
  const auto rougherBsdf = makeBsdf(*rougher);
  EXPECT_EQ(materialValidationCount() - before, 1u);

  EXPECT_EQ(rougher->completed, *withMismatchedRoughness(material, 1.1));
  EXPECT_DOUBLE_EQ(rougher->parameters.pair("alpha").x, 0.3 * 1.1);
  EXPECT_DOUBLE_EQ(rougher->parameters.pair("alpha").y, 0.2 * 1.1);
  const Vec3d wi = glm::normalize(Vec3d(0.3, 0.1, 0.9)), wo = glm::normalize(Vec3d(-0.2, 0.1, 0.95));
  EXPECT_EQ(rougherBsdf->eval(wi, wo), makeBsdf(*withMismatchedRoughness(material, 1.1))->eval(wi, wo));
  EXPECT_EQ(bsdf->eval(wi, wo), makeBsdf(material)->eval(wi, wo));
}

}  // namespace registry_test
}  // namespace scatterlab
