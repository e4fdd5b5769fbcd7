// Exit codes and messages of hostile or careless input: one message, exit 2, nothing written;
// a typo gets the nearest subcommand; no message echoes more than about 200 characters of a
// value; a failed write to stdout is not a success.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "cli_runner.h"
#include "materials/measured/merl_format.h"
#include "materials/measured/merl_io.h"

namespace scatterlab {
namespace messages_cli_test {

using namespace cli_runner;

TEST(Subcommands, ATypoGetsTheNearestName) {
  expectBadInput({"chek", "{}"}, {"unknown subcommand 'chek'; did you mean 'check'?"});
  expectBadInput({"rendr"}, {"did you mean 'render'?"});
  expectBadInput({"--quiet", "lba"}, {"did you mean 'lab'?"});
  expectBadInput({"frobnicate"}, {"unknown subcommand 'frobnicate'; allowed: one of", "check", "render"});
}

TEST(Subcommands, HelpIsASubcommandToo) {
  ProcessResult run = runScatterlab({"help"});
  EXPECT_EQ(run.exitCode, 0) << describe(run);
  expectMentions(run.out, {"Usage", "check", "render", "lab"});
  run = runScatterlab({"help", "render"});
  EXPECT_EQ(run.exitCode, 0) << describe(run);
  expectMentions(run.out, {"--spp", "--env"});
  expectBadInput({"help", "rendr"}, {"help: \"rendr\" is not a subcommand"});
}

TEST(Messages, ALongValueIsEchoedShortened) {
  const std::string huge(100000, 'x');
  for (const auto& args : std::vector<std::vector<std::string>>{
           {"check", R"({"type":"lambertian","albedo":")" + huge + "\"}"},
           {"check", R"({"type":")" + huge + "\"}"},
           {"check", R"({"type":"lambertian",")" + huge + "\":1}"},
           {"check", huge + ".json"},
           {"render", R"({"type":"lambertian"})", "--res", huge, "--out", "x"},
           {"check", "--wi-theta", huge},
           {huge}}) {
    const ProcessResult run = runScatterlab(args);
    EXPECT_EQ(run.exitCode, 2) << describe(run).substr(0, 2000);
    EXPECT_LT(run.err.size(), 1000u) << run.err.substr(0, 2000);
  }
}

TEST(Messages, WriteErrorsOnStandardOutputAreNotASuccess) {
  const ProcessResult run = runScatterlab({"models"}, RunOptions{"/dev/full", std::nullopt});
  EXPECT_EQ(run.exitCode, 2) << describe(run);
  expectMentions(run.err, {"standard output", "No space left on device"});
}

TEST(Messages, UnwritableOutputsAreFoundBeforeTheWork) {
  expectBadInput(
      {"check", R"({"type":"lambertian"})", "--samples", "100000000", "--images", "/proc/scatterlab"},
      {"--images", "/proc/scatterlab"});
  expectBadInput(
      {"fit", R"({"type":"lambertian"})", "--model", "lambertian", "--metric", "l2", "--out", "/proc/x.json"},
      {"--out", "cannot write in the directory \"/proc\""});
  const fs::path file = uniquePath("a-file");
  std::ofstream(file) << "x";
  expectBadInput(
      {"render", R"({"type":"lambertian"})", "--spp", "1048576", "--out", (file / "sphere").string()},
      {"--out", "cannot create the directory"});
}

TEST(Messages, AnAllMissingTableIsRefusedByEveryCommand) {
  const fs::path table = uniquePath("all-missing") += ".binary";
  MerlTable empty;
  for (size_t cell = 0; cell < merl::CellCount; ++cell) empty.setMissing(cell);
  writeMerl(table, empty);
  const std::string material = R"({"type":"measured","file":")" + table.string() + R"("})";
  expectBadInput({"check", material}, {table.string(), "no valid cells"});
  expectBadInput({"check", table.string()}, {table.string(), "no valid cells"});
  expectBadInput({"fit", table.string(), "--model", "lambertian", "--metric", "l2"}, {"no valid cells"});
  expectBadInput({"lab", table.string(), "--out", uniquePath("lab").string()}, {"no valid cells"});
}

TEST(Messages, ATableOfHugeValuesIsRefused) {
  const fs::path table = uniquePath("huge") += ".binary";
  MerlTable huge;
  for (size_t cell = 0; cell < merl::CellCount; ++cell) huge.setStored(1, cell, 1e300);
  std::ofstream out(table, std::ios::binary);
  const int32_t header[3] = {90, 90, 180};
  out.write(reinterpret_cast<const char*>(header), sizeof header);
  out.write(reinterpret_cast<const char*>(huge.storedData().data()),
            std::streamsize(huge.storedData().size_bytes()));
  out.close();
  expectBadInput({"check", table.string()}, {table.string(), "exceed", "green channel"});
  expectBadInput({"fit", table.string(), "--model", "lambertian", "--metric", "l2"}, {"exceed"});
}

// Material files named like the report's own entries (index.html.json is the material
// "index.html") get folders of their own: the report's page, record and assets stay intact.
TEST(LabNames, InputsNamedLikeTheReportsOwnFilesDoNotBreakIt) {
  const fs::path dir = uniquePath("lab-names");
  fs::create_directories(dir / "inputs");
  std::vector<std::string> args{"lab"};
  for (const char* name : {"index.html.json", "report.json.json", "assets.json", "manifest.json.json"}) {
    std::ofstream(dir / "inputs" / name) << R"({"type":"lambertian","albedo":0.5})";
    args.push_back((dir / "inputs" / name).string());
  }
  const fs::path out = dir / "report";
  for (const char* option : {"--quick", "--out"}) args.push_back(option);
  args.push_back(out.string());
  const ProcessResult run = runScatterlab(args);
  ASSERT_EQ(run.exitCode, 0) << describe(run);
  EXPECT_TRUE(fs::is_regular_file(out / "index.html"));
  EXPECT_TRUE(fs::is_regular_file(out / "report.json"));
  EXPECT_TRUE(fs::is_regular_file(out / "manifest.json"));
  EXPECT_TRUE(fs::is_directory(out / "assets"));
  int materialFolders = 0;
  for (const auto& entry : fs::directory_iterator(out))
    materialFolders += int(entry.is_directory() && fs::is_regular_file(entry.path() / "data.json"));
  EXPECT_EQ(materialFolders, 4);
}

// A subsurface medium whose profile would overflow or vanish is refused naming the key the user
// gave, never printed as nan or inf with exit 0 (and never an internal option's name).
TEST(Messages, ProfileValuesThatWouldNotBeFiniteAreRefused) {
  expectBadInput({"profile", R"({"type":"subsurface","sigma_s":1,"sigma_a":0.1,"scale":1e308})"},
                 {"material key \"scale\"", "allowed"});
  expectBadInput({"profile", R"({"type":"subsurface","sigma_s":1e-300,"sigma_a":1e-300})"},
                 {"material key \"sigma_", "allowed"});
  for (
      const auto& args : std::vector<std::vector<std::string>>{
          {"profile", R"({"type":"subsurface","sigma_s":1,"sigma_a":0.1,"scale":1e308})"},
          {"profile", R"({"type":"subsurface","sigma_s":1e-300,"sigma_a":1e-300})"},
          {"profile",
           R"({"type":"subsurface","profile":"burley","sigma_s":1,"sigma_a":0,"burley_fit":"searchlight-dmfp"})"}}) {
    const ProcessResult run = runScatterlab(args);
    EXPECT_EQ(run.err.find("--min-radius"), std::string::npos) << run.err;
    EXPECT_EQ(run.out.find("nan"), std::string::npos) << run.out;
    EXPECT_EQ(run.out.find("inf"), std::string::npos) << run.out;
  }
}

}  // namespace messages_cli_test
}  // namespace scatterlab
