// `scatterlab check --render-agreement` through the real executable: a sound material's path,
// light and BDPT renders agree (app/render_agreement.h), and the option's bad input is refused.
// The agreement itself, on every registry model and with its negative controls, is tested in
// adjoint_agreement_test.cpp; this is the command's plumbing at a small sample count.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_runner.h"

namespace scatterlab {
namespace render_agreement_cli_test {

using nlohmann::json;
using namespace cli_runner;

// The kit's part of the check kept well under a second (few samples, a coarse grid, one angle);
// the renders at 16 x 12 pixels and 128 path-traced samples per pixel take about a second.
const std::vector<std::string> QuickRenderCheck{
    "--samples", "20000", "--grid", "16x32", "--wi-theta", "0", "--render-agreement", "128", "--json"};

TEST(RenderAgreementCli, LambertianRendersAgree) {
  const ProcessResult run =
      runScatterlab(std::vector<std::string>{"check", R"({"type":"lambertian"})"} + QuickRenderCheck);
  ASSERT_EQ(run.exitCode, 0) << describe(run);
  const json document = json::parse(run.out);
  EXPECT_EQ(document.at("options").at("render_agreement_spp"), 128);
  int renderRows = 0;
  for (const json& row : document.at("report").at("rows")) {
    const std::string test = row.at("test");
    if (test.rfind("render ", 0) != 0) continue;
    ++renderRows;
    EXPECT_TRUE(row.at("passed").get<bool>()) << row.dump();
    if (test == "render finite") {
      EXPECT_EQ(row.at("statistic"), 0.0) << row.dump();
      continue;
    }
    EXPECT_GE(row.at("dof").get<int>(), 1) << row.dump();
    EXPECT_GE(row.at("p_value").get<double>(), row.at("threshold").get<double>()) << row.dump();
    EXPECT_GT(row.at("threshold").get<double>(), 0.0) << row.dump();
    EXPECT_FALSE(row.at("note").get<std::string>().empty()) << row.dump();
  }
  // A Lambertian sphere: path-bdpt, path-light and bdpt-light on the ground, direct light on the
  // sphere (no delta lobe), no transmission; and the finite-sample row.
  EXPECT_EQ(renderRows, 5) << run.out;
}

TEST(RenderAgreementCli, SubsurfaceOnlyIsBadInput) {
  const ProcessResult run = runScatterlab({"check", R"({"type":"subsurface"})", "--render-agreement", "64"});
  EXPECT_EQ(run.exitCode, 2) << describe(run);
  EXPECT_NE(run.err.find("--render-agreement"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("BSDF"), std::string::npos) << run.err;
  EXPECT_TRUE(run.out.empty()) << run.out;
}

struct BadSpp {
  const char* what;
  const char* value;
};
void PrintTo(const BadSpp& bad, std::ostream* out) { *out << bad.what; }

class RenderAgreementBadSpp : public ::testing::TestWithParam<BadSpp> {};

TEST_P(RenderAgreementBadSpp, IsRefusedNamingTheValueAndTheRange) {
  const ProcessResult run =
      runScatterlab({"check", R"({"type":"lambertian"})", "--render-agreement", GetParam().value});
  EXPECT_EQ(run.exitCode, 2) << describe(run);
  for (const std::string& fragment :
       {std::string("--render-agreement"), "\"" + std::string(GetParam().value) + "\"",
        std::string("integer in [16, 65536]")})
    EXPECT_NE(run.err.find(fragment), std::string::npos) << "\"" << fragment << "\" missing from:\n"
                                                         << run.err;
  EXPECT_TRUE(run.out.empty()) << run.out;
}

INSTANTIATE_TEST_SUITE_P(Cli, RenderAgreementBadSpp,
                         ::testing::Values(BadSpp{"zero", "0"}, BadSpp{"too_few", "8"},
                                           BadSpp{"too_many", "1000000"}, BadSpp{"not_a_number", "many"}),
                         [](const ::testing::TestParamInfo<BadSpp>& info) {
                           return std::string(info.param.what);
                         });

}  // namespace render_agreement_cli_test
}  // namespace scatterlab
