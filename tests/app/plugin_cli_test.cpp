// Plugins (materials/registry/plugin.h) through the real executable: a plugin's model gets the
// whole lab (models, check with negative controls, render, lab, fit with its kernel or with
// numeric derivatives), a plugin that misbehaves at run time is reported without a crash, and a
// library the loader must refuse is one message and exit 2. The plugins are built by
// tests/app/plugins/plugins.cmake.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "cli_runner.h"
#include "fit_report.h"
#include "materials/measured/merl_io.h"

namespace scatterlab {
namespace plugin_cli_test {

using nlohmann::json;
namespace fs = std::filesystem;
using namespace cli_runner;

const std::string ExamplePhong = SCATTERLAB_PLUGIN_EXAMPLE_PHONG;
const std::string TestModels = SCATTERLAB_PLUGIN_TEST_PLUGIN_MODELS;
// A check of well under a second: few samples, a coarse grid, two angles.
const std::vector<std::string> QuickCheck{"--samples", "20000", "--grid", "16x32", "--wi-theta", "0,60"};
// With the negative controls: a pdf 5% high on half the sphere moves the chi-square by about
// N x 0.05^2 / 4, so 2e4 samples (a shift of ~12 on 63 dof) cannot reject it reliably; 4e5 (~250) can.
const std::vector<std::string> ControlsCheck{"--samples", "400000", "--grid", "16x32", "--wi-theta", "0,60"};

// ---- A plugin's model in every command ---------------------------------------------------

TEST(PluginCli, EveryCommandThatReadsMaterialsTakesPlugin) {
  for (const char* command : {"check", "render", "lab", "models", "fit", "synth"}) {
    const ProcessResult run = runScatterlab({command, "--help"});
    EXPECT_EQ(run.exitCode, 0) << describe(run);
    expectMentions(run.out, {"--plugin", "SCATTERLAB_PLUGIN_PATH"});
  }
}

TEST(PluginCli, ModelsListsThePluginsModelWithItsSpecAndLibrary) {
  const ProcessResult run = runScatterlab({"models", "--plugin", ExamplePhong});
  ASSERT_EQ(run.exitCode, 0) << describe(run);
  expectMentions(run.out, {"example-phong: Example plugin", "exponent", "in [0, 10000]", "ks", "plugin: "});
  const ProcessResult asJson = runScatterlab({"models", "--json", "--plugin", ExamplePhong});
  ASSERT_EQ(asJson.exitCode, 0) << describe(asJson);
  const json catalog = json::parse(asJson.out);
  const json& last = catalog.back();
  EXPECT_EQ(last.at("type"), "example-phong");
  EXPECT_EQ(fs::path(last.at("plugin").get<std::string>()), fs::canonical(ExamplePhong));
  EXPECT_EQ(last.at("parameters").at(0).at("default"), 30.0);
}

TEST(PluginCli, PluginPathVariableLoadsPluginsAtStart) {
  const ProcessResult run =
      runScatterlab({"models", "--json"},
                    std::vector<std::string>{"SCATTERLAB_PLUGIN_PATH=" + ExamplePhong + ":" + TestModels});
  ASSERT_EQ(run.exitCode, 0) << describe(run);
  std::vector<std::string> types;
  for (const json& model : json::parse(run.out)) types.push_back(model.at("type"));
  for (const char* type : {"example-phong", "numeric-phong", "throwing-lobe", "nan-lobe"})
    EXPECT_NE(std::find(types.begin(), types.end(), type), types.end()) << type;
  // The same library again on the command line is not a duplicate: it is loaded once.
  const ProcessResult again =
      runScatterlab({"models", "--plugin", ExamplePhong},
                    std::vector<std::string>{"SCATTERLAB_PLUGIN_PATH=" + ExamplePhong});
  EXPECT_EQ(again.exitCode, 0) << describe(again);
}

TEST(PluginCli, PluginPathVariableTakesADirectory) {
  const fs::path directory = uniquePath("plugin-dir");
  fs::create_directories(directory);
  fs::copy_file(ExamplePhong, directory / "libexample_phong.so");
  const ProcessResult run =
      runScatterlab({"models"}, std::vector<std::string>{"SCATTERLAB_PLUGIN_PATH=" + directory.string()});
  EXPECT_EQ(run.exitCode, 0) << describe(run);
  expectMentions(run.out, {"example-phong"});
  fs::remove_all(directory);
}

TEST(PluginCli, CheckPassesThePluginsModelWithNegativeControls) {
  const ProcessResult run = runScatterlab(std::vector<std::string>{"check", "--plugin", ExamplePhong,
                                                                   R"({"type": "example-phong"})",
                                                                   "--negative-controls", "--json"} +
                                          ControlsCheck);
  ASSERT_EQ(run.exitCode, 0) << describe(run);
  const json report = json::parse(run.out);
  EXPECT_TRUE(report.at("passed").get<bool>());
  EXPECT_EQ(report.at("materials").at(0).at("material"),
            json::parse(R"({"type": "example-phong", "exponent": 30.0, "ks": 0.8})"));
  // The roughness-mismatch control applies: the spec names the lobe-width parameter.
  int mismatchRows = 0;
  for (const json& row : report.at("report").at("rows"))
    if (row.at("test") == "control: sampler lobe width 10% off") {
      ++mismatchRows;
      EXPECT_EQ(row.at("note").get<std::string>().rfind("not applicable", 0), std::string::npos) << row;
    }
  EXPECT_EQ(mismatchRows, 2) << run.out;  // one per incident angle
}

TEST(PluginCli, PluginSpecValidatesMaterialsLikeABuiltInOne) {
  expectBadInput({"check", "--plugin", ExamplePhong, R"({"type": "example-phong", "exponent": -1})"},
                 {"\"exponent\"", "-1", "out of range", "in [0, 10000]"});
  expectBadInput({"check", "--plugin", ExamplePhong, R"({"type": "example-phong", "roughness": 1})"},
                 {"\"roughness\"", "not a key of model \"example-phong\"", "\"exponent\"", "\"ks\""});
}

TEST(PluginCli, RenderDrawsThePluginsModel) {
  const fs::path out = uniquePath("plugin-render");
  const ProcessResult run = runScatterlab({"render", "--plugin", ExamplePhong, R"({"type": "example-phong"})",
                                           "--res", "24x16", "--spp", "4", "--out", out.string(), "--json"});
  ASSERT_EQ(run.exitCode, 0) << describe(run);
  const json report = json::parse(run.out);
  EXPECT_EQ(report.at("renders").at(0).at("non_finite_samples"), 0);
  EXPECT_TRUE(fs::exists(out.string() + ".exr"));
  EXPECT_TRUE(fs::exists(out.string() + ".png"));
  fs::remove(out.string() + ".exr");
  fs::remove(out.string() + ".png");
}

TEST(PluginCli, LabWritesAReportOnThePluginsModel) {
  const fs::path out = uniquePath("plugin-lab");
  const ProcessResult run = runScatterlab(
      {"lab", "--plugin", ExamplePhong, R"({"type": "example-phong"})", "--quick", "--out", out.string()});
  ASSERT_EQ(run.exitCode, 0) << describe(run);
  expectMentions(run.out, {"verdict: PASS"});
  const std::string index = readFile(out / "index.html");
  expectMentions(index, {"example-phong"});
  fs::remove_all(out);
}

// `synth` evaluates the plugin's model on the MERL grid. The built-in "phong" with kd = 0 is the
// same formula written independently (materials/bsdf/phong.h), so the two tables agree cell by
// cell up to rounding: a few ulp of cos alpha, raised to the power 30, stays below 1e-12 relative.
TEST(PluginCli, SynthTabulatesThePluginsModelAsTheBuiltInPhongWithoutDiffuse) {
  const fs::path plugin = uniquePath("plugin-phong") += ".binary";
  const fs::path builtIn = uniquePath("builtin-phong") += ".binary";
  const ProcessResult run = runScatterlab(
      {"synth", "--plugin", ExamplePhong, R"({"type": "example-phong"})", "--out", plugin.string()});
  ASSERT_EQ(run.exitCode, 0) << describe(run);
  ASSERT_EQ(runScatterlab({"synth", R"({"type": "phong", "kd": 0, "ks": 0.8, "exponent": 30})", "--out",
                           builtIn.string()})
                .exitCode,
            0);
  const MerlTable fromPlugin = readMerl(plugin), reference = readMerl(builtIn);
  double largest = 0;
  size_t disagreeing = 0;
  for (size_t cell = 0; cell < merl::CellCount; ++cell)
    for (int channel = 0; channel < 3; ++channel) {
      const double expected = reference.value(channel, cell);
      largest = std::max(largest, expected);
      if (std::abs(fromPlugin.value(channel, cell) - expected) > 1e-12 * std::max(1.0, expected))
        ++disagreeing;
    }
  EXPECT_EQ(disagreeing, 0u);
  EXPECT_GT(largest, 1.0);  // the lobe's peak, 0.8 * 32 / (2 pi) ~ 4 /sr, is in the table
  fs::remove(plugin);
  fs::remove(builtIn);
}

// Noise-free data tabulated from the model itself: the optimum is the truth, and the solver's
// tolerances (function and parameter 1e-10, brdf_fit.h) leave it at ~1e-6 relative; 1e-4 leaves
// room for the numeric derivatives' error in the path taken, not in the optimum.
constexpr double RecoveryTolerance = 1e-4;

TEST(PluginCli, FitRecoversThePluginsParametersWithItsKernel) {
  const ProcessResult run = runScatterlab(
      {"fit", "--plugin", ExamplePhong, R"({"type": "example-phong", "exponent": 80, "ks": [0.7, 0.5, 0.3]})",
       "--model", "example-phong", "--metric", "l2", "--samples", "20000", "--json"});
  ASSERT_EQ(run.exitCode, 0) << describe(run);
  const json report = json::parse(run.out);
  EXPECT_TRUE(report.at("derivative_notes").empty());
  EXPECT_NEAR(fittedParameter(report, "example-phong.exponent") / 80.0, 1.0, RecoveryTolerance);
  EXPECT_NEAR(fittedParameter(report, "example-phong.ks.b"), 0.3, RecoveryTolerance);
  EXPECT_EQ(report.at("material").at("type"), "example-phong");
}

TEST(PluginCli, FitWithoutAKernelDifferentiatesNumericallyAndSaysSo) {
  const ProcessResult run = runScatterlab(
      {"fit", "--plugin", TestModels, R"({"type": "numeric-phong", "exponent": 80, "ks": [0.7, 0.5, 0.3]})",
       "--model", "numeric-phong", "--metric", "l2", "--samples", "20000", "--json"});
  ASSERT_EQ(run.exitCode, 0) << describe(run);
  expectMentions(run.err, {"note", "numeric derivatives", "registers no fit kernel"});
  const json report = json::parse(run.out);
  EXPECT_EQ(report.at("derivative_notes").size(), 1u);
  EXPECT_NEAR(fittedParameter(report, "numeric-phong.exponent") / 80.0, 1.0, RecoveryTolerance);
  EXPECT_NEAR(fittedParameter(report, "numeric-phong.ks.r"), 0.7, RecoveryTolerance);
}

// ---- A plugin that misbehaves at run time ------------------------------------------------

TEST(PluginCli, APluginThatThrowsIsReportedAsItsError) {
  expectBadInput(
      std::vector<std::string>{"check", "--plugin", TestModels, R"({"type": "throwing-lobe"})"} + QuickCheck,
      {"plugin model \"throwing-lobe\"", fs::canonical(TestModels).string(), "(wi = (",
       "threw: deliberate failure of the test plugin"});
}

TEST(PluginCli, APluginThatReturnsNaNFailsTheCheckAndIsCountedByTheRenderer) {
  const ProcessResult check = runScatterlab(
      std::vector<std::string>{"check", "--plugin", TestModels, R"({"type": "nan-lobe"})"} + QuickCheck);
  EXPECT_EQ(check.exitCode, 1) << describe(check);
  expectMentions(check.out, {"FAIL", "verdict: FAIL"});

  const fs::path out = uniquePath("plugin-nan-render");
  const ProcessResult render = runScatterlab({"render", "--plugin", TestModels, R"({"type": "nan-lobe"})",
                                              "--res", "16x16", "--spp", "2", "--out", out.string()});
  // The film drops the NaN samples, counts them, and the render fails (render.h).
  EXPECT_EQ(render.exitCode, 1) << describe(render);
  expectMentions(render.out, {"samples dropped"});
  fs::remove(out.string() + ".exr");
  fs::remove(out.string() + ".png");
}

// ---- Libraries the loader refuses: one message, exit 2 -------------------------------------

TEST(PluginCli, MissingLibraryIsBadInput) {
  expectBadInput({"models", "--plugin", "/nonexistent/libnothing.so"},
                 {"--plugin \"/nonexistent/libnothing.so\"", "no such file", "allowed"});
}

TEST(PluginCli, AFileThatIsNotASharedLibraryIsBadInput) {
  const fs::path text = uniquePath("not-a-library") += ".so";
  std::ofstream(text) << "not a shared library\n";
  expectBadInput({"models", "--plugin", text.string()}, {text.string(), "cannot be loaded", "allowed"});
  fs::remove(text);
}

TEST(PluginCli, ASharedLibraryThatIsNotAPluginIsBadInput) {
  expectBadInput({"models", "--plugin", SCATTERLAB_PLUGIN_BAD_PLUGIN_NOT_A_PLUGIN},
                 {"is not a scatterlab plugin", "scatterlab_plugin_abi", "SCATTERLAB_PLUGIN"});
}

TEST(PluginCli, APluginWithoutItsRegistrationEntryPointIsBadInput) {
  expectBadInput({"models", "--plugin", SCATTERLAB_PLUGIN_BAD_PLUGIN_NO_REGISTER},
                 {"is not a scatterlab plugin", "no scatterlab_plugin_register symbol", "SCATTERLAB_PLUGIN"});
}

TEST(PluginCli, APluginBuiltAgainstAnotherScatterlabIsRefused) {
  expectBadInput({"models", "--plugin", SCATTERLAB_PLUGIN_BAD_PLUGIN_WRONG_ABI},
                 {"was built for \"scatterlab plugin interface 0, scatterlab 0.0.0\"", "this scatterlab is",
                  "rebuilt against this installation"});
}

TEST(PluginCli, APluginModelWithATypeThatExistsIsRefused) {
  expectBadInput({"models", "--plugin", SCATTERLAB_PLUGIN_BAD_PLUGIN_DUPLICATE},
                 {"model type \"phong\" already exists (built in)", "a type no other model has"});
  // The same type from two plugins: the second names the first.
  const fs::path copy = uniquePath("example-phong-copy") += ".so";
  fs::copy_file(ExamplePhong, copy);
  expectBadInput({"models", "--plugin", ExamplePhong, "--plugin", copy.string()},
                 {"\"example-phong\" already exists (from plugin " + fs::canonical(ExamplePhong).string()});
  fs::remove(copy);
}

TEST(PluginCli, APluginSpecWithoutADefaultIsRefused) {
  expectBadInput({"models", "--plugin", SCATTERLAB_PLUGIN_BAD_PLUGIN_NO_DEFAULT},
                 {"model \"no-default-lobe\"", "parameter \"albedo\" has no default",
                  "{\"type\": \"no-default-lobe\"} is a complete material"});
}

TEST(PluginCli, APluginWhoseRegistrationThrowsIsBadInput) {
  expectBadInput({"models", "--plugin", SCATTERLAB_PLUGIN_BAD_PLUGIN_THROWS},
                 {"its registration threw: deliberate failure while registering"});
}

TEST(PluginCli, ABadLibraryInThePluginPathVariableIsBadInput) {
  const ProcessResult run = runScatterlab(
      {"models"}, std::vector<std::string>{"SCATTERLAB_PLUGIN_PATH=/nonexistent/libnothing.so"});
  EXPECT_EQ(run.exitCode, 2) << describe(run);
  expectMentions(run.err, {"SCATTERLAB_PLUGIN_PATH \"/nonexistent/libnothing.so\"", "no such file"});
}

}  // namespace plugin_cli_test
}  // namespace scatterlab
