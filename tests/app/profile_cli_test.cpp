// `scatterlab profile`, and subsurface materials in `scatterlab check` and `scatterlab models`,
// end to end: exit codes, output, and messages for bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <set>

#include <nlohmann/json.hpp>

#include "cli_runner.h"
#include "tests/test_names.h"

namespace scatterlab {
namespace profile_cli_test {

using nlohmann::json;
using namespace cli_runner;

TEST(ProfileCli, HelpListsEveryOption) {
  const ProcessResult run = runScatterlab({"profile", "--help"});
  ASSERT_EQ(run.exitCode, 0) << describe(run);
  for (const char* option : {"--reference", "--albedo", "--eta", "--g", "--paths", "--min-radius",
                             "--max-radius", "--bins", "--seed", "--threads", "--compare", "--json"})
    EXPECT_NE(run.out.find(option), std::string::npos) << option;
}

TEST(ProfileCli, PrintsTheProfileAndJensensReflectance) {
  const ProcessResult run =
      runScatterlab({"profile", R"({"type": "subsurface", "profile": "dipole"})", "--json"});
  ASSERT_EQ(run.exitCode, 0) << describe(run);
  const json out = json::parse(run.out);
  EXPECT_EQ(out["profile_model"], "dipole");
  EXPECT_EQ(out["radius_edges"].size(), 25u);  // 0 and 24 log-spaced edges
  const double expected[3] = {0.436, 0.227, 0.131};
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(out["channels"][size_t(c)]["total_reflectance"].get<double>(), expected[c], 5e-4);
    EXPECT_EQ(out["channels"][size_t(c)]["profile"].size(), 24u);
  }
  EXPECT_TRUE(run.err.empty()) << run.err;  // no progress when stderr is not a terminal
}

TEST(ProfileCli, WalkReferenceAgreesWithTheHFunctionWhenIndexMatched) {
  const ProcessResult run =
      runScatterlab({"profile", R"({"type": "subsurface"})", "--reference", "walk", "--albedo", "0.8",
                     "--eta", "1", "--g", "0", "--paths", "40000", "--bins", "6", "--json"});
  ASSERT_EQ(run.exitCode, 0) << describe(run);
  const json out = json::parse(run.out);
  for (const json& channel : out["channels"]) {
    const json& walk = channel["walk"];
    ASSERT_TRUE(walk.contains("exact_total_reflectance")) << walk.dump();
    // 4 standard errors: three channels per run, each its own seed.
    EXPECT_NEAR(walk["total_reflectance"].get<double>(), walk["exact_total_reflectance"].get<double>(),
                4 * walk["std_error"].get<double>());
    EXPECT_EQ(walk["profile"].size(), 6u);
  }
}

TEST(ProfileCli, TextOutputNamesTheColumns) {
  const ProcessResult run =
      runScatterlab({"profile", SCATTERLAB_DATA_DIR "/materials/subsurface-skin-burley.json", "--reference",
                     "walk", "--paths", "2000", "--bins", "3"});
  ASSERT_EQ(run.exitCode, 0) << describe(run);
  for (const char* text : {"total diffuse reflectance", "random walk", "R_r profile", "R_b walk", "+- se"})
    EXPECT_NE(run.out.find(text), std::string::npos) << text << " missing from:\n" << run.out;
}

TEST(ProfileCli, CompareTablesEveryModelAgainstTheWalk) {
  const ProcessResult run = runScatterlab({"profile", R"({"type": "subsurface", "medium": "Skin1"})",
                                           "--reference", "walk", "--compare", "--paths", "20000", "--json"});
  ASSERT_EQ(run.exitCode, 0) << describe(run);
  const json out = json::parse(run.out);
  std::set<std::string> models;
  for (const json& m : out["models"]) {
    models.insert(m["model"].get<std::string>());
    for (const char* key : {"total_reflectance", "total_error", "profile_error", "multiple_total_error",
                            "multiple_profile_error"})
      EXPECT_EQ(m[key].size(), 3u) << key;
    for (const json& e : m["profile_error"]) EXPECT_GE(e.get<double>(), 0.0);
  }
  EXPECT_EQ(models, (std::set<std::string>{"dipole", "better-dipole", "beam-diffusion", "burley"}));
  const json& walk = out["walk"];
  EXPECT_EQ(walk["channels"].size(), 3u);
  for (int c = 0; c < 3; ++c)  // all orders = single + multiple scattering
    EXPECT_NEAR(walk["total"][size_t(c)].get<double>(),
                walk["channels"][size_t(c)]["single_scattering"].get<double>() +
                    walk["multiple_total"][size_t(c)].get<double>(),
                1e-12);
  EXPECT_EQ(out["radius_edges"].size(), 25u);
  // The dipole's total is Jensen's closed form; its error is relative to the walk's total.
  const json& dipole = out["models"][0];
  EXPECT_EQ(dipole["model"], "dipole");
  EXPECT_NEAR(dipole["total_error"][0].get<double>(),
              dipole["total_reflectance"][0].get<double>() / walk["total"][0].get<double>() - 1.0, 1e-12);
  const ProcessResult text = runScatterlab({"profile", R"({"type": "subsurface", "medium": "Skin1"})",
                                            "--reference", "walk", "--compare", "--paths", "5000"});
  ASSERT_EQ(text.exitCode, 0) << describe(text);
  for (const char* fragment : {"multiple only", "single scattering", "noise floor", "beam-diffusion", "R(r)"})
    EXPECT_NE(text.out.find(fragment), std::string::npos) << fragment << " missing from:\n" << text.out;
}

// The published property of the shape fit (docs/validation.md section 6): Burley's curve
// cannot follow the walk's diffusive tail, so the power it carries, P, is below the walk's
// total A. At A = 0.8 and 0.95 the tail holds 5% and 12% of A (0.04 and 0.11), and 30000 paths
// give P a standard error near 0.002: P < A - 5 standard errors (the fit's own estimate) holds
// with room, and a noise excursion of 5 sigma (probability 3e-7) is all that could cross it.
TEST(ShapeFactorCli, FitsAndComparesWithThePublishedFit) {
  const ProcessResult run = runScatterlab(
      {"shape-factor", "--albedos", "0.8,0.95", "--paths", "30000", "--threads", "1", "--json"});
  ASSERT_EQ(run.exitCode, 0) << describe(run);
  const json out = json::parse(run.out);
  ASSERT_EQ(out["rows"].size(), 2u);
  EXPECT_EQ(out["non_finite_paths"], 0);
  for (const json& row : out["rows"]) {
    const double a = row["albedo"].get<double>();
    SCOPED_TRACE(a);
    EXPECT_NEAR(row["published_shape_factor"].get<double>(), 1.85 - a + 7 * std::pow(std::abs(a - 0.8), 3),
                1e-12);
    const double power = row["power"].get<double>(), powerError = row["power_std_error"].get<double>();
    EXPECT_GT(powerError, 0.0);
    EXPECT_LT(power, a - 5.0 * powerError) << "P " << power << " +- " << powerError;
    EXPECT_GT(row["shape_factor"].get<double>(), 0.0);
    EXPECT_GT(row["normalised_shape_factor"].get<double>(), 0.0);
    EXPECT_EQ(row["termination"], "CONVERGENCE");
    EXPECT_EQ(row["normalised_termination"], "CONVERGENCE");
  }
  EXPECT_NE(out["metric"].get<std::string>().find("r R(r)"), std::string::npos);
  // The same seed gives the same table for any thread count.
  const ProcessResult two = runScatterlab(
      {"shape-factor", "--albedos", "0.8,0.95", "--paths", "30000", "--threads", "2", "--json"});
  EXPECT_EQ(json::parse(two.out)["rows"], out["rows"]);
  const ProcessResult text = runScatterlab({"shape-factor", "--albedos", "0.5", "--paths", "5000"});
  ASSERT_EQ(text.exitCode, 0) << describe(text);
  for (const char* fragment :
       {"shape s", "normalised s", "power P", "published s", "least squares of r R(r)", "mean |difference|"})
    EXPECT_NE(text.out.find(fragment), std::string::npos) << fragment << " missing from:\n" << text.out;
}

TEST(ShapeFactorCli, BadInputExitsTwo) {
  for (const std::vector<std::string>& args : {std::vector<std::string>{"shape-factor", "--albedos", "1"},
                                               {"shape-factor", "--albedos", "0.5,abc"},
                                               {"shape-factor", "--paths", "10"},
                                               {"shape-factor", "--annulus-width", "0"}}) {
    const ProcessResult run = runScatterlab(args);
    EXPECT_EQ(run.exitCode, 2) << describe(run);
    EXPECT_TRUE(run.out.empty()) << run.out;
    EXPECT_NE(run.err.find(args[1]), std::string::npos) << run.err;
  }
}

struct BadProfileRun {
  const char* what;
  std::vector<std::string> args;
  std::vector<std::string> messageContains;
};
void PrintTo(const BadProfileRun& b, std::ostream* os) { *os << b.what; }

class BadProfileInput : public ::testing::TestWithParam<BadProfileRun> {};

TEST_P(BadProfileInput, ExitsTwoWithAMessage) {
  std::vector<std::string> args{"profile"};
  args.insert(args.end(), GetParam().args.begin(), GetParam().args.end());
  const ProcessResult run = runScatterlab(args);
  EXPECT_EQ(run.exitCode, 2) << describe(run);
  EXPECT_TRUE(run.out.empty()) << run.out;
  for (const std::string& fragment : GetParam().messageContains)
    EXPECT_NE(run.err.find(fragment), std::string::npos)
        << "\"" << fragment << "\" missing from: " << run.err;
}

INSTANTIATE_TEST_SUITE_P(
    ProfileCli, BadProfileInput,
    ::testing::Values(
        BadProfileRun{"negative coefficients",
                      {R"({"type": "subsurface", "sigma_s": [1, -2, 1], "sigma_a": 0.1})"},
                      {"\"sigma_s\"", "g = -2", ">= 0"}},
        BadProfileRun{"reflectance outside [0, 1]",
                      {R"({"type": "subsurface", "reflectance": 1.5, "mfp": 1})"},
                      {"\"reflectance\"", "1.5", "[0, 1]"}},
        BadProfileRun{"walk albedo outside [0, 1]",
                      {R"({"type": "subsurface"})", "--reference", "walk", "--albedo", "1.5"},
                      {"--albedo", "1.5", "[0, 1]"}},
        BadProfileRun{"eta zero", {R"({"type": "subsurface", "eta": 0})"}, {"\"eta\"", "(0, 4]"}},
        BadProfileRun{"walk eta negative",
                      {R"({"type": "subsurface"})", "--reference", "walk", "--eta", "-1"},
                      {"--eta", "-1"}},
        BadProfileRun{"zero mean free path",
                      {R"({"type": "subsurface", "reflectance": 0.5, "mfp": 0})"},
                      {"\"mfp\"", "> 0"}},
        BadProfileRun{"unknown medium",
                      {R"({"type": "subsurface", "medium": "Jelly"})"},
                      {"\"medium\"", "\"Jelly\"", "\"Skin1\""}},
        BadProfileRun{
            "a BSDF", {R"({"type": "lambertian"})"}, {"\"lambertian\"", "not a subsurface material"}},
        BadProfileRun{"walk options without the walk",
                      {R"({"type": "subsurface"})", "--albedo", "0.5"},
                      {"--albedo", "--reference walk"}},
        BadProfileRun{"two albedos",
                      {R"({"type": "subsurface"})", "--reference", "walk", "--albedo", "0.5,0.6"},
                      {"--albedo", "three"}},
        BadProfileRun{"unknown reference",
                      {R"({"type": "subsurface"})", "--reference", "monte-carlo"},
                      {"--reference"}},
        BadProfileRun{"radii the wrong way round",
                      {R"({"type": "subsurface"})", "--min-radius", "5", "--max-radius", "1"},
                      {"--min-radius", "--max-radius"}},
        BadProfileRun{"compare without the walk",
                      {R"({"type": "subsurface"})", "--compare"},
                      {"--compare", "--reference walk"}},
        BadProfileRun{"compare with the walk's own albedo",
                      {R"({"type": "subsurface"})", "--reference", "walk", "--compare", "--albedo", "0.5"},
                      {"--albedo", "share the material's medium"}},
        BadProfileRun{"compare with a radius grid",
                      {R"({"type": "subsurface"})", "--reference", "walk", "--compare", "--max-radius", "5"},
                      {"--max-radius", "--bins"}},
        BadProfileRun{"missing file", {"no-such-material.json"}, {"no-such-material.json", "not found"}},
        BadProfileRun{"no material", {}, {"material"}}),
    [](const ::testing::TestParamInfo<BadProfileRun>& info) {
      return test_names::readableTestName(info.param.what);
    });

TEST(SubsurfaceCheckCli, ChecksASubsurfaceMaterialWithControls) {
  const ProcessResult run =
      runScatterlab({"check", R"({"type": "subsurface", "profile": "burley", "medium": "Marble"})",
                     "--samples", "20000", "--grid", "16x32", "--negative-controls", "--json"});
  ASSERT_EQ(run.exitCode, 0) << describe(run);
  const json out = json::parse(run.out);
  EXPECT_TRUE(out["passed"].get<bool>());
  std::set<std::string> tests;
  for (const json& row : out["report"]["rows"]) tests.insert(row["test"].get<std::string>());
  for (const char* test :
       {"profile energy (r)", "radius chi2 (g)", "radius consistency (b)", "radius inverse (r)",
        "directional normalisation", "probe chi2 (aligned frame)", "probe chi2 (tilted frame)",
        "control: radial shortcut pdf", "control: wrong channel weights"})
    EXPECT_TRUE(tests.contains(test)) << test;
  EXPECT_EQ(out["materials"][0]["material"]["eta"], 1.5);
}

TEST(SubsurfaceCheckCli, WritesTheChiSquareMapsOfEveryTest) {
  const auto dir = uniquePath("subsurface-images");
  const ProcessResult run = runScatterlab({"check", R"({"type": "subsurface"})", "--samples", "5000",
                                           "--grid", "8x16", "--images", dir.string()});
  ASSERT_EQ(run.exitCode, 0) << describe(run);
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    EXPECT_TRUE(name.find("radius_") != std::string::npos || name.find("probe_") != std::string::npos)
        << name;
    ++files;
  }
  EXPECT_EQ(files, 5 * 4);  // 3 radius + 2 probe tests: observed, expected, residual, tables
  std::filesystem::remove_all(dir);
}

TEST(SubsurfaceCheckCli, BadSubsurfaceMaterialExitsTwo) {
  const ProcessResult run =
      runScatterlab({"check", R"({"type": "subsurface", "sigma_s": 1, "sigma_a": -1})"});
  EXPECT_EQ(run.exitCode, 2) << describe(run);
  EXPECT_NE(run.err.find("\"sigma_a\""), std::string::npos) << run.err;
}

TEST(SubsurfaceModelsCli, ListsTheSubsurfaceModelAndItsMedia) {
  const ProcessResult run = runScatterlab({"models"});
  ASSERT_EQ(run.exitCode, 0) << describe(run);
  for (const char* text : {"subsurface", "beam-diffusion", "better-dipole", "\"Skin1\"", "\"Wholemilk\"",
                           "burley_fit", "reflectance", "mfp", "roughness"})
    EXPECT_NE(run.out.find(text), std::string::npos) << text;
  const json catalog = json::parse(runScatterlab({"models", "--json"}).out);
  bool found = false;
  for (const json& model : catalog)
    if (model["type"] == "subsurface") found = model["kind"] == "subsurface";
  EXPECT_TRUE(found);
}

}  // namespace profile_cli_test
}  // namespace scatterlab
