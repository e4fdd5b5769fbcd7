// `scatterlab lab` end to end: a failing material still gets its report (exit 1), a report
// replaces the previous one whole, and bad input leaves the output directory as it was.
// The browser test (tests/report) looks at a whole report in Chromium.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "app/lab/html.h"
#include "cli_runner.h"
#include "integrator/material_scene.h"
#include "materials/registry/parameter_spec.h"

namespace scatterlab {
namespace lab_cli_test {

namespace fs = std::filesystem;
using nlohmann::json;
using namespace cli_runner;

// Disney's BRDF is not energy-conserving: a white, rough base reflects more than it receives
// at grazing incidence (README), so the kit's albedo row fails at 80 degrees.
constexpr const char* WhiteRoughDisney = R"({"type": "disney", "baseColor": [1, 1, 1], "roughness": 1})";

TEST(LabCli, HelpListsEveryOption) {
  const ProcessResult run = runScatterlab({"lab", "--help"});
  ASSERT_EQ(run.exitCode, 0) << describe(run);
  expectMentions(run.out, {"--out", "--quick", "--seed", "--env", "--json", "showcase"});
}

TEST(LabCli, AFailingMaterialGetsAReportThatShowsTheFailure) {
  const fs::path out = uniquePath("lab-failing");
  const ProcessResult run =
      runScatterlab({"lab", WhiteRoughDisney, "--quick", "--out", out.string(), "--json"});
  ASSERT_EQ(run.exitCode, 1) << describe(run);
  const json summary = json::parse(run.out);
  EXPECT_FALSE(summary["passed"].get<bool>());
  EXPECT_EQ(summary["report"], (out / "index.html").string());
  const json report = json::parse(readFile(out / "report.json"));
  EXPECT_EQ(report["generator"], "scatterlab lab");
  ASSERT_EQ(report["materials"].size(), 1u);
  EXPECT_FALSE(report["materials"][0]["passed"].get<bool>());
  const json data = json::parse(readFile(out / report["materials"][0]["data"].get<std::string>()));
  bool albedoFailed = false;
  for (const json& row : data["sections"]["check"]["data"]["report"]["rows"])
    albedoFailed = albedoFailed || (row["test"] == "albedo" && !row["passed"].get<bool>());
  EXPECT_TRUE(albedoFailed) << data["sections"]["check"].dump();
  const std::string page = readFile(out / "index.html");
  expectMentions(page, {"class=\"badge fail\"", "What failed", "class=\"material failed\""});
  // The chi-square maps of a failing material are open for the reader.
  expectMentions(page, {"<details open=\"open\"><summary>Chi-square maps"});
  EXPECT_TRUE(fs::exists(out / "assets" / "chart.umd.min.js"));
  EXPECT_TRUE(fs::exists(out / "assets" / "chart.js-LICENSE.md"));
}

TEST(LabCli, ASecondReportReplacesTheFirstWhole) {
  const fs::path out = uniquePath("lab-replace");
  const std::vector<std::string> lambertian{"lab", R"({"type": "lambertian"})", "--quick", "--out",
                                            out.string()};
  ASSERT_EQ(runScatterlab(lambertian).exitCode, 0);
  const json manifest = json::parse(readFile(out / "manifest.json"));
  EXPECT_EQ(manifest["generator"], "scatterlab lab");
  EXPECT_NE(std::find(manifest["files"].begin(), manifest["files"].end(), "lambertian/data.json"),
            manifest["files"].end());
  // A file the report did not write (not in its manifest) is never deleted with it.
  std::ofstream(out / "notes.txt") << "mine";
  expectBadInput(lambertian, {"--out", "cannot replace", "notes.txt"});
  EXPECT_EQ(readFile(out / "notes.txt"), "mine");
  fs::remove(out / "notes.txt");
  const ProcessResult run = runScatterlab(lambertian + std::vector<std::string>{"--seed", "2"});
  ASSERT_EQ(run.exitCode, 0) << describe(run);
  expectMentions(run.out, {"PASS  lambertian", "report: " + (out / "index.html").string()});
  EXPECT_TRUE(fs::exists(out / "lambertian" / "data.json"));
  EXPECT_NE(readFile(out / "report.json").find("--seed 2"), std::string::npos);
  // Progress is for terminals; the phase timings always go to stderr.
  expectMentions(run.err, {"lab: check", "lab: plots", "open " + (out / "index.html").string()});
}

TEST(LabCli, BadInputLeavesTheOutputDirectoryAlone) {
  const fs::path out = uniquePath("lab-bad");
  expectBadInput({"lab", R"({"type": "conductor", "alpha": 7})", "--out", out.string()}, {"alpha", "7"});
  EXPECT_FALSE(fs::exists(out));
  expectBadInput({"lab", (out / "missing.json").string(), "--out", out.string()}, {"missing.json"});
  expectBadInput({"lab", (out / "missing.binary").string(), "--out", out.string()}, {"missing.binary"});
  EXPECT_FALSE(fs::exists(out));
  // Unreadable contents: a truncated MERL table, a JSON file that does not parse.
  const fs::path inputs = uniquePath("lab-bad-inputs");
  fs::create_directories(inputs);
  std::ofstream(inputs / "short.binary") << "garbage";
  std::ofstream(inputs / "broken.json") << "{not json";
  expectBadInput({"lab", (inputs / "short.binary").string(), "--out", out.string()},
                 {"short.binary", "truncated"});
  expectBadInput({"lab", (inputs / "broken.json").string(), "--out", out.string()},
                 {"broken.json", "line 1"});
  EXPECT_FALSE(fs::exists(out));

  fs::create_directories(out);
  std::ofstream(out / "thesis.tex") << "years of work";
  expectBadInput({"lab", R"({"type": "lambertian"})", "--out", out.string()}, {"--out", "cannot replace"});
  EXPECT_EQ(readFile(out / "thesis.tex"), "years of work");

  const fs::path file = out / "thesis.tex";
  expectBadInput({"lab", R"({"type": "lambertian"})", "--out", file.string()}, {"--out", "not a directory"});
}

TEST(LabCli, AnUnreadableEnvironmentMapIsBadInputAndTheLastReportStays) {
  const fs::path out = uniquePath("lab-bad-env");
  const std::vector<std::string> lambertian{"lab", R"({"type": "lambertian"})", "--quick", "--out",
                                            out.string()};
  const fs::path missing = uniquePath("lab-bad-env-missing") / "studio.exr";
  expectBadInput(lambertian + std::vector<std::string>{"--env", missing.string()},
                 {"--env", missing.string()});
  EXPECT_FALSE(fs::exists(out));

  ASSERT_EQ(runScatterlab(lambertian).exitCode, 0);
  const std::string before = readFile(out / "index.html");
  const fs::path notExr = out.string() + "-not.exr";
  std::ofstream(notExr) << "not an OpenEXR file";
  expectBadInput(lambertian + std::vector<std::string>{"--env", notExr.string()}, {"--env", notExr.string()});
  EXPECT_EQ(readFile(out / "index.html"), before);
}

// The report renders what the renderer accepts and shows the renderer's message for what it
// refuses; which of the two a subsurface material is, the integrator says (it renders BSSRDFs
// in diffusion mode; were it to refuse this one, the report must show its message instead).
TEST(LabCli, EveryMaterialGoesToTheRenderer) {
  const json subsurface{{"type", "subsurface"}};  // the default medium: a short random walk
  std::string refusal;
  try {
    makeMaterialScene(ScenePreset::MaterialSphere, subsurface, Environment::constant(Rgb(1.0)), 8, 8);
  } catch (const MaterialError& error) {
    refusal = error.what();
  }
  const fs::path out = uniquePath("lab-renders");
  // One map (a material after --env is a material, not a second map).
  const std::string studio = std::string(SCATTERLAB_DATA_DIR) + "/envmaps/studio.exr";
  const ProcessResult run = runScatterlab({"lab", "--env", studio, R"({"type": "lambertian"})",
                                           subsurface.dump(), "--quick", "--out", out.string()});
  ASSERT_EQ(run.exitCode, 0) << describe(run);
  const json report = json::parse(readFile(out / "report.json"));
  ASSERT_EQ(report["materials"].size(), 2u);
  const auto rendersOf = [&](size_t i) {
    return json::parse(
        readFile(out / report["materials"][i]["data"].get<std::string>()))["sections"]["renders"]["data"];
  };
  const json lambertian = rendersOf(0);
  EXPECT_EQ(lambertian["renders"].size(), 1u);
  EXPECT_EQ(lambertian["environments"][0]["file"], studio);
  EXPECT_TRUE(lambertian["refused"].empty());
  const json other = rendersOf(1);
  const std::string page = readFile(out / "index.html");
  if (refusal.empty()) {
    EXPECT_EQ(other["renders"].size(), 1u);
    EXPECT_TRUE(other["refused"].empty());
  } else {
    EXPECT_TRUE(other["renders"].empty());
    ASSERT_EQ(other["refused"].size(), 1u);
    EXPECT_EQ(other["refused"][0]["message"], refusal);
    expectMentions(page, {"class=\"render-refused\"", "not rendered: "});
    expectMentions(page, {html::escape(refusal)});
  }
}

}  // namespace lab_cli_test
}  // namespace scatterlab
