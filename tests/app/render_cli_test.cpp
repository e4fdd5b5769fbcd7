// `scatterlab render` end to end: what is written (EXR with layers, PNG, a labelled gallery),
// JSON output, determinism across thread counts, and bad input (exit 2, one message naming
// the option or file and what is allowed, nothing written).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "app/render_command.h"
#include "cli_runner.h"
#include "integrator/exr_io.h"
#include "integrator/render.h"

namespace scatterlab {
namespace render_cli_test {

using nlohmann::json;
namespace fs = std::filesystem;
using namespace cli_runner;

const std::string WhiteLambertian = R"({"type":"lambertian","albedo":1})";

std::vector<std::string> operator+(std::vector<std::string> a, const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

void expectMentions(const std::string& text, const std::vector<std::string>& fragments) {
  for (const std::string& fragment : fragments)
    EXPECT_NE(text.find(fragment), std::string::npos) << "\"" << fragment << "\" missing from:\n" << text;
}

// A bad-input run: exit 2, one error message mentioning `fragments`, nothing on stdout, and
// neither output file.
void expectBadInput(const std::vector<std::string>& args, const std::vector<std::string>& fragments,
                    const fs::path& prefix) {
  const ProcessResult run = runScatterlab(args);
  EXPECT_EQ(run.exitCode, 2) << describe(run);
  EXPECT_TRUE(run.out.empty()) << describe(run);
  EXPECT_EQ(run.err.rfind("scatterlab: error: ", 0), 0u) << describe(run);
  expectMentions(run.err, fragments);
  EXPECT_FALSE(fs::exists(prefix.string() + ".exr")) << describe(run);
  EXPECT_FALSE(fs::exists(prefix.string() + ".png")) << describe(run);
}

std::string readBytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), {});
}

// A map written by the library, for --env.
fs::path writeMap(const std::string& stem, int width, int height, float value, int badX = -1,
                  float bad = 0.0f) {
  Image image(width, height, 3, value);
  if (badX >= 0) image.pixel(badX, 0)[0] = bad;
  const fs::path path = uniquePath(stem) += ".exr";
  writeExr(path, {{"", {"R", "G", "B"}, &image}});
  return path;
}

TEST(RenderCli, HelpListsEveryOption) {
  const ProcessResult run = runScatterlab({"render", "--help"});
  EXPECT_EQ(run.exitCode, 0) << describe(run);
  expectMentions(run.out, {"--scene",        "--env",
                           "--env-strength", "--env-rotate",
                           "--spp",          "--res",
                           "--threads",      "--seed",
                           "--max-depth",    "--estimator",
                           "--subsurface",   "--filter",
                           "--exposure",     "--layers",
                           "--label",        "--columns",
                           "--out",          "--json",
                           "--integrator",   "--light-position",
                           "--light-radius", "--light-strength",
                           "--no-light",     "--photons",
                           "--sppm-radius",  "caustic"});
}

TEST(RenderCli, WritesExrAndPngWithLayersAndJson) {
  const fs::path prefix = uniquePath("furnace");
  const ProcessResult run =
      runScatterlab({"render", WhiteLambertian, "--res", "24x16", "--spp", "8", "--layers",
                     "albedo,normal,variance", "--out", prefix.string(), "--json"});
  ASSERT_EQ(run.exitCode, 0) << describe(run);
  const json out = json::parse(run.out);
  EXPECT_EQ(out["res"], json({24, 16}));
  EXPECT_EQ(out["environment"]["type"], "constant");
  const json& r = out["renders"][0];
  EXPECT_EQ(r["material"]["type"], "lambertian");
  EXPECT_EQ(r["samples"], 24 * 16 * 8);
  EXPECT_GT(r["vertices_per_second"].get<double>(), 0.0);
  EXPECT_EQ(r["non_finite_samples"], 0);
  EXPECT_EQ(r["background"]["mean"], 1.0);  // the furnace's background is exactly 1
  const Image color = readExrRgb(prefix.string() + ".exr");
  EXPECT_EQ(color.width(), 24);
  EXPECT_EQ(color.height(), 16);
  std::vector<std::string> channels = readExrChannelNames(prefix.string() + ".exr");
  EXPECT_EQ(channels,
            (std::vector<std::string>{"B", "G", "R", "albedo.B", "albedo.G", "albedo.R", "normal.X",
                                      "normal.Y", "normal.Z", "variance.B", "variance.G", "variance.R"}));
  EXPECT_GT(fs::file_size(prefix.string() + ".png"), 50u);
}

TEST(RenderCli, MapAndPreviewSceneAndGaussianFilter) {
  const fs::path prefix = uniquePath("preview");
  const ProcessResult run = runScatterlab(
      {"render", (fs::path(SCATTERLAB_DATA_DIR) / "materials" / "copper-beckmann.json").string(), "--scene",
       "preview", "--env", (fs::path(SCATTERLAB_DATA_DIR) / "envmaps" / "studio.exr").string(),
       "--env-rotate", "45", "--filter", "gaussian", "--res", "20", "--spp", "4", "--exposure", "1", "--out",
       prefix.string()});
  ASSERT_EQ(run.exitCode, 0) << describe(run);
  expectMentions(run.out, {"copper-beckmann", "20x20", "wrote"});
  EXPECT_TRUE(fs::exists(prefix.string() + ".exr"));
  EXPECT_TRUE(fs::exists(prefix.string() + ".png"));
}

// A material whose samples are not finite or negative (the test hook of
// integrator/fault_injection.h, half of every BSDF's samples): the film drops them, the images
// hold no NaN and nothing below 0, and the command says how many and exits 1. Without the
// fault the same render drops nothing and exits 0.
TEST(RenderCli, DroppedSamplesAreCountedShownAndFailTheRender) {
  const std::vector<std::string> render{
      "render", R"({"type":"conductor","alpha":0.3})", "--res", "16x12", "--spp", "4", "--json"};
  const fs::path clean = uniquePath("no-fault");
  const ProcessResult good = runScatterlab(render + std::vector<std::string>{"--out", clean.string()});
  ASSERT_EQ(good.exitCode, 0) << describe(good);
  EXPECT_EQ(json::parse(good.out)["dropped_samples"], 0);
  EXPECT_EQ(json::parse(good.out)["passed"], true);
  for (const auto& [fault, key] : std::vector<std::pair<std::string, std::string>>{
           {"non-finite", "non_finite_samples"}, {"negative", "negative_samples"}}) {
    SCOPED_TRACE(fault);
    const fs::path prefix = uniquePath("fault-" + fault);
    const ProcessResult run = runScatterlab(render + std::vector<std::string>{"--out", prefix.string()},
                                            std::vector<std::string>{"SCATTERLAB_TEST_FAULT=" + fault});
    ASSERT_EQ(run.exitCode, 1) << describe(run);
    const json out = json::parse(run.out);
    const json& r = out["renders"][0];
    const uint64_t dropped = r["dropped_samples"].get<uint64_t>();
    // About half of the sphere's samples (its BSDF samples with uLobe < 1/2), none of the
    // background's; every one of them of the kind the fault makes.
    EXPECT_GT(dropped, 16u);
    EXPECT_LT(dropped, r["samples"].get<uint64_t>());
    EXPECT_EQ(r[key].get<uint64_t>(), dropped);
    EXPECT_EQ(out["dropped_samples"].get<uint64_t>(), dropped);
    EXPECT_EQ(out["passed"], false);
    expectMentions(run.err,
                   {"render: ", std::to_string(dropped) + " of " +
                                    std::to_string(r["samples"].get<uint64_t>()) + " samples dropped"});
    const Image image = readExrRgb(prefix.string() + ".exr");
    for (const float v : image.data()) ASSERT_TRUE(std::isfinite(v) && v >= 0.0f) << v;
    // The text output says it too.
    const ProcessResult text = runScatterlab(std::vector<std::string>(render.begin(), render.end() - 1) +
                                                 std::vector<std::string>{"--out", prefix.string()},
                                             std::vector<std::string>{"SCATTERLAB_TEST_FAULT=" + fault});
    EXPECT_EQ(text.exitCode, 1) << describe(text);
    expectMentions(text.out, {"FAILED: " + std::to_string(dropped) + " samples dropped"});
  }
}

// Every estimator renders the caustic scene (glass on grey ground, the sphere light alone) to
// EXR and PNG, with its variance layer where it has one, and says which it was.
TEST(RenderCli, EveryIntegratorRendersTheCausticScene) {
  for (const std::string integrator : {"path", "light", "bdpt", "sppm"}) {
    const fs::path prefix = uniquePath("caustic-" + integrator);
    std::vector<std::string> args{"render",       R"({"type":"dielectric"})",
                                  "--integrator", integrator,
                                  "--scene",      "caustic",
                                  "--res",        "16x12",
                                  "--spp",        "2",
                                  "--out",        prefix.string(),
                                  "--json"};
    if (integrator != "sppm") args = args + std::vector<std::string>{"--layers", "variance,normal"};
    const ProcessResult run = runScatterlab(args);
    ASSERT_EQ(run.exitCode, 0) << describe(run);
    const json out = json::parse(run.out);
    EXPECT_EQ(out["integrator"], integrator);
    EXPECT_EQ(out["environment"]["type"], "none");
    EXPECT_EQ(out["light"]["radius"], PresetLight{}.radius);
    EXPECT_EQ(out["renders"][0]["non_finite_samples"], 0);
    EXPECT_GT(out["renders"][0]["vertices"].get<uint64_t>(), 0u);
    EXPECT_TRUE(fs::exists(prefix.string() + ".png"));
    const std::vector<std::string> channels = readExrChannelNames(prefix.string() + ".exr");
    EXPECT_EQ(channels.size(), integrator == "sppm" ? 3u : 9u) << integrator;
  }
}

TEST(RenderCli, ThePreviewLightMovesScalesAndGoes) {
  const fs::path prefix = uniquePath("light");
  const ProcessResult moved = runScatterlab(
      {"render", WhiteLambertian, "--scene", "preview", "--light-position", "-2,1,3", "--light-radius", "0.5",
       "--light-strength", "2", "--res", "8", "--spp", "1", "--out", prefix.string(), "--json"});
  ASSERT_EQ(moved.exitCode, 0) << describe(moved);
  const json light = json::parse(moved.out)["light"];
  EXPECT_EQ(light["position"], json({-2.0, 1.0, 3.0}));
  EXPECT_EQ(light["radius"], 0.5);
  EXPECT_EQ(light["radiance"][0], 2 * PresetLight{}.radiance.x);
  const ProcessResult gone = runScatterlab({"render", WhiteLambertian, "--scene", "preview", "--no-light",
                                            "--res", "8", "--spp", "1", "--out", prefix.string(), "--json"});
  ASSERT_EQ(gone.exitCode, 0) << describe(gone);
  EXPECT_TRUE(json::parse(gone.out)["light"].is_null());
}

TEST(RenderCli, GalleryIsOneLabelledSheet) {
  const fs::path prefix = uniquePath("gallery");
  const ProcessResult run =
      runScatterlab({"render", WhiteLambertian, R"({"type":"dielectric"})", R"({"type":"conductor"})",
                     "--res", "16", "--spp", "2", "--label", "white", "--label", "glass", "--label", "metal",
                     "--columns", "3", "--out", prefix.string(), "--json"});
  ASSERT_EQ(run.exitCode, 0) << describe(run);
  const json out = json::parse(run.out);
  ASSERT_EQ(out["renders"].size(), 3u);
  EXPECT_EQ(out["renders"][1]["label"], "glass");
  const Image sheet = readExrRgb(prefix.string() + ".exr");
  EXPECT_EQ(sheet.width(), 4 + 3 * (16 + 4));  // gap + columns x (cell + gap)
  EXPECT_GT(sheet.height(), 16 + 8);           // a cell and its label strip
}

TEST(RenderCli, SameImageForOneAndTwoThreads) {
  const fs::path one = uniquePath("threads1"), two = uniquePath("threads2");
  const std::vector<std::string> common{
      "render", R"({"type":"rough-dielectric","alpha":0.3})", "--res", "24", "--spp", "4", "--seed", "7"};
  ASSERT_EQ(
      runScatterlab(common + std::vector<std::string>{"--threads", "1", "--out", one.string()}).exitCode, 0);
  ASSERT_EQ(
      runScatterlab(common + std::vector<std::string>{"--threads", "2", "--out", two.string()}).exitCode, 0);
  EXPECT_EQ(readBytes(one.string() + ".exr"), readBytes(two.string() + ".exr"));
  EXPECT_EQ(readBytes(one.string() + ".png"), readBytes(two.string() + ".png"));
}

// The gallery of Jensen et al. 2001's measured media (Marble on a sphere of 1 cm, "scale": 10;
// Skin1 behind a rough boundary, Ketchup and Wholemilk at 1 mm), both ways: the diffusion
// profile and the volumetric random walk. Every sphere renders finite and lit.
TEST(RenderCli, SubsurfaceGalleryInBothModes) {
  for (const char* mode : {"diffusion", "walk"}) {
    const fs::path prefix = uniquePath(std::string("subsurface-") + mode);
    const ProcessResult run = runScatterlab(
        {"render", R"({"type":"subsurface","medium":"Marble","scale":10})",
         R"({"type":"subsurface","medium":"Skin1","profile":"beam-diffusion","boundary":"rough","roughness":0.2})",
         R"({"type":"subsurface","medium":"Ketchup","profile":"dipole"})",
         R"({"type":"subsurface","medium":"Wholemilk","profile":"better-dipole"})", "--res", "16", "--spp",
         "2", "--subsurface", mode, "--out", prefix.string(), "--json"});
    ASSERT_EQ(run.exitCode, 0) << describe(run);
    const json out = json::parse(run.out);
    EXPECT_EQ(out["subsurface"], mode);
    ASSERT_EQ(out["renders"].size(), 4u);
    for (const json& r : out["renders"]) {
      EXPECT_EQ(r["non_finite_samples"], 0) << r.dump();
      EXPECT_GT(r["sphere"]["n"].get<int>(), 0) << r.dump();
      EXPECT_GT(r["sphere"]["mean"].get<double>(), 0.0) << r.dump();
      EXPECT_EQ(r["material"]["type"], "subsurface");
    }
    EXPECT_TRUE(fs::exists(prefix.string() + ".png"));
  }
}

// ---- Bad input ------------------------------------------------------------------------------

class RenderCliBadInput : public ::testing::Test {
 protected:
  fs::path prefix = uniquePath("bad");
  std::vector<std::string> with(const std::vector<std::string>& extra) const {
    return std::vector<std::string>{"render", WhiteLambertian, "--res",        "8", "--spp",
                                    "1",      "--out",         prefix.string()} +
           extra;
  }
};

TEST_F(RenderCliBadInput, Resolutions) {
  expectBadInput(with({"--res", "0x16"}), {"--res", "\"0x16\"", "WxH"}, prefix);
  expectBadInput(with({"--res", "100000x100000"}),
                 {"--res", "\"100000x100000\"", std::to_string(MaxImageSide)}, prefix);
  expectBadInput(with({"--res", "8192x8192"}), {"--res", std::to_string(MaxImagePixels)}, prefix);
  expectBadInput(with({"--res", "abc"}), {"--res", "\"abc\""}, prefix);
}

TEST_F(RenderCliBadInput, SamplesAndSettings) {
  expectBadInput(with({"--spp", "0"}), {"--spp", "\"0\"", "[1, "}, prefix);
  expectBadInput(with({"--spp", "-3"}), {"--spp"}, prefix);
  expectBadInput(with({"--scene", "cornell"}),
                 {"--scene", "\"cornell\"", "\"sphere\", \"preview\", \"caustic\""}, prefix);
  expectBadInput(with({"--estimator", "guess"}), {"--estimator", "\"mis\", \"bsdf\", \"light\""}, prefix);
  expectBadInput(with({"--subsurface", "photon"}), {"--subsurface", "\"diffusion\", \"walk\""}, prefix);
  expectBadInput(with({"--layers", "depth"}),
                 {"--layers", "\"depth\"", "\"albedo\", \"normal\", \"variance\""}, prefix);
  expectBadInput(with({"--env-strength", "nan"}), {"--env-strength", "\"nan\""}, prefix);
}

// An integrator that is not one, or that cannot take what it is given: one message, exit 2,
// nothing written.
TEST_F(RenderCliBadInput, Integrators) {
  expectBadInput(with({"--integrator", "photon"}),
                 {"--integrator", "\"photon\"", "\"path\", \"light\", \"bdpt\", \"sppm\""}, prefix);
  for (const char* integrator : {"light", "bdpt", "sppm"})
    expectBadInput(
        {"render", R"({"type":"subsurface"})", "--integrator", integrator, "--out", prefix.string()},
        {"subsurface", integrator, "--integrator path"}, prefix);
  expectBadInput(with({"--integrator", "bdpt", "--estimator", "bsdf"}), {"--estimator", "--integrator path"},
                 prefix);
  expectBadInput(with({"--integrator", "sppm", "--layers", "variance"}), {"--layers", "variance", "sppm"},
                 prefix);
  expectBadInput(with({"--photons", "100"}), {"--photons", "--integrator sppm"}, prefix);
  expectBadInput(with({"--integrator", "light", "--sppm-radius", "2"}),
                 {"--sppm-radius", "--integrator sppm"}, prefix);
}

TEST_F(RenderCliBadInput, Lights) {
  expectBadInput(with({"--light-radius", "0.5"}), {"--light-radius", "sphere scene", "preview or caustic"},
                 prefix);
  expectBadInput(with({"--scene", "preview", "--light-position", "0.5,0,0"}),
                 {"--light-position", "meets the sphere"}, prefix);
  expectBadInput(with({"--scene", "caustic", "--light-position", "3,0,-0.9"}), {"--light-position", "ground"},
                 prefix);
  expectBadInput(with({"--scene", "preview", "--light-position", "1,2"}), {"--light-position"}, prefix);
  expectBadInput(with({"--scene", "preview", "--light-strength", "-1"}), {"--light-strength", "\"-1\""},
                 prefix);
  expectBadInput(with({"--scene", "preview", "--no-light", "--light-radius", "0.3"}), {"--no-light"}, prefix);
  expectBadInput(with({"--env", "none", "--env-strength", "nan"}), {"--env-strength"}, prefix);
}

TEST_F(RenderCliBadInput, Materials) {
  expectBadInput({"render", R"({"type":"lambertian","albedo":2})", "--out", prefix.string()}, {"albedo"},
                 prefix);
  expectBadInput({"render", "no-such-material.json", "--out", prefix.string()}, {"no-such-material.json"},
                 prefix);
  // A subsurface material's rough boundary is a rough dielectric: eta 1 has no microfacet
  // refraction, and the material is refused when it is read, naming the key.
  expectBadInput({"render", R"({"type":"subsurface","eta":1,"boundary":"rough"})", "--out", prefix.string()},
                 {"\"eta\"", "[1.02, 4]", "rough boundary"}, prefix);
  expectBadInput(
      {"render", R"({"type":"subsurface","sigma_s":[1,1,1],"sigma_a":[-1,0,0]})", "--out", prefix.string()},
      {"sigma_a"}, prefix);
  expectBadInput({"render", WhiteLambertian, WhiteLambertian, "--label", "one", "--out", prefix.string()},
                 {"--label", "1 labels for 2 materials"}, prefix);
  expectBadInput({"render", WhiteLambertian, WhiteLambertian, "--layers", "albedo", "--out", prefix.string()},
                 {"--layers", "single material"}, prefix);
}

TEST_F(RenderCliBadInput, EnvironmentMaps) {
  const fs::path missing = uniquePath("absent") += ".exr";
  expectBadInput(with({"--env", missing.string()}), {"--env", missing.string(), "no such file"}, prefix);
  const fs::path text = uniquePath("text") += ".exr";
  std::ofstream(text) << "not an image";
  expectBadInput(with({"--env", text.string()}), {"--env", text.string(), "cannot be read as OpenEXR"},
                 prefix);
  const fs::path square = writeMap("square", 16, 16, 1.0f);
  expectBadInput(with({"--env", square.string()}), {"--env", square.string(), "width = 2 x height"}, prefix);
  const fs::path nan = writeMap("nan", 16, 8, 1.0f, 3, NAN);
  expectBadInput(with({"--env", nan.string()}), {"--env", nan.string(), "pixel (3, 0) channel R", "finite"},
                 prefix);
  const fs::path negative = writeMap("negative", 16, 8, 1.0f, 2, -2.0f);
  expectBadInput(with({"--env", negative.string()}), {"--env", negative.string(), "pixel (2, 0)", ">= 0"},
                 prefix);
}

TEST_F(RenderCliBadInput, Outputs) {
  // Missing parents are created (as everywhere); a file in their place is found before rendering.
  const fs::path blocker = uniquePath("blocker");
  std::ofstream(blocker) << "a file";
  const fs::path nowhere = blocker / "sub" / "image";
  expectBadInput({"render", WhiteLambertian, "--out", nowhere.string()},
                 {"--out", "cannot create the directory"}, nowhere);
  // PREFIX.exr occupied by a directory: rejected before rendering.
  const fs::path occupied = uniquePath("occupied");
  fs::create_directories(occupied.string() + ".exr");
  const ProcessResult run =
      runScatterlab({"render", WhiteLambertian, "--res", "8", "--out", occupied.string()});
  EXPECT_EQ(run.exitCode, 2) << describe(run);
  expectMentions(run.err, {"--out", "is a directory"});
  EXPECT_FALSE(fs::exists(occupied.string() + ".png"));
  // PREFIX.png occupied: found before anything is written, so no EXR either.
  const fs::path pngOccupied = uniquePath("png-occupied");
  fs::create_directories(pngOccupied.string() + ".png");
  const ProcessResult second =
      runScatterlab({"render", WhiteLambertian, "--res", "8", "--out", pngOccupied.string()});
  EXPECT_EQ(second.exitCode, 2) << describe(second);
  EXPECT_FALSE(fs::exists(pngOccupied.string() + ".exr"));
  expectBadInput({"render", WhiteLambertian}, {"--out"}, prefix);
}

TEST(RenderResolution, ParsesWidthByHeightOrASide) {
  EXPECT_EQ(parseResolution("256x128")->width, 256);
  EXPECT_EQ(parseResolution("256x128")->height, 128);
  EXPECT_EQ(parseResolution("64")->height, 64);
  EXPECT_FALSE(parseResolution("64x"));
  EXPECT_FALSE(parseResolution("x64"));
  EXPECT_FALSE(parseResolution("64x64x2"));
  EXPECT_FALSE(parseResolution("-4x4"));
}

}  // namespace render_cli_test
}  // namespace scatterlab
