// What a plugin's model must satisfy before it joins the registry (materials/registry/plugin.h,
// checkPluginModel and the spec check every model passes), and the guard around its calls
// (plugin_bsdf.h). The registry itself is not changed here: the command-line tests load real
// plugins in processes of their own (tests/app/plugin_cli_test.cpp).
#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>
#include <string>

#include "materials/bsdf/lambertian.h"
#include "materials/registry/model_list.h"
#include "materials/registry/plugin.h"
#include "materials/registry/plugin_bsdf.h"
#include "materials/registry/spec_validation.h"

namespace scatterlab {
namespace plugin_model_test {

using nlohmann::json;

std::unique_ptr<BsdfModel> buildGrey(const MaterialParameters& p) {
  return std::make_unique<LambertianBsdf>(Rgb(p.number("albedo")));
}

// A plugin's model as a plugin would register it: one number parameter with a default.
MaterialModel greyModel() {
  return {.type = "grey",
          .description = "a grey Lambertian",
          .citation = "none",
          .parameters = {numberParameter("albedo", ValueRange::closed(0.0, 1.0), 0.5, "albedo")},
          .build = buildGrey,
          .plugin = "/plugins/libgrey.so"};
}

// The message of the MaterialError that checkPluginModel throws ("" if none).
std::string refusalOf(const MaterialModel& model) {
  try {
    checkPluginModel(model);
  } catch (const MaterialError& error) {
    return error.what();
  }
  return "";
}

void expectRefusal(const MaterialModel& model, const std::vector<std::string>& fragments) {
  const std::string message = refusalOf(model);
  ASSERT_FALSE(message.empty()) << "accepted";
  for (const std::string& fragment : fragments)
    EXPECT_NE(message.find(fragment), std::string::npos)
        << "\"" << fragment << "\" missing from: " << message;
}

TEST(PluginModel, EveryBuiltInModelPassesTheSpecCheck) {
  for (const MaterialModel& model : materialModels()) EXPECT_NO_THROW(checkModelSpec(model)) << model.type;
}

TEST(PluginModel, AWellFormedModelIsAccepted) { EXPECT_EQ(refusalOf(greyModel()), ""); }

TEST(PluginModel, AParameterWithoutADefaultIsRefused) {
  MaterialModel model = greyModel();
  model.parameters[0].defaultValue = nullptr;
  expectRefusal(model, {"model \"grey\"", "parameter \"albedo\" has no default", "{\"type\": \"grey\"}"});
  model.parameters[0].defaultValue = 0.5;
  model.parameters[0].required = true;
  expectRefusal(model, {"parameter \"albedo\" has no default"});
}

TEST(PluginModel, ADefaultOutsideItsRangeIsRefused) {
  MaterialModel model = greyModel();
  model.parameters[0].defaultValue = 2.0;
  expectRefusal(model, {"parameter \"albedo\"", "its default is not a valid value", "out of range"});
}

TEST(PluginModel, ASubsurfaceModelIsRefused) {
  MaterialModel model = greyModel();
  model.kind = MaterialKind::Subsurface;
  expectRefusal(model, {"subsurface", "BSDF models"});
}

TEST(PluginModel, AModelWithoutABuildFunctionIsRefused) {
  MaterialModel model = greyModel();
  model.build = nullptr;
  expectRefusal(model, {"without a build function"});
}

TEST(PluginModel, ATypeThatIsNotAPlainNameIsRefused) {
  for (const char* type : {"", "my model", "a\"b", "{x}"}) {
    MaterialModel model = greyModel();
    model.type = type;
    expectRefusal(model, {"the type is not a plain name"});
  }
}

TEST(PluginModel, AParameterListedTwiceIsRefused) {
  MaterialModel model = greyModel();
  model.parameters.push_back(model.parameters[0]);
  expectRefusal(model, {"parameter \"albedo\" is listed twice"});
}

TEST(PluginModel, ALobeWidthThatIsNoNumberParameterIsRefused) {
  MaterialModel model = greyModel();
  model.lobeWidthParameter = "alpha";
  expectRefusal(model, {"lobe-width parameter \"alpha\"", "not a number or pair parameter"});
}

TEST(PluginModel, AFitKernelOfTheWrongWidthIsRefused) {
  MaterialModel model = greyModel();
  model.fitKernel = {2, [](const double*, const Vec3d&, const Vec3d&, double value[3], double*) {
                       value[0] = value[1] = value[2] = 0;
                     }};
  expectRefusal(model, {"its fit kernel reads 2 values, its spec has 1"});
}

TEST(PluginModel, AddingATypeThatExistsIsRefusedAndChangesNothing) {
  MaterialModel model = greyModel();
  model.type = "lambertian";
  const size_t before = materialModels().size();
  try {
    addMaterialModel(model);
    ADD_FAILURE() << "accepted";
  } catch (const MaterialError& error) {
    EXPECT_NE(std::string(error.what()).find("model type \"lambertian\" already exists (built in)"),
              std::string::npos)
        << error.what();
  }
  EXPECT_EQ(materialModels().size(), before);
}

// ---- The guard around a plugin's calls --------------------------------------------------------

class ThrowingBsdf final : public BsdfModel {
 public:
  Rgb eval(const Vec3d&, const Vec3d&, TransportMode) const override {
    throw std::runtime_error("eval broke");
  }
  double pdf(const Vec3d&, const Vec3d&, TransportMode) const override { throw 42; }
  std::optional<BsdfSample> sample(const Vec3d&, double, const Vec2d&, TransportMode) const override {
    throw std::out_of_range("sample broke");
  }
  LobeFlags flags() const override { return LobeFlags::DiffuseReflection; }
};

std::string pluginErrorOf(const std::function<void()>& call) {
  try {
    call();
  } catch (const PluginError& error) {
    return error.what();
  }
  return "";
}

TEST(PluginBsdfGuard, AnExceptionFromThePluginBecomesAPluginErrorNamingTheCall) {
  const MaterialModel entry = greyModel();
  const PluginBsdf guarded(std::make_unique<ThrowingBsdf>(), entry);
  const Vec3d wi(0, 0, 1), wo(0.5, 0, 0.8660254037844386);
  const std::string eval = pluginErrorOf([&] { guarded.eval(wi, wo); });
  for (const char* fragment : {"plugin model \"grey\" (/plugins/libgrey.so)",
                               "eval(wi = (0, 0, 1), wo = (0.5, 0, 0.866", "radiance", "threw: eval broke"})
    EXPECT_NE(eval.find(fragment), std::string::npos) << fragment << " missing from: " << eval;
  EXPECT_NE(pluginErrorOf([&] { guarded.pdf(wi, wo); }).find("pdf(wi = (0, 0, 1)"), std::string::npos);
  EXPECT_NE(pluginErrorOf([&] { guarded.pdf(wi, wo); }).find("not a std::exception"), std::string::npos);
  const std::string sample = pluginErrorOf([&] { guarded.sample(wi, 0.25, Vec2d(0.5, 0.75)); });
  EXPECT_NE(sample.find("uLobe = 0.25, u = (0.5, 0.75)"), std::string::npos) << sample;
  EXPECT_NE(sample.find("threw: sample broke"), std::string::npos) << sample;
  EXPECT_EQ(guarded.flags(), LobeFlags::DiffuseReflection);  // what does not throw passes through
}

TEST(PluginBsdfGuard, ValuesPassUnchanged) {
  const MaterialModel entry = greyModel();
  MaterialParameters parameters;
  parameters.set("albedo", 0.25);
  const std::unique_ptr<BsdfModel> guarded = buildPluginBsdf(entry, parameters);
  const LambertianBsdf plain(Rgb(0.25));
  const Vec3d wi(0.3, 0.1, 0.9486832980505138), wo(-0.2, 0.4, 0.8944271909999159);
  EXPECT_EQ(guarded->eval(wi, wo), plain.eval(wi, wo));
  EXPECT_EQ(guarded->pdf(wi, wo), plain.pdf(wi, wo));
  EXPECT_EQ(guarded->sample(wi, 0.5, Vec2d(0.3, 0.7))->wo, plain.sample(wi, 0.5, Vec2d(0.3, 0.7))->wo);
}

TEST(PluginBsdfGuard, ABuildThatThrowsOrBuildsNothingIsAPluginErrorAndAMaterialErrorPasses) {
  MaterialModel entry = greyModel();
  const MaterialParameters parameters;
  entry.build = [](const MaterialParameters&) -> std::unique_ptr<BsdfModel> {
    throw std::runtime_error("no memory for the table");
  };
  EXPECT_NE(
      pluginErrorOf([&] { buildPluginBsdf(entry, parameters); }).find("build threw: no memory for the table"),
      std::string::npos);
  entry.build = [](const MaterialParameters&) -> std::unique_ptr<BsdfModel> { return nullptr; };
  EXPECT_NE(pluginErrorOf([&] { buildPluginBsdf(entry, parameters); }).find("build returned no model"),
            std::string::npos);
  entry.build = [](const MaterialParameters&) -> std::unique_ptr<BsdfModel> {
    throw MaterialError("material key \"albedo\": 0.5 and 0.5 together; allowed: anything else");
  };
  try {
    buildPluginBsdf(entry, parameters);
    ADD_FAILURE() << "no exception";
  } catch (const PluginError&) {
    ADD_FAILURE() << "a MaterialError of the plugin is the material's, not the plugin's";
  } catch (const MaterialError& error) {
    EXPECT_EQ(std::string(error.what()).rfind("material key \"albedo\"", 0), 0u);
  }
}

}  // namespace plugin_model_test
}  // namespace scatterlab
