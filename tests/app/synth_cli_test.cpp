// `scatterlab synth` and `scatterlab check` on measured files, end to end: what is written,
// determinism across seeds and thread counts, the bundle and its cache, and bad input (exit 2,
// one message naming the file or option and the problem, nothing written).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <fstream>
#include <map>
#include <set>

#include <nlohmann/json.hpp>

#include "app/measured_bundle.h"
#include "app/synth_command.h"
#include "cli_runner.h"
#include "materials/bsdf/lambertian.h"
#include "materials/measured/merl_io.h"
#include "materials/measured/ngan_fits.h"
#include "materials/registry/spec_validation.h"

namespace scatterlab {
namespace synth_cli_test {

using nlohmann::json;
namespace fs = std::filesystem;
using namespace cli_runner;

const std::vector<std::string> Perturbed{"--log-noise",  "0.1",  "--noise-floor",   "0.001",
                                         "--gain-sigma", "0.02", "--missing-above", "80"};
// A check of a measured file that takes a few seconds: few samples, a coarse grid.
const std::vector<std::string> QuickCheck{"--samples", "20000", "--grid", "16x32", "--wi-theta", "0,60"};

std::string fitFile() {
  return (fs::path(SCATTERLAB_DATA_DIR) / "published-fits" / "ngan_cooktorrance.fit").string();
}

// ---- synth ----------------------------------------------------------------------------------

TEST(SynthCli, HelpListsEveryOption) {
  const ProcessResult run = runScatterlab({"synth", "--help"});
  EXPECT_EQ(run.exitCode, 0) << describe(run);
  for (const char* option : {"--fit", "--name", "--bundle", "--out", "--seed", "--gain-sigma", "--log-noise",
                             "--noise-floor", "--missing-above", "--threads", "--force", "--json"})
    EXPECT_NE(run.out.find(option), std::string::npos) << option;
}

TEST(SynthCli, WritesAMaterialsTableAndDescribesItInJson) {
  const fs::path out = uniquePath("gold") += ".binary";
  const ProcessResult run =
      runScatterlab({"synth", R"({"type": "conductor", "alpha": 0.2})", "--out", out.string(), "--json"});
  ASSERT_EQ(run.exitCode, 0) << describe(run);
  const json written = json::parse(run.out).at("written").at(0);
  EXPECT_EQ(written.at("file"), out.string());
  EXPECT_EQ(written.at("bytes"), merl::FileBytes);
  EXPECT_EQ(written.at("missing_cells"), 0);
  EXPECT_EQ(written.at("material").at("metal"), "Au");  // the completed material
  EXPECT_EQ(fs::file_size(out), merl::FileBytes);
  EXPECT_EQ(readMerl(out).missingCount(), 0u);
  fs::remove(out);
}

TEST(SynthCli, SameSeedSameBytesForAnyThreadCount) {
  const fs::path one = uniquePath("one"), two = uniquePath("two"), other = uniquePath("other");
  const std::vector<std::string> base{"synth", "--fit", fitFile(), "--name", "gray-plastic"};
  const auto run = [&](const fs::path& out, const std::string& seed, const std::string& threads) {
    return runScatterlab(
        base + Perturbed +
        std::vector<std::string>{"--out", out.string(), "--seed", seed, "--threads", threads});
  };
  EXPECT_EQ(run(one, "7", "1").exitCode, 0);
  EXPECT_EQ(run(two, "7", "2").exitCode, 0);
  EXPECT_EQ(run(other, "8", "2").exitCode, 0);
  EXPECT_TRUE(readFile(one) == readFile(two));
  EXPECT_FALSE(readFile(one) == readFile(other));
  for (const fs::path& p : {one, two, other}) fs::remove(p);
}

// The parallel generator gives the table of the serial one (app/synth_command.h).
TEST(SynthCli, ParallelTableEqualsTheSerialOne) {
  const LambertianBsdf diffuse(Rgb(0.4));
  MeasurementPerturbation p;
  p.logSigma = 0.2;
  p.missingAboveDeg = 85;
  const MeasurementSynthesizer synthesizer({&diffuse}, p);
  EXPECT_TRUE(synthesizeTable(synthesizer, 2) == synthesizer.synthesize());
}

TEST(SynthCli, FitLineWithPerturbationsReportsWhatItDid) {
  const fs::path out = uniquePath("bronze");
  const ProcessResult run =
      runScatterlab(std::vector<std::string>{"synth", "--fit", fitFile(), "--name", "alum-bronze", "--out",
                                             out.string(), "--json"} +
                    Perturbed + std::vector<std::string>{"--seed", "7"});
  ASSERT_EQ(run.exitCode, 0) << describe(run);
  const json written = json::parse(run.out).at("written").at(0);
  EXPECT_EQ(written.at("fit").at("name"), "alum-bronze");
  EXPECT_EQ(written.at("fit").at("components").at(1).at("type"), "ngan-cook-torrance");
  EXPECT_EQ(written.at("perturbation").at("seed"), 7);
  EXPECT_EQ(written.at("perturbation").at("missing_above_deg"), 80.0);
  EXPECT_GT(written.at("missing_cells").get<size_t>(), 0u);
  EXPECT_EQ(readMerl(out).missingCount(), written.at("missing_cells").get<size_t>());
  for (double gain : written.at("channel_gains")) EXPECT_NE(gain, 1.0);
  fs::remove(out);
}

TEST(SynthCli, BadInputWritesNothing) {
  const fs::path out = uniquePath("never");
  const std::string o = out.string();
  expectBadInput({"synth", "--out", o}, {"nothing to tabulate"});
  expectBadInput({"synth", R"({"type": "lambertian"})", "--fit", fitFile(), "--name", "chrome", "--out", o},
                 {"more than one source"});
  expectBadInput({"synth", "--fit", fitFile(), "--out", o}, {"--fit", "needs --name"});
  expectBadInput({"synth", "--fit", fitFile(), "--name", "unobtainium", "--out", o},
                 {"--name", "\"unobtainium\"", "alum-bronze", "86 in all"});
  expectBadInput({"synth", "--fit", (out / "absent.fit").string(), "--name", "chrome", "--out", o},
                 {"absent.fit", "not found"});
  expectBadInput({"synth", R"({"type": "lambertian", "albedo": 2})", "--out", o}, {"albedo", "out of range"});
  expectBadInput({"synth", R"({"type": "lambertian"})"}, {"--out", "missing"});
  // Missing parents are created (as everywhere); a file in their place is found before the work.
  const fs::path blocker = uniquePath("blocker");
  std::ofstream(blocker) << "a file";
  expectBadInput({"synth", R"({"type": "lambertian"})", "--out", (blocker / "sub" / "x.binary").string()},
                 {"--out", "cannot create the directory"});
  expectBadInput({"synth", "--bundle", blocker.string()},
                 {"--bundle", "cannot create the directory", blocker.filename().string()});
  expectBadInput({"synth", R"({"type": "lambertian"})", "--out", testOutputDir().string()},
                 {"is a directory"});
  expectBadInput({"synth", R"({"type": "lambertian"})", "--out", o, "--log-noise", "-1"},
                 {"--log-noise", "-1"});
  expectBadInput({"synth", R"({"type": "lambertian"})", "--out", o, "--missing-above", "0"},
                 {"--missing-above"});
  expectBadInput({"synth", R"({"type": "lambertian"})", "--out", o, "--force"}, {"--force"});
  expectBadInput({"synth", "--bundle", (out / "b").string(), "--out", o},
                 {"--out", "not used with --bundle"});
  EXPECT_FALSE(fs::exists(out));
}

// ---- the bundle ---------------------------------------------------------------------------------

TEST(SynthBundle, SpansTheCategoriesAndCopiesTheShippedFitLines) {
  std::map<std::string, std::string> lines;
  for (const PublishedFit& fit : readPublishedFits(fitFile())) lines[fit.name] = fit.line;
  std::set<std::string> categories, names;
  for (const BundleMaterial& material : measuredBundle()) {
    SCOPED_TRACE(material.name);
    names.insert(material.name);
    categories.insert(material.category);
    ASSERT_TRUE(lines.contains(material.name));
    EXPECT_EQ(lines[material.name], material.fitLine);
    EXPECT_EQ(parsePublishedFitLine(material.fitLine).name, material.name);
  }
  EXPECT_GE(names.size(), 8u);
  EXPECT_EQ(categories, (std::set<std::string>{"diffuse", "plastic", "paint", "metal"}));
}

// The whole bundle (10 tables, 350 MB, ~5 s), then again from the cache.
TEST(SynthBundle, GeneratesEveryMaterialThenKeepsTheCache) {
  const fs::path dir = uniquePath("bundle");
  const ProcessResult first = runScatterlab({"synth", "--bundle", dir.string(), "--json"});
  ASSERT_EQ(first.exitCode, 0) << describe(first);
  const json report = json::parse(first.out);
  ASSERT_EQ(report.at("written").size(), measuredBundle().size());
  for (const json& entry : report.at("written")) {
    EXPECT_FALSE(entry.at("cached").get<bool>());
    EXPECT_EQ(fs::file_size(entry.at("file").get<std::string>()), merl::FileBytes);
  }
  const json manifest = json::parse(readFile(dir / "bundle.json"));
  EXPECT_EQ(manifest.at("materials").size(), measuredBundle().size());
  EXPECT_EQ(manifest.at("materials").at("chrome").at("category"), "metal");

  const ProcessResult second = runScatterlab({"synth", "--bundle", dir.string()});
  ASSERT_EQ(second.exitCode, 0) << describe(second);
  EXPECT_NE(second.out.find("cached " + (dir / "chrome.binary").string()), std::string::npos) << second.out;
  EXPECT_EQ(second.out.find("wrote"), std::string::npos) << second.out;
  // The bundle's chrome is the --fit chrome with the same seed.
  const fs::path single = uniquePath("chrome");
  ASSERT_EQ(
      runScatterlab({"synth", "--fit", fitFile(), "--name", "chrome", "--out", single.string()}).exitCode, 0);
  EXPECT_TRUE(readFile(single) == readFile(dir / "chrome.binary"));
  fs::remove(single);
  fs::remove_all(dir);
}

// ---- check on measured files --------------------------------------------------------------------

class MeasuredCheck : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    table_ = new fs::path(uniquePath("felt") += ".binary");
    MeasurementPerturbation p;
    p.missingAboveDeg = 85;
    const auto fit = parsePublishedFitLine(measuredBundle()[0].fitLine);
    std::vector<std::unique_ptr<BsdfModel>> models;
    std::vector<const BsdfModel*> pointers;
    for (const json& component : fit.components()) {
      models.push_back(makeBsdf(component));
      pointers.push_back(models.back().get());
    }
    writeMerl(*table_, MeasurementSynthesizer(pointers, p).synthesize());
  }
  static void TearDownTestSuite() {
    fs::remove(*table_);
    delete table_;
  }
  static const fs::path& table() { return *table_; }

 private:
  static fs::path* table_;
};
fs::path* MeasuredCheck::table_ = nullptr;

TEST_F(MeasuredCheck, PassesAndReportsTheMissingCells) {
  const std::string material = json{{"type", "measured"}, {"file", table().string()}}.dump();
  const ProcessResult text = runScatterlab(std::vector<std::string>{"check", material} + QuickCheck);
  EXPECT_EQ(text.exitCode, 0) << describe(text);
  expectMentions(text.out, {"cells missing in the file", "verdict: PASS"});
  const ProcessResult run = runScatterlab(std::vector<std::string>{"check", material, "--json"} + QuickCheck);
  ASSERT_EQ(run.exitCode, 0) << describe(run);
  const json document = json::parse(run.out);
  EXPECT_EQ(document.at("materials").at(0).at("missing_cells"), readMerl(table()).missingCount());
}

TEST_F(MeasuredCheck, RelativeFileInAMaterialFileIsFound) {
  const fs::path dir = uniquePath("materials");
  fs::create_directories(dir / "data");
  fs::copy_file(table(), dir / "data" / "felt.binary");
  std::ofstream(dir / "felt.json") << R"({"type": "measured", "file": "data/felt.binary"})";
  const ProcessResult run =
      runScatterlab(std::vector<std::string>{"check", (dir / "felt.json").string()} + QuickCheck);
  EXPECT_EQ(run.exitCode, 0) << describe(run);
  fs::remove_all(dir);
}

TEST(MeasuredCheckBadInput, EveryBadFileIsNamedWithItsProblem) {
  const fs::path dir = uniquePath("bad-tables");
  fs::create_directories(dir);
  const auto check = [](const fs::path& file) {
    return std::vector<std::string>{"check", json{{"type", "measured"}, {"file", file.string()}}.dump()};
  };
  expectBadInput(check(dir / "absent.binary"), {"absent.binary", "not found"});
  expectBadInput(check(dir), {dir.string(), "is a directory"});
  std::ofstream(dir / "tiny.binary") << "01234";
  expectBadInput(check(dir / "tiny.binary"), {"tiny.binary", "truncated", "5 bytes", "header"});
  {
    std::ofstream cut(dir / "short.binary", std::ios::binary);
    const int32_t dims[3] = {90, 90, 180};
    cut.write(reinterpret_cast<const char*>(dims), sizeof dims);
    cut << std::string(100, '\0');
  }
  expectBadInput(check(dir / "short.binary"), {"short.binary", "truncated", "112 bytes", "34992012"});
  {
    std::ofstream header(dir / "header.binary", std::ios::binary);
    const int32_t dims[3] = {90, 90, 90};
    header.write(reinterpret_cast<const char*>(dims), sizeof dims);
  }
  expectBadInput(check(dir / "header.binary"), {"header.binary", "bad header", "90 x 90 x 90"});
  {
    MerlTable table;
    writeMerl(dir / "nan.binary", table);
    std::fstream patch(dir / "nan.binary", std::ios::binary | std::ios::in | std::ios::out);
    const double nan = std::nan("");
    patch.seekp(12 + 8 * 100);
    patch.write(reinterpret_cast<const char*>(&nan), 8);
  }
  expectBadInput(check(dir / "nan.binary"), {"nan.binary", "NaN", "red", "cell 100"});
  expectBadInput({"check", R"({"type": "measured"})"}, {"\"file\" is missing"});
  fs::remove_all(dir);
}

TEST(MeasuredModels, AreListed) {
  const ProcessResult run = runScatterlab({"models"});
  ASSERT_EQ(run.exitCode, 0) << describe(run);
  expectMentions(run.out, {"measured:", "file", "path", "Matusik"});
}

}  // namespace synth_cli_test
}  // namespace scatterlab
