// One behaviour across commands: --out names every output (generate-table keeps --output);
// missing parent directories of an output are created; a path ending in '/' or a device is no
// output file; a MERL table is a material anywhere; a JSON array is one (refused) argument.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "cli_runner.h"
#include "materials/measured/merl_format.h"
#include "materials/measured/merl_io.h"

namespace scatterlab {
namespace consistency_cli_test {

using namespace cli_runner;

const std::string Lambertian = R"({"type":"lambertian","albedo":0.5})";

TEST(Consistency, MissingParentDirectoriesOfAnOutputAreCreated) {
  const fs::path root = uniquePath("parents");
  ASSERT_EQ(runScatterlab({"render", Lambertian, "--res", "8", "--spp", "1", "--out",
                           (root / "a" / "b" / "s").string()})
                .exitCode,
            0);
  EXPECT_TRUE(fs::exists(root / "a" / "b" / "s.png"));
  ASSERT_EQ(runScatterlab({"synth", Lambertian, "--out", (root / "c" / "t.binary").string()}).exitCode, 0);
  EXPECT_TRUE(fs::exists(root / "c" / "t.binary"));
  ASSERT_EQ(runScatterlab({"fit", (root / "c" / "t.binary").string(), "--model", "lambertian", "--metric",
                           "l2", "--samples", "2000", "--out", (root / "d" / "fit.json").string()})
                .exitCode,
            0);
  EXPECT_TRUE(fs::exists(root / "d" / "fit.json"));
}

TEST(Consistency, ADirectoryOrDeviceIsNoOutputFile) {
  const std::string dir = uniquePath("slash").string() + "/";
  for (const std::string& out : {dir, std::string("/dev/null")}) {
    SCOPED_TRACE(out);
    expectBadInput({"synth", Lambertian, "--out", out}, {"--out"});
    expectBadInput({"fit", Lambertian, "--model", "lambertian", "--metric", "l2", "--out", out}, {"--out"});
    expectBadInput({"render", Lambertian, "--out", out}, {"--out"});
  }
  EXPECT_FALSE(fs::exists(dir));
}

TEST(Consistency, AJsonArrayIsOneArgumentNotSplitAtItsCommas) {
  expectBadInput({"check", R"([{"type":"lambertian"},{"type":"conductor"}])"},
                 {"inline JSON", "array", "one material per argument"});
  expectBadInput({"render", R"([{"type":"lambertian"},{"type":"conductor"}])", "--out", "x"},
                 {"one material per argument"});
}

TEST(Consistency, ABareTableIsAMaterialForCheckAsForLab) {
  const fs::path table = uniquePath("bare") += ".binary";
  ASSERT_EQ(runScatterlab({"synth", Lambertian, "--out", table.string()}).exitCode, 0);
  const ProcessResult run =
      runScatterlab({"check", table.string(), "--samples", "20000", "--grid", "8x16", "--wi-theta", "30"});
  EXPECT_EQ(run.exitCode, 0) << describe(run);
  expectMentions(run.out, {"\"type\":\"measured\"", table.string()});
}

TEST(Consistency, SynthRefusesAMaterialWithoutReflectionLikeFit) {
  expectBadInput({"synth", R"({"type":"dielectric"})", "--out", uniquePath("glass").string()},
                 {"\"dielectric\"", "no diffuse or glossy reflection"});
}

TEST(Consistency, ATinyRenderSaysWhyItsSphereHasNoMean) {
  const ProcessResult run =
      runScatterlab({"render", Lambertian, "--res", "1", "--spp", "1", "--out", uniquePath("tiny").string()});
  ASSERT_EQ(run.exitCode, 0) << describe(run);
  expectMentions(run.out, {"sphere mean undefined at 1x1", "near the silhouette count for neither"});
}

}  // namespace consistency_cli_test
}  // namespace scatterlab
