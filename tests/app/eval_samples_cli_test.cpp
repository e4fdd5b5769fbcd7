// `scatterlab eval --samples FILE`: what a material's sampler returns for given incident
// directions and random numbers, in full precision, for every registry type; and bad queries
// and option combinations (exit 2, one message naming the key or option and what is allowed).
#include <gtest/gtest.h>

#include <fstream>

#include <nlohmann/json.hpp>

#include "cli_runner.h"
#include "materials/bssrdf/subsurface_registry.h"
#include "materials/core/spherical.h"
#include "materials/registry/model_list.h"

namespace scatterlab {
namespace eval_samples_cli_test {

using nlohmann::json;
namespace fs = std::filesystem;
using namespace cli_runner;

json vectorJson(const Vec3d& v) { return json::array({v.x, v.y, v.z}); }
Vec3d vectorOf(const json& v) { return {v[0].get<double>(), v[1].get<double>(), v[2].get<double>()}; }

// Queries at normal, oblique and grazing incidence, with random numbers that pick every lobe of
// a two-lobe model (u_lobe low and high).
json someQueries() {
  json queries = json::array();
  const double rows[][5] = {{0, 0, 0.1, 0.2, 0.3},
                            {30, 20, 0.9, 0.7, 0.05},
                            {60, 0, 0.5, 0.5, 0.5},
                            {85, 45, 0.2, 0.95, 0.6},
                            {45, 10, 0.99, 0.01, 0.99}};
  for (const auto& r : rows)
    queries.push_back({{"wi", vectorJson(directionFromDegrees(r[0], r[1]))},
                       {"u_lobe", r[2]},
                       {"u", json::array({r[3], r[4]})}});
  return queries;
}

// Every registry type at its defaults prints exactly what its model's sample() returns in this
// process at the incident directions the executable reports (JSON round-trips a double exactly).
TEST(EvalSamplesCli, EveryRegistryTypePrintsItsSamplersValues) {
  const json queries = someQueries();
  const fs::path file = writeInputFile("samples.json", queries.dump());
  for (const MaterialModel& entry : materialModels()) {
    if (entry.type == "measured") continue;  // needs a file; the measured sampler has its own tests
    const json material{{"type", entry.type}};
    const ProcessResult run = runScatterlab({"eval", "--json", material.dump(), "--samples", file.string()});
    ASSERT_EQ(run.exitCode, 0) << describe(run);
    const json printed = json::parse(run.out).at("samples");
    ASSERT_EQ(printed.size(), queries.size()) << material;
    const auto model = makeFarFieldBsdf(material);
    for (size_t i = 0; i < queries.size(); ++i) {
      const json& row = printed[i];
      const Vec3d wi = vectorOf(row["wi"]);
      const Vec2d u(row["u"][0].get<double>(), row["u"][1].get<double>());
      const std::optional<BsdfSample> s = model->sample(wi, row["u_lobe"].get<double>(), u);
      ASSERT_EQ(row["valid"].get<bool>(), s.has_value()) << material << " query " << i;
      if (!s) continue;
      for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(row["wo"][c].get<double>(), s->wo[c]) << material << " query " << i;
        EXPECT_EQ(row["weight"][c].get<double>(), s->weight[c]) << material << " query " << i;
      }
      EXPECT_EQ(row["pdf"].get<double>(), s->pdf) << material << " query " << i;
      EXPECT_EQ(row["delta"].get<bool>(), s->isDelta()) << material << " query " << i;
    }
  }
}

// A smooth mirror at 30 degrees: the one sample is the mirror direction, a delta lobe of
// probability 1.
TEST(EvalSamplesCli, SmoothConductorSamplesTheMirrorDirection) {
  const fs::path file = writeInputFile(
      "samples.json",
      json::array({{{"wi", vectorJson(directionFromDegrees(30, 0))}, {"u_lobe", 0.5}, {"u", {0.5, 0.5}}}})
          .dump());
  const ProcessResult run =
      runScatterlab({"eval", "--json", R"({"type": "smooth-conductor"})", "--samples", file.string()});
  ASSERT_EQ(run.exitCode, 0) << describe(run);
  const json row = json::parse(run.out)["samples"][0];
  EXPECT_TRUE(row["valid"].get<bool>());
  EXPECT_TRUE(row["delta"].get<bool>());
  const Vec3d mirror = directionFromDegrees(30, 180);
  // The reflection is computed from the normalised wi: rounding only.
  EXPECT_LT(glm::length(vectorOf(row["wo"]) - mirror), 1e-15);
}

TEST(EvalSamplesCli, TextOutputHasOneRowPerQuery) {
  const fs::path file = writeInputFile("samples.json", someQueries().dump());
  const ProcessResult run = runScatterlab({"eval", R"({"type": "lambertian"})", "--samples", file.string()});
  ASSERT_EQ(run.exitCode, 0) << describe(run);
  size_t rows = 0;
  for (size_t at = run.out.find('\n'); at != std::string::npos; at = run.out.find('\n', at + 1)) ++rows;
  EXPECT_EQ(rows, 2 + someQueries().size()) << run.out;  // the material, the header, the queries
  expectMentions(run.out, {"material: {", "u_lobe", "weight_r"});
}

void expectQueriesRefused(const std::string& text, const std::vector<std::string>& fragments) {
  const fs::path file = writeInputFile("samples.json", text);
  expectBadInput({"eval", R"({"type": "lambertian"})", "--samples", file.string()},
                 std::vector<std::string>{"--samples file", file.string()} + fragments);
}

TEST(EvalSamplesCli, BadQueriesAreRefusedNamingTheKey) {
  expectQueriesRefused(R"([])", {"samples", "is empty"});
  expectQueriesRefused(R"({"wi": [0, 0, 1]})", {"samples", "not an array"});
  expectQueriesRefused(R"([{"wi": [0, 0, 1], "u_lobe": 0.5}])", {"[0]", "has no \"u\""});
  expectQueriesRefused(R"([{"wi": [0, 0, 1], "u_lobe": 1.0, "u": [0, 0]}])", {"[0].u_lobe", "[0, 1)"});
  expectQueriesRefused(R"([{"wi": [0, 0, 1], "u_lobe": 0, "u": [0, -0.1]}])", {"[0].u[1]", "[0, 1)"});
  expectQueriesRefused(R"([{"wi": [0, 0, 1], "u_lobe": 0, "u": [0]}])", {"[0].u", "2 numbers"});
  expectQueriesRefused(R"([{"wi": [0, 0, 2], "u_lobe": 0, "u": [0, 0]}])", {"[0].wi", "unit vector"});
  expectQueriesRefused(R"([{"wi": [0, 0, 1], "u_lobe": 0, "u": [0, 0], "mode": 1}])",
                       {"[0].mode", "not a key"});
}

TEST(EvalSamplesCli, SamplesWithDirectionsOrAnglesIsRefused) {
  const fs::path file = writeInputFile("samples.json", someQueries().dump());
  expectBadInput(
      {"eval", R"({"type": "lambertian"})", "--samples", file.string(), "--wi", "0,0", "--wo", "0,0"},
      {"--samples and --wi/--wo both given"});
  expectBadInput(
      {"eval", R"({"type": "lambertian"})", "--samples", file.string(), "--directions", file.string()},
      {"--samples and --directions both given"});
}

}  // namespace eval_samples_cli_test
}  // namespace scatterlab
