// `scatterlab lab` end to end: a failing material still gets its report (exit 1), a report
// replaces the previous one whole, and bad input leaves the output directory as it was.
// The browser test (tests/report) looks at a whole report in Chromium.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "cli_runner.h"

namespace scatterlab {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using namespace cli_runner;

// Disney's BRDF is not energy-conserving: a white, rough base reflects more than it receives
// at grazing incidence (README), so the kit's albedo row fails at 80 degrees.
constexpr const char* WhiteRoughDisney = R"({"type": "disney", "baseColor": [1, 1, 1], "roughness": 1})";

TEST(LabCli, HelpListsEveryOption) {
  const ProcessResult run = runScatterlab({"lab", "--help"});
  ASSERT_EQ(run.exitCode, 0) << describe(run);
  expectMentions(run.out, {"--out", "--quick", "--seed", "--json", "showcase"});
}

TEST(LabCli, AFailingMaterialGetsAReportThatShowsTheFailure) {
  const fs::path out = uniquePath("lab-failing");
  const ProcessResult run = runScatterlab({"lab", WhiteRoughDisney, "--quick", "--out", out.string(), "--json"});
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
  const std::vector<std::string> lambertian{"lab", R"({"type": "lambertian"})", "--quick", "--out", out.string()};
  ASSERT_EQ(runScatterlab(lambertian).exitCode, 0);
  std::ofstream(out / "left-over.txt") << "from before";
  const ProcessResult run = runScatterlab(lambertian);
  ASSERT_EQ(run.exitCode, 0) << describe(run);
  expectMentions(run.out, {"PASS  lambertian", "report: " + (out / "index.html").string()});
  EXPECT_FALSE(fs::exists(out / "left-over.txt"));
  EXPECT_TRUE(fs::exists(out / "lambertian" / "data.json"));
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

  fs::create_directories(out);
  std::ofstream(out / "thesis.tex") << "years of work";
  expectBadInput({"lab", R"({"type": "lambertian"})", "--out", out.string()}, {"--out", "other files"});
  EXPECT_EQ(readFile(out / "thesis.tex"), "years of work");

  const fs::path file = out / "thesis.tex";
  expectBadInput({"lab", R"({"type": "lambertian"})", "--out", file.string()}, {"--out", "not a directory"});
}

}  // namespace
}  // namespace scatterlab
