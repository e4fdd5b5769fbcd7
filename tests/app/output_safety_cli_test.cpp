// No command writes over what it reads, and a failed write leaves the previous outputs as they
// were (app/output_guard.h, app/staged_outputs.h): every output is compared with every input
// (canonical path, device and inode) before any work, and outputs are staged and committed as
// one set.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "cli_runner.h"
#include "materials/measured/merl_format.h"
#include "materials/measured/merl_io.h"

namespace scatterlab {
namespace output_safety_cli_test {

using namespace cli_runner;

const std::string Lambertian = R"({"type":"lambertian","albedo":0.5})";

fs::path writeText(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  std::ofstream(path) << text;
  return path;
}

// A small MERL table of a Lambertian (every cell measured).
fs::path writeTable(const fs::path& path) {
  fs::create_directories(path.parent_path());
  MerlTable table;
  for (size_t cell = 0; cell < merl::CellCount; ++cell) table.setRgb(cell, Rgb(0.5 / 3.14159));
  writeMerl(path, table);
  return path;
}

TEST(OutputOverInput, FitRefusesToWriteOverItsData) {
  const fs::path dir = uniquePath("fit-over");
  const fs::path data = writeTable(dir / "data.binary");
  const std::string before = readFile(data);
  expectBadInput({"fit", data.string(), "--model", "lambertian", "--metric", "l2", "--out", data.string()},
                 {"--out", "is the data file", "which it would overwrite"});
  EXPECT_EQ(readFile(data), before);
}

TEST(OutputOverInput, SynthRefusesToWriteOverItsMaterialFile) {
  const fs::path material = writeText(uniquePath("synth-over") / "m.json", Lambertian);
  expectBadInput({"synth", material.string(), "--out", material.string()}, {"--out", "is the material file"});
  EXPECT_EQ(readFile(material), Lambertian);
}

TEST(OutputOverInput, RenderRefusesToWriteOverItsEnvironmentMap) {
  const fs::path dir = uniquePath("render-over");
  const fs::path prefix = dir / "map";
  ASSERT_EQ(
      runScatterlab({"render", Lambertian, "--res", "16x8", "--spp", "1", "--out", prefix.string()}).exitCode,
      0);
  const std::string map = readFile(prefix.string() + ".exr");
  expectBadInput({"render", Lambertian, "--env", prefix.string() + ".exr", "--out", prefix.string()},
                 {"--out", "is the environment map"});
  EXPECT_EQ(readFile(prefix.string() + ".exr"), map);
}

TEST(OutputOverInput, LinksDoNotHideTheInput) {
  const fs::path dir = uniquePath("links");
  const fs::path material = writeText(dir / "m.json", Lambertian);
  fs::create_symlink(material, dir / "symlink.json");
  fs::create_hard_link(material, dir / "hardlink.json");
  expectBadInput({"synth", material.string(), "--out", (dir / "symlink.json").string()},
                 {"is the material file"});
  expectBadInput({"synth", material.string(), "--out", (dir / "hardlink.json").string()},
                 {"is the material file"});
  expectBadInput({"synth", material.string(), "--out", (dir / "sub" / ".." / "m.json").string()},
                 {"is the material file"});
  EXPECT_EQ(readFile(material), Lambertian);
}

TEST(OutputOverInput, ANestedTableOfAMaterialIsAnInputToo) {
  const fs::path dir = uniquePath("nested-input");
  const fs::path table = writeTable(dir / "t.binary");
  const std::string before = readFile(table);
  const std::string material = R"({"type":"measured","file":")" + table.string() + R"("})";
  expectBadInput({"synth", material, "--out", table.string()}, {"is the material's table"});
  EXPECT_EQ(readFile(table), before);
}

TEST(OutputOverInput, LabRefusesADirectoryHoldingItsInput) {
  const fs::path dir = uniquePath("lab-holds-input");
  const fs::path material = writeText(dir / "mat.json", Lambertian);
  expectBadInput({"lab", material.string(), "--quick", "--out", dir.string()},
                 {"--out", "holds the material file", "would delete"});
  EXPECT_EQ(readFile(material), Lambertian);
}

TEST(OutputOverInput, CheckImagesRefuseToReplaceAnInputOfTheSameName) {
  const fs::path dir = uniquePath("images-over");
  const fs::path material = writeText(dir / "lambertian_wi0_tables.json", Lambertian);
  expectBadInput({"check", material.string(), "--samples", "1000", "--grid", "4x8", "--images", dir.string()},
                 {"--images", "a name this command writes there"});
  EXPECT_EQ(readFile(material), Lambertian);
}

// A write that fails half-way (here: a file-size limit, as a full disk would) leaves the
// previous pair of files exactly as it was, and no temporary behind.
TEST(FailedWrite, KeepsThePreviousRenderPair) {
  const fs::path prefix = uniquePath("full-disk") / "sphere";
  const std::vector<std::string> render{"render", Lambertian, "--res", "48x48",
                                        "--spp",  "2",        "--out", prefix.string()};
  ASSERT_EQ(runScatterlab(render).exitCode, 0);
  const std::string exr = readFile(prefix.string() + ".exr"), png = readFile(prefix.string() + ".png");
  // Between the two files' sizes: the smaller is written whole, the larger fails.
  const rlim_t limit = rlim_t(std::min(exr.size(), png.size()) + 16);
  ASSERT_LT(limit, std::max(exr.size(), png.size()));
  const ProcessResult failed =
      runScatterlab(render + std::vector<std::string>{"--seed", "2"}, RunOptions{"", limit});
  EXPECT_EQ(failed.exitCode, 2) << describe(failed);
  expectMentions(failed.err, {"--out"});
  EXPECT_EQ(readFile(prefix.string() + ".exr"), exr);
  EXPECT_EQ(readFile(prefix.string() + ".png"), png);
  for (const auto& entry : fs::directory_iterator(prefix.parent_path()))
    EXPECT_EQ(entry.path().filename().string().find(".tmp-"), std::string::npos) << entry.path();
}

TEST(LabManifest, ADirectoryWithAForeignFileIsNotReplaced) {
  const fs::path out = uniquePath("lab-manifest");
  // A one-line report.json naming the generator proves nothing.
  writeText(out / "report.json", R"({"generator": "scatterlab lab"})");
  writeText(out / "notes.txt", "mine");
  expectBadInput({"lab", Lambertian, "--quick", "--out", out.string()},
                 {"--out", "cannot replace", "manifest"});
  EXPECT_EQ(readFile(out / "notes.txt"), "mine");
}

}  // namespace output_safety_cli_test
}  // namespace scatterlab
