// `scatterlab eval`, end to end: f and pdf at given direction pairs for every registry type
// (measured tables and subsurface materials included), in full precision as JSON, checked
// against closed forms where the model has one; and bad pairs, options and materials (exit 2,
// one message naming the key or option, the value and what is allowed).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include <nlohmann/json.hpp>

#include "cli_runner.h"
#include "materials/bsdf/lambertian.h"
#include "materials/bssrdf/subsurface_registry.h"
#include "materials/core/spherical.h"
#include "materials/measured/measurement_synthesis.h"
#include "materials/measured/merl_io.h"
#include "materials/registry/model_list.h"

namespace scatterlab {
namespace eval_cli_test {

using nlohmann::json;
namespace fs = std::filesystem;
using namespace cli_runner;

json evalJson(const std::vector<std::string>& args) {
  const ProcessResult run = runScatterlab(std::vector<std::string>{"eval", "--json"} + args);
  EXPECT_EQ(run.exitCode, 0) << describe(run);
  EXPECT_TRUE(run.err.empty()) << describe(run);
  return run.exitCode == 0 ? json::parse(run.out) : json::object();
}

json vectorJson(const Vec3d& v) { return json::array({v.x, v.y, v.z}); }

// A few pairs in reflection and one in transmission (wo below the surface).
json somePairs() {
  json pairs = json::array();
  const double angles[][4] = {
      {0, 0, 0, 0}, {30, 20, 35, 190}, {60, 0, 50, 120}, {80, 45, 75, 230}, {40, 0, 150, 180}};
  for (const auto& a : angles)
    pairs.push_back({{"wi", vectorJson(directionFromDegrees(a[0], a[1]))},
                     {"wo", vectorJson(directionFromDegrees(a[2], a[3]))}});
  return pairs;
}

Vec3d vectorOf(const json& v) { return {v[0].get<double>(), v[1].get<double>(), v[2].get<double>()}; }

// The material's model evaluated in this process at the directions the executable reports it
// evaluated (the given ones, normalised): it must print exactly the model's numbers (JSON
// round-trips a double exactly).
void expectModelValues(const json& material, const json& pairs, const json& printed) {
  const auto model = makeFarFieldBsdf(material);
  ASSERT_EQ(printed.at("values").size(), pairs.size()) << material;
  for (size_t i = 0; i < pairs.size(); ++i) {
    const json& value = printed["values"][i];
    const Vec3d wi = vectorOf(value["wi"]), wo = vectorOf(value["wo"]);
    // The given directions are unit to rounding: normalising moves them by a few ulps.
    EXPECT_LT(glm::length(wi - vectorOf(pairs[i]["wi"])), 1e-15) << material << " pair " << i;
    EXPECT_LT(glm::length(wo - vectorOf(pairs[i]["wo"])), 1e-15) << material << " pair " << i;
    const Rgb f = model->eval(wi, wo);
    for (int c = 0; c < 3; ++c) EXPECT_EQ(value["f"][c].get<double>(), f[c]) << material << " pair " << i;
    EXPECT_EQ(value["pdf"].get<double>(), model->pdf(wi, wo)) << material << " pair " << i;
  }
}

TEST(EvalCli, HelpListsEveryOption) {
  const ProcessResult run = runScatterlab({"eval", "--help"});
  EXPECT_EQ(run.exitCode, 0) << describe(run);
  expectMentions(run.out,
                 {"Usage", "--directions", "--wi", "--wo", "--json", "without the cosine", "far-field"});
}

// Lambertian: f = albedo / pi and pdf = cos(theta_o) / pi (cosine sampling), whatever wi.
TEST(EvalCli, LambertianByAnglesIsAlbedoOverPi) {
  const json printed =
      evalJson({R"({"type": "lambertian", "albedo": [0.2, 0.4, 0.6]})", "--wi", "30,0", "--wo", "60,135"});
  ASSERT_EQ(printed["values"].size(), 1u);
  const json& value = printed["values"][0];
  // Closed forms computed here in double: rounding differences only (a few ulps).
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(value["f"][c].get<double>(), 0.2 * (c + 1) / Pi, 1e-15);
  EXPECT_NEAR(value["pdf"].get<double>(), std::cos(radians(60.0)) / Pi, 1e-15);
  EXPECT_NEAR(value["wi"][0].get<double>(), std::sin(radians(30.0)), 1e-15);
  EXPECT_NEAR(value["wo"][2].get<double>(), std::cos(radians(60.0)), 1e-15);
  EXPECT_EQ(printed["material"]["type"], "lambertian");
}

// Components with 6 significant digits (length 1 + 5e-6): accepted, and evaluated as the unit
// vector they stand for.
TEST(EvalCli, NearlyUnitDirectionsAreNormalised) {
  const fs::path file = writeInputFile("pairs.json", R"([{"wi": [0.6, 0, 0.800004], "wo": [0, 0, 1]}])");
  const json printed = evalJson({R"({"type": "lambertian"})", "--directions", file.string()});
  ASSERT_EQ(printed["values"].size(), 1u);
  EXPECT_NEAR(glm::length(vectorOf(printed["values"][0]["wi"])), 1.0, 1e-15);
}

TEST(EvalCli, TextOutputHasOneRowPerPair) {
  const fs::path file = writeInputFile("pairs.json", somePairs().dump());
  const ProcessResult run =
      runScatterlab({"eval", R"({"type": "conductor"})", "--directions", file.string()});
  ASSERT_EQ(run.exitCode, 0) << describe(run);
  size_t rows = 0;
  for (size_t at = run.out.find('\n'); at != std::string::npos; at = run.out.find('\n', at + 1)) ++rows;
  EXPECT_EQ(rows, 2 + somePairs().size()) << run.out;  // the material, the header, the pairs
  expectMentions(run.out, {"material: {", "pdf (1/sr)"});
}

// Every registry type at its defaults prints its model's own numbers, from a directions file.
TEST(EvalCli, EveryRegistryTypePrintsItsModelsValues) {
  const json pairs = somePairs();
  const fs::path file = writeInputFile("pairs.json", pairs.dump());
  for (const MaterialModel& model : materialModels()) {
    if (model.type == "measured") continue;  // needs a file: MeasuredTableByBarePathOrDescription
    const json material{{"type", model.type}};
    expectModelValues(material, pairs, evalJson({material.dump(), "--directions", file.string()}));
  }
}

// The far-field BRDF of a subsurface material: Ft(wi) Rd Ft(wo) / (pi c), so that f(wi, wo) /
// f(wo', wi') at equal cosines is 1 and the ratio of two values at one wi is the ratio of the
// transmittances at the two wo. Checked here against the profile's own total reflectance.
TEST(EvalCli, SubsurfaceGivesItsFarFieldBrdf) {
  const json material{{"type", "subsurface"}, {"medium", "Skin1"}, {"profile", "dipole"}};
  const json printed = evalJson({material.dump(), "--wi", "0,0", "--wo", "0,0"});
  const SubsurfaceMaterial subsurface = makeSubsurface(material);
  const double eta = subsurface.medium.eta, c = separableNormalization(eta);
  const double ft = 1.0 - fresnelDielectric(1.0, eta);
  const Rgb rd = subsurface.profile->totalReflectance();
  // Products of a few doubles: rounding only.
  for (int ch = 0; ch < 3; ++ch)
    EXPECT_NEAR(printed["values"][0]["f"][ch].get<double>(), ft * rd[ch] * ft / (Pi * c), 1e-14);
  EXPECT_NEAR(printed["values"][0]["pdf"].get<double>(), InvPi, 1e-15);
}

// A MERL table of a Lambertian holds albedo / pi in every cell: eval gives it back at any pair,
// whether the table is named bare or in a description.
TEST(EvalCli, MeasuredTableByBarePathOrDescription) {
  const LambertianBsdf lambert(Rgb(0.3, 0.5, 0.7));
  const MerlTable table = MeasurementSynthesizer({&lambert}, {}).synthesize();
  const fs::path file = uniquePath("lambert.binary");
  writeMerl(file, table);
  const json pairs = somePairs();
  const fs::path pairsFile = writeInputFile("pairs.json", pairs.dump());
  const json bare = evalJson({file.string(), "--directions", pairsFile.string()});
  const json described = evalJson(
      {json{{"type", "measured"}, {"file", file.string()}}.dump(), "--directions", pairsFile.string()});
  ASSERT_EQ(bare["values"].size(), pairs.size());
  EXPECT_EQ(bare["values"], described["values"]);
  for (size_t i = 0; i < pairs.size(); ++i) {
    const json& value = bare["values"][i];
    const bool reflection = value["wo"][2].get<double>() > 0;
    // The model holds the table's values as floats (tabulated_brdf.h), interpolating equal values:
    // the rounding to float, half an ulp, 2^-24 relative.
    for (int c = 0; c < 3; ++c) {
      const double expected = reflection ? lambert.albedo()[c] / Pi : 0.0;
      EXPECT_NEAR(value["f"][c].get<double>(), expected, 0x1p-24 * expected) << i;
    }
  }
  fs::remove(file);
}

// ---- Bad input -----------------------------------------------------------------------------

class EvalCliBadInput : public ::testing::Test {
 protected:
  void expectPairsRefused(const std::string& pairsJson, const std::vector<std::string>& fragments) {
    const fs::path file = writeInputFile("bad-pairs.json", pairsJson);
    expectBadInput({"eval", R"({"type": "lambertian"})", "--directions", file.string()},
                   std::vector<std::string>{"--directions file", file.string()} + fragments);
  }
};

TEST_F(EvalCliBadInput, NotUnitDirections) {
  expectPairsRefused(R"([{"wi": [0, 0, 1], "wo": [0, 0, 1]}, {"wi": [1, 0, 0.5], "wo": [0, 0, 1]}])",
                     {"[1].wi", "not a unit vector", "1.118", "allowed"});
  expectPairsRefused(R"([{"wi": [0, 0, 0], "wo": [0, 0, 1]}])", {"[0].wi", "not a unit vector"});
  // Ten times the tolerance (NearlyUnitDirectionsAreNormalised: within it is accepted).
  expectPairsRefused(R"([{"wi": [0, 0, 1.0001], "wo": [0, 0, 1]}])", {"[0].wi", "length 1.0001"});
}

TEST_F(EvalCliBadInput, WrongShapes) {
  expectPairsRefused(R"([{"wi": [0, 1], "wo": [0, 0, 1]}])", {"[0].wi", "not an array of 3 numbers"});
  expectPairsRefused(R"([{"wi": [0, "1", 0], "wo": [0, 0, 1]}])", {"[0].wi", "not a number"});
  expectPairsRefused(R"([{"wi": [0, 0, 1]}])", {"[0]", "has no \"wo\""});
  expectPairsRefused(R"([{"wi": [0, 0, 1], "wo": [0, 0, 1], "w": 1}])", {"[0].w", "not a key"});
  expectPairsRefused(R"([[0, 0, 1]])", {"[0]", "not an object"});
  expectPairsRefused(R"({"wi": [0, 0, 1], "wo": [0, 0, 1]})", {"directions", "not an array"});
  expectPairsRefused(R"([])", {"directions", "is empty"});
  // A number too large for a double is refused by the JSON reader.
  expectPairsRefused(R"([{"wi": [0, 0, 1e999], "wo": [0, 0, 1]}])", {"not valid JSON", "1e999"});
}

TEST_F(EvalCliBadInput, NaNIsNotJson) {
  expectPairsRefused(R"([{"wi": [NaN, 0, 1], "wo": [0, 0, 1]}])", {"not valid JSON", "line 1"});
}

TEST_F(EvalCliBadInput, DirectionsFileAndAngles) {
  const std::string lambert = R"({"type": "lambertian"})";
  expectBadInput({"eval", lambert, "--directions", uniquePath("missing.json").string()},
                 {"--directions", "not found"});
  expectBadInput({"eval", lambert, "--directions", testOutputDir().string()},
                 {"--directions", "is a directory"});
  expectBadInput({"eval", lambert}, {"no directions given", "--wi THETA,PHI"});
  expectBadInput({"eval", lambert, "--wi", "30,0"}, {"--wo missing"});
  expectBadInput({"eval", lambert, "--wi", "200,0", "--wo", "0,0"},
                 {"--wi", "\"200,0\"", "THETA in [0, 180]"});
  expectBadInput({"eval", lambert, "--wi", "nan,0", "--wo", "0,0"}, {"--wi", "\"nan,0\"", "not a direction"});
  expectBadInput({"eval", lambert, "--wi", "30", "--wo", "0,0"}, {"--wi", "\"30\""});
  const fs::path file = writeInputFile("pairs.json", somePairs().dump());
  expectBadInput({"eval", lambert, "--directions", file.string(), "--wi", "0,0", "--wo", "0,0"},
                 {"--directions and --wi/--wo both given"});
}

TEST_F(EvalCliBadInput, Materials) {
  expectBadInput({"eval", R"({"type": "conductor", "alpha": 2})", "--wi", "0,0", "--wo", "0,0"},
                 {"\"alpha\"", "2", "[0.001, 1]"});
  expectBadInput({"eval", uniquePath("missing-material.json").string(), "--wi", "0,0", "--wo", "0,0"},
                 {"not found"});
  // A file that is not JSON is read as a measured table, whose reader refuses it by name.
  const fs::path notATable = writeInputFile("not-a-table.binary", "this is not a table");
  expectBadInput({"eval", notATable.string(), "--wi", "0,0", "--wo", "0,0"},
                 {notATable.string(), "\"file\""});
  expectBadInput({"eval"}, {"material"});
}

}  // namespace eval_cli_test
}  // namespace scatterlab

namespace scatterlab {
namespace eval_cli_test {

using nlohmann::json;
namespace fs = std::filesystem;
using namespace cli_runner;

// `scatterlab eval` on the two real RGL files reproduces the reference reader's own values
// (rgl-epfl/brdf-loader in float32, data/rgl/NAME.ref.json) at all 256 pairs: f cos(theta_o),
// the reader's convention, and the pdf. The tolerance is tests/materials/measured/
// rgl_reference_test.cpp's: 2e-3 relative, with a float32 floor of 1e-6 of the pair's largest
// channel where a value is clipped to 0 or outside the lobe's support.
TEST(EvalCli, RglFilesReproduceTheReferenceReadersValues) {
  constexpr double RelativeTolerance = 2e-3, Float32Floor = 1e-6;
  const fs::path rgl = fs::path(SCATTERLAB_DATA_DIR) / "rgl";
  for (const std::string name : {"acrylic_felt_green_rgb", "cc_ibiza_sunset_rgb"}) {
    std::ifstream in(rgl / (name + ".ref.json"));
    const json reference = json::parse(in).at("eval");
    json pairs = json::array();
    for (const json& pair : reference) pairs.push_back({{"wi", pair.at("wi")}, {"wo", pair.at("wo")}});
    const fs::path directions = uniquePath("rgl-pairs");
    std::ofstream(directions) << pairs.dump();
    const json out = evalJson({(rgl / (name + ".bsdf")).string(), "--directions", directions.string()});
    ASSERT_EQ(out.at("values").size(), reference.size()) << name;
    for (size_t i = 0; i < reference.size(); ++i) {
      const json& expected = reference[i];
      const json& value = out.at("values")[i];
      const double cosThetaO = expected.at("wo")[2].get<double>();
      double scale = 0;
      for (int c = 0; c < 3; ++c) scale = std::max(scale, expected.at("f")[c].get<double>());
      for (int c = 0; c < 3; ++c) {
        const double got = value.at("f")[c].get<double>() * cosThetaO,
                     want = expected.at("f")[c].get<double>();
        EXPECT_LE(std::abs(got - want),
                  RelativeTolerance * std::max(std::abs(got), std::abs(want)) + Float32Floor * scale)
            << name << " pair " << i << " channel " << c;
      }
      const double pdf = value.at("pdf").get<double>(), wantPdf = expected.at("pdf").get<double>();
      EXPECT_LE(std::abs(pdf - wantPdf), RelativeTolerance * std::max(pdf, wantPdf)) << name << " pair " << i;
    }
  }
}

}  // namespace eval_cli_test
}  // namespace scatterlab
