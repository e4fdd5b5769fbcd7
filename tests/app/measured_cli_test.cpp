// Measured files as MATERIAL, end to end: a bare path of an RGL file or a MERL table (told apart
// by content, materials/measured/measured_file.h) is `{"type": "measured", "file": PATH}` for
// check and render, and synth and fit tell their DATA apart the same way. The real RGL file
// passes the whole kit with the negative controls rejected (docs/references.md, "RGL measured
// BRDFs").
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_runner.h"
#include "materials/measured/merl_io.h"
#include "materials/measured/tabulated_brdf.h"

namespace scatterlab {
namespace measured_cli_test {

using nlohmann::json;
namespace fs = std::filesystem;
using namespace cli_runner;

const fs::path Vinyl = fs::path(SCATTERLAB_DATA_DIR) / "rgl" / "cc_ibiza_sunset_rgb.bsdf";
const fs::path Felt = fs::path(SCATTERLAB_DATA_DIR) / "rgl" / "acrylic_felt_green_rgb.bsdf";

// `scatterlab check data/rgl/cc_ibiza_sunset_rgb.bsdf --negative-controls` at one incident angle
// (the defaults' five take tens of seconds): every row passes, and the controls that apply (3 of
// 4: an RGL file has no roughness to mismatch) are rejected by the kit.
TEST(MeasuredCli, RglFilePassesTheKitAndItsControlsAreRejected) {
  const ProcessResult run =
      runScatterlab({"check", Vinyl.string(), "--negative-controls", "--wi-theta", "60", "--json"});
  ASSERT_EQ(run.exitCode, 0) << describe(run);
  const json document = json::parse(run.out);
  EXPECT_TRUE(document.at("passed").get<bool>());
  const json& material = document.at("materials").at(0);
  EXPECT_EQ(material.at("label"), Vinyl.string());
  EXPECT_EQ(material.at("material"), (json{{"type", "measured"}, {"file", Vinyl.string()}}));
  int chiSquare = 0;
  std::set<std::string> rejected, notApplicable;  // control names (a control has a row per angle)
  for (const json& row : document.at("report").at("rows")) {
    EXPECT_TRUE(row.at("passed").get<bool>()) << row.dump();
    const std::string test = row.at("test"), note = row.value("note", "");
    chiSquare += test == "chi2";
    if (test.rfind("control:", 0) != 0) continue;
    if (note.rfind("rejected", 0) == 0) rejected.insert(test);
    if (note.find("not applicable") != std::string::npos) notApplicable.insert(test);
  }
  EXPECT_GT(chiSquare, 0);
  EXPECT_EQ(rejected.size(), 3u) << run.out;
  EXPECT_EQ(notApplicable.size(), 1u) << run.out;
}

// Render takes a bare path of either format; the picture is finite.
TEST(MeasuredCli, RenderTakesABarePathOfEitherFormat) {
  const fs::path table = uniquePath("grey-table") += ".dat";  // the name says nothing
  {
    MerlTable merl;
    for (size_t cell = 0; cell < merl::CellCount; ++cell) merl.setRgb(cell, Rgb(0.5 * InvPi));
    writeMerl(table, merl);
  }
  for (const fs::path& file : {Felt, table}) {
    const fs::path prefix = uniquePath("measured-render");
    const ProcessResult run = runScatterlab(
        {"render", file.string(), "--res", "16", "--spp", "4", "--out", prefix.string(), "--json"});
    ASSERT_EQ(run.exitCode, 0) << describe(run);
    const json out = json::parse(run.out);
    EXPECT_EQ(out.at("renders").at(0).at("material"), (json{{"type", "measured"}, {"file", file.string()}}))
        << out.dump();
    EXPECT_EQ(out.at("renders").at(0).at("non_finite_samples"), 0) << out.dump();
    EXPECT_TRUE(fs::exists(prefix.string() + ".exr")) << file;
  }
  fs::remove(table);
}

// Synth and fit take bare paths too, whatever their names say: an RGL file copied to a name
// without its extension is tabulated by synth and fitted on its own pairs, the table synth
// writes (named ".dat") is fitted as a MERL table, and a JSON material named ".txt" is a material.
TEST(MeasuredCli, SynthAndFitTellBarePathsByContent) {
  const fs::path rgl = uniquePath("felt-copy") += ".data";
  fs::copy_file(Felt, rgl);
  const fs::path table = uniquePath("felt-table") += ".dat";
  const ProcessResult synth = runScatterlab({"synth", rgl.string(), "--out", table.string()});
  ASSERT_EQ(synth.exitCode, 0) << describe(synth);
  const fs::path material = uniquePath("lambert-material") += ".txt";
  std::ofstream(material) << R"({"type": "lambertian", "albedo": 0.5})";
  const std::vector<std::pair<fs::path, std::string>> cases{
      {rgl, "rgl"}, {table, "merl"}, {material, "material"}};
  for (const auto& [file, kind] : cases) {
    const ProcessResult fit =
        runScatterlab({"fit", file.string(), "--model", "lambertian", "--metric", "ngan", "--samples", "2000",
                       "--grid-points", "8", "--starts", "1", "--json"});
    ASSERT_LE(fit.exitCode, 1) << describe(fit);  // exit 1: a poor fit, an honest outcome
    EXPECT_EQ(json::parse(fit.out).at("data").at("kind"), kind) << file;
  }
  fs::remove(rgl);
  fs::remove(table);
  fs::remove(material);
}

}  // namespace measured_cli_test
}  // namespace scatterlab
