// The `scatterlab` executable end to end: exit codes, what goes to stdout and stderr, and that
// bad input leaves no output behind.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "cli_runner.h"

namespace scatterlab {
namespace cli_test {

using nlohmann::json;
namespace fs = std::filesystem;
using namespace cli_runner;

// A check that takes well under a second: few samples, a coarse grid, two angles.
const std::vector<std::string> QuickCheck{"--samples", "20000", "--grid", "16x32", "--wi-theta", "0,60"};

// ---- Help, version, models ---------------------------------------------------------------

TEST(Cli, HelpOfEveryCommandExitsZero) {
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"--help"}, {"models", "--help"}, {"check", "--help"}}) {
    const ProcessResult run = runScatterlab(args);
    EXPECT_EQ(run.exitCode, 0) << describe(run);
    EXPECT_NE(run.out.find("Usage"), std::string::npos) << describe(run);
    EXPECT_TRUE(run.err.empty()) << describe(run);
  }
  const ProcessResult check = runScatterlab({"check", "--help"});
  for (const char* option : {"--wi-theta", "--wi-phi", "--samples", "--grid", "--seed", "--alpha", "--images",
                             "--negative-controls", "--render-agreement", "--json"})
    EXPECT_NE(check.out.find(option), std::string::npos) << option << " missing from check --help";
}

TEST(Cli, Version) {
  const ProcessResult run = runScatterlab({"--version"});
  EXPECT_EQ(run.exitCode, 0) << describe(run);
  EXPECT_EQ(run.out.rfind("scatterlab ", 0), 0u) << describe(run);
}

TEST(Cli, NoSubcommandIsBadInput) {
  const ProcessResult run = runScatterlab({});
  EXPECT_EQ(run.exitCode, 2) << describe(run);
  EXPECT_FALSE(run.err.empty());
}

TEST(Cli, ModelsListsEveryTypeWithRangesAndDefaults) {
  const ProcessResult run = runScatterlab({"models"});
  ASSERT_EQ(run.exitCode, 0) << describe(run);
  for (const char* text : {"lambertian", "conductor", "albedo", "alpha", "[0.001, 1]", "\"ggx\"", "Walter",
                           "blend", "materials", "exactly 2 materials"})
    EXPECT_NE(run.out.find(text), std::string::npos) << text << " missing from:\n" << run.out;
}

TEST(Cli, ModelsJsonParses) {
  const ProcessResult run = runScatterlab({"models", "--json"});
  ASSERT_EQ(run.exitCode, 0) << describe(run);
  const json catalog = json::parse(run.out);
  std::set<std::string> types;
  for (const json& model : catalog) types.insert(model.at("type").get<std::string>());
  EXPECT_TRUE(types.contains("lambertian"));
  EXPECT_TRUE(types.contains("conductor"));
}

// The page docs/models.md is: a heading and a parameter table per model of the JSON catalogue
// (tests/CMakeLists.txt's docs.models compares it with the committed page).
TEST(Cli, ModelsMarkdownHasASectionPerModel) {
  const ProcessResult run = runScatterlab({"models", "--markdown"});
  ASSERT_EQ(run.exitCode, 0) << describe(run);
  EXPECT_EQ(run.out.rfind("# Material models\n", 0), 0u) << run.out.substr(0, 200);
  const json catalog = json::parse(runScatterlab({"models", "--json"}).out);
  for (const json& model : catalog) {
    const std::string heading = "\n## `" + model.at("type").get<std::string>() + "`\n";
    EXPECT_NE(run.out.find(heading), std::string::npos) << heading;
  }
  EXPECT_NE(run.out.find("| `alpha` | pair | a number or [alpha_x, alpha_y], each in [0.001, 1] | `0.1` |"),
            std::string::npos);
  EXPECT_NE(run.out.find("give at most one of `metal`, or `eta` + `k`"), std::string::npos);
}

TEST(Cli, ModelsMarkdownAndJsonExcludeEachOther) {
  const ProcessResult run = runScatterlab({"models", "--markdown", "--json"});
  EXPECT_EQ(run.exitCode, 2) << describe(run);
  EXPECT_TRUE(run.out.empty()) << describe(run);
}

// ---- Bad input: exit 2, one message naming key or option, value and what is allowed,
// ---- and no output directory ---------------------------------------------------------------

struct BadInput {
  const char* what;
  std::vector<std::string> args;
  std::vector<std::string> messageContains;
};

void PrintTo(const BadInput& bad, std::ostream* os) { *os << bad.what; }

class CliBadInputTest : public ::testing::TestWithParam<BadInput> {};

TEST_P(CliBadInputTest, ExitsTwoWithOneMessageAndWritesNothing) {
  const BadInput& bad = GetParam();
  const fs::path images = uniquePath("images");
  const ProcessResult run = runScatterlab(bad.args + std::vector<std::string>{"--images", images.string()});
  EXPECT_EQ(run.exitCode, 2) << describe(run);
  EXPECT_TRUE(run.out.empty()) << describe(run);
  EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << "one line:\n" << run.err;
  for (const std::string& fragment : bad.messageContains)
    EXPECT_NE(run.err.find(fragment), std::string::npos) << "\"" << fragment << "\" missing from:\n"
                                                         << run.err;
  EXPECT_FALSE(fs::exists(images)) << "--images directory created on bad input";
}

INSTANTIATE_TEST_SUITE_P(
    Cli, CliBadInputTest,
    ::testing::Values(
        BadInput{"negative_roughness",
                 {"check", R"({"type":"conductor","alpha":-0.1})"},
                 {"\"alpha\"", "-0.1", "[0.001, 1]"}},
        BadInput{"nan_roughness",
                 {"check", R"({"type":"conductor","alpha":NaN})"},
                 {"\"alpha\"", "NaN", "inline JSON", "line 1"}},
        BadInput{
            "malformed_json", {"check", R"({"type":"conductor",)"}, {"inline JSON", "line 1, column 21"}},
        BadInput{"unknown_model",
                 {"check", R"({"type":"plastic"})"},
                 {"\"type\"", "\"plastic\"", "\"lambertian\"", "\"conductor\""}},
        BadInput{"unknown_key",
                 {"check", R"({"type":"lambertian","colour":0.5})"},
                 {"\"colour\"", "0.5", "\"albedo\""}},
        BadInput{"wrong_type",
                 {"check", R"({"type":"conductor","alpha":"rough"})"},
                 {"\"alpha\"", "\"rough\"", "wrong type"}},
        BadInput{"eta_not_positive",
                 {"check", R"({"type":"conductor","eta":[0,1,1],"k":1})"},
                 {"\"eta\"", "[0,1,1]", "> 0"}},
        BadInput{"metal_and_eta",
                 {"check", R"({"type":"conductor","metal":"Au","eta":1,"k":1})"},
                 {"\"metal\"", "\"eta\""}},
        BadInput{"second_material_bad",
                 {"check", R"({"type":"lambertian"})", R"({"type":"lambertian","albedo":2})"},
                 {"\"albedo\"", "2", "[0, 1]"}},
        BadInput{"nested_material_bad",
                 {"check",
                  R"({"type":"blend","materials":[{"type":"lambertian"},{"type":"conductor","alpha":2}]})"},
                 {"material key \"materials[1].alpha\"", "2", "[0.001, 1]"}},
        BadInput{"missing_file", {"check", "no-such-material.json"}, {"no-such-material.json", "not found"}},
        BadInput{"grid_without_x", {"check", "--grid", "64"}, {"--grid", "\"64\"", "COSxPHI"}},
        BadInput{"grid_too_small", {"check", "--grid", "1x128"}, {"--grid", "\"1x128\"", "[2, 4096]"}},
        BadInput{"incident_angle_90", {"check", "--wi-theta", "0,90"}, {"--wi-theta", "\"90\"", "[0, 90)"}},
        BadInput{"incident_angle_not_a_number",
                 {"check", "--wi-theta", "0,abc"},
                 {"--wi-theta", "\"abc\"", "[0, 90)"}},
        BadInput{
            "negative_samples", {"check", "--samples", "-5"}, {"--samples", "\"-5\"", "integer in [1000"}},
        BadInput{
            "too_few_samples", {"check", "--samples", "10"}, {"--samples", "\"10\"", "integer in [1000"}},
        BadInput{"significance_zero", {"check", "--alpha", "0"}, {"--alpha", "\"0\"", "(0, 0.5]"}},
        BadInput{"azimuth_nan", {"check", "--wi-phi", "nan"}, {"--wi-phi", "\"nan\"", "finite"}},
        BadInput{"seed_negative", {"check", "--seed", "-1"}, {"--seed", "\"-1\"", "integer >= 0"}},
        BadInput{"unknown_option", {"check", "--colour"}, {"--colour"}}),
    [](const ::testing::TestParamInfo<BadInput>& info) { return std::string(info.param.what); });

TEST(Cli, ImagesPathThatIsAFileIsBadInput) {
  const fs::path file = uniquePath("not-a-directory");
  std::ofstream(file) << "x";
  const ProcessResult run = runScatterlab(
      std::vector<std::string>{"check", R"({"type":"lambertian"})", "--images", file.string()} + QuickCheck);
  EXPECT_EQ(run.exitCode, 2) << describe(run);
  EXPECT_NE(run.err.find("--images"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("not a directory"), std::string::npos) << run.err;
  fs::remove(file);
}

// ---- Checks that run -----------------------------------------------------------------------

TEST(Cli, QuickLambertianCheckPassesWithJson) {
  const ProcessResult run = runScatterlab(std::vector<std::string>{"check", R"({"type":"lambertian"})"} +
                                          QuickCheck + std::vector<std::string>{"--json"});
  ASSERT_EQ(run.exitCode, 0) << describe(run);
  EXPECT_TRUE(run.err.empty()) << "progress must be quiet when stderr is not a terminal:\n" << run.err;
  const json document = json::parse(run.out);
  EXPECT_EQ(document.at("passed"), true);
  EXPECT_EQ(document.at("materials").at(0).at("material"), (json{{"type", "lambertian"}, {"albedo", 0.8}}));
  const json& rows = document.at("report").at("rows");
  ASSERT_FALSE(rows.empty());
  std::set<std::string> tests;
  for (const json& row : rows) {
    EXPECT_EQ(row.at("passed"), true) << row.dump();
    tests.insert(row.at("test").get<std::string>());
  }
  EXPECT_TRUE(tests.contains("chi2"));
  EXPECT_EQ(document.at("options").at("grid"), (json{16, 32}));
}

TEST(Cli, TextOutputShowsTheCompletedMaterialAndTheVerdict) {
  const ProcessResult run =
      runScatterlab(std::vector<std::string>{"check", R"({"type":"lambertian","albedo":0.5})"} + QuickCheck);
  ASSERT_EQ(run.exitCode, 0) << describe(run);
  EXPECT_NE(run.out.find(R"({"albedo":0.5,"type":"lambertian"})"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("PASS"), std::string::npos) << run.out;
  EXPECT_EQ(run.out.find("FAIL"), std::string::npos) << run.out;
}

TEST(Cli, MaterialFileIsAccepted) {
  const fs::path file = uniquePath("copper.json");
  std::ofstream(file) << R"({"type": "conductor", "distribution": "beckmann", "alpha": 0.3, "metal": "Cu"})";
  const ProcessResult run = runScatterlab(std::vector<std::string>{"check", file.string()} + QuickCheck +
                                          std::vector<std::string>{"--json"});
  EXPECT_EQ(run.exitCode, 0) << describe(run);
  const json document = json::parse(run.out);
  EXPECT_EQ(document.at("materials").at(0).at("label"), file.string());
  EXPECT_EQ(document.at("materials").at(0).at("material").at("sampling"), "visible");
  fs::remove(file);
}

TEST(Cli, GrazingIncidenceOnAConductorGivesNoNaN) {
  const ProcessResult run = runScatterlab({"check", R"({"type":"conductor"})", "--samples", "20000", "--grid",
                                           "16x32", "--wi-theta", "89.9", "--json"});
  ASSERT_EQ(run.exitCode, 0) << describe(run);
  const json document = json::parse(run.out);
  for (const json& row : document.at("report").at("rows")) {
    // The kit writes a non-finite statistic as a string; a number here is finite by JSON's rules.
    EXPECT_TRUE(row.at("statistic").is_number()) << row.dump();
    EXPECT_TRUE(row.at("threshold").is_number()) << row.dump();
    EXPECT_TRUE(row.at("p_value").is_null() || row.at("p_value").is_number()) << row.dump();
  }
  EXPECT_EQ(run.out.find("nan"), std::string::npos) << run.out;
}

TEST(Cli, ImagesAreWrittenOnRequest) {
  const fs::path images = uniquePath("images");
  const ProcessResult run = runScatterlab(
      std::vector<std::string>{"check", R"({"type":"lambertian"})", "--images", images.string()} +
      QuickCheck);
  ASSERT_EQ(run.exitCode, 0) << describe(run);
  int pngs = 0;
  for (const auto& entry : fs::directory_iterator(images)) pngs += entry.path().extension() == ".png";
  EXPECT_GT(pngs, 0);
  fs::remove_all(images);
}

}  // namespace cli_test
}  // namespace scatterlab
