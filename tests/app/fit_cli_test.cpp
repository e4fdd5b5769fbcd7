// `scatterlab fit`, end to end: a good fit is printed and written as registry JSON that the
// registry and `check` accept; a poor fit (not converged, too large an error, no registry
// form) is reported and not written (exit 1); bad input gets one message naming the option,
// file or value (exit 2) and nothing is written.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "cli_runner.h"
#include "fit_report.h"
#include "materials/bsdf/metals.h"
#include "materials/measured/merl_io.h"
#include "materials/registry/spec_validation.h"

namespace scatterlab {
namespace fit_cli_test {

using nlohmann::json;
namespace fs = std::filesystem;
using namespace cli_runner;

// lambertian 0.2 + Cook-Torrance (albedo 0.2, F0 0.3, roughness 0.1), as one registry material.
const std::string Truth = R"({"type":"blend","weight":0.5,"materials":[{"type":"lambertian","albedo":0.4},)"
                          R"({"type":"ngan-cook-torrance","albedo":0.4,"eta":0.3,"roughness":0.1}]})";
const std::vector<std::string> Quick{"--samples", "20000", "--grid-points", "64", "--starts", "2"};

fs::path fitFile() { return fs::path(SCATTERLAB_DATA_DIR) / "published-fits" / "ngan_cooktorrance.fit"; }

TEST(FitCli, HelpListsEveryOption) {
  const ProcessResult run = runScatterlab({"fit", "--help"});
  EXPECT_EQ(run.exitCode, 0) << describe(run);
  for (const char* option : {"--model", "--metric", "--lobes", "--robust", "--robust-scale", "--per-channel",
                             "--samples", "--seed", "--starts", "--grid-points", "--max-iterations",
                             "--max-relative-error", "--threads", "--out", "--json"})
    EXPECT_NE(run.out.find(option), std::string::npos) << option;
}

TEST(FitCli, GoodFitIsPrintedAndWrittenAsARegistryMaterial) {
  const fs::path out = uniquePath("fit") += ".json";
  const ProcessResult run =
      runScatterlab(std::vector<std::string>{"fit", Truth, "--model", "lambertian+ngan-cook-torrance",
                                             "--metric", "ngan", "--out", out.string()} +
                    Quick);
  ASSERT_EQ(run.exitCode, 0) << describe(run);
  expectMentions(run.out, {"ngan-cook-torrance.roughness", "std dev", "sigma^2", "relative error",
                           "iterations", "CONVERGENCE", "verdict: GOOD", "wrote " + out.string()});
  const json material = json::parse(readFile(out));
  EXPECT_NO_THROW(makeBsdf(material));
  EXPECT_EQ(material, completeMaterial(material));  // written complete
  // `check` accepts it as it is (a few thousand samples: a smoke test of the handover).
  const ProcessResult check =
      runScatterlab({"check", out.string(), "--samples", "20000", "--grid", "16x32", "--wi-theta", "0,60"});
  EXPECT_EQ(check.exitCode, 0) << describe(check);
  fs::remove(out);
}

TEST(FitCli, JsonReportHoldsTheParametersTheMaterialAndTheVerdict) {
  const ProcessResult run =
      runScatterlab(std::vector<std::string>{"fit", Truth, "--model", "lambertian+ngan-cook-torrance",
                                             "--metric", "low-log", "--json"} +
                    Quick);
  ASSERT_EQ(run.exitCode, 0) << describe(run);
  const json report = json::parse(run.out);
  EXPECT_EQ(report.at("verdict"), "good");
  EXPECT_EQ(report.at("fit").at("metric"), "low-log");
  EXPECT_TRUE(report.at("fit").at("converged").get<bool>());
  // Noise-free data from the model itself: recovered (1e-4 as recovery_test.cpp).
  EXPECT_NEAR(fittedParameter(report, "ngan-cook-torrance.roughness"), 0.1, 1e-5);
  EXPECT_NEAR(fittedParameter(report, "lambertian.albedo.g"), 0.2, 2e-5);
  EXPECT_EQ(report.at("material").at("type"), "blend");
  EXPECT_TRUE(report.at("written").is_null());
  EXPECT_EQ(report.at("data").at("kind"), "material");
}

TEST(FitCli, SameResultForAnyThreadCount) {
  const auto fitWith = [&](const std::string& threads) {
    const ProcessResult run =
        runScatterlab(std::vector<std::string>{"fit", Truth, "--model",
                                               R"(lambertian+{"type":"conductor","eta":1,"k":1e8})",
                                               "--metric", "cube-root", "--json", "--threads", threads} +
                      Quick);
    EXPECT_EQ(run.exitCode, 0) << describe(run);
    return json::parse(run.out).at("fit").at("parameters");
  };
  EXPECT_EQ(fitWith("1"), fitWith("2"));
}

// A measured-style MERL file with noise and missing grazing cells.
TEST(FitCli, FitsANoisyMerlFileWithMissingCells) {
  const fs::path table = uniquePath("bronze") += ".binary";
  const ProcessResult synth =
      runScatterlab({"synth", "--fit", fitFile().string(), "--name", "alum-bronze", "--out", table.string(),
                     "--log-noise", "0.05", "--missing-above", "80"});
  ASSERT_EQ(synth.exitCode, 0) << describe(synth);
  const ProcessResult run =
      runScatterlab(std::vector<std::string>{"fit", table.string(), "--model",
                                             "lambertian+ngan-cook-torrance", "--metric", "ngan", "--json"} +
                    Quick);
  ASSERT_EQ(run.exitCode, 0) << describe(run);
  const json report = json::parse(run.out);
  EXPECT_GT(report.at("data").at("missing_cells").get<size_t>(), 100000u);
  EXPECT_EQ(report.at("data").at("kind"), "merl");
  // 5% log-normal noise: the roughness within 1% of the line's 0.0367.
  EXPECT_NEAR(fittedParameter(report, "ngan-cook-torrance.roughness"), 0.0367, 0.01 * 0.0367);
  fs::remove(table);
}

// A GGX copper table made by `synth`, fitted back by a conductor that names neither the metal
// nor an index (its index fitted as f0 and edge tint): alpha and the normal-incidence
// reflectance within 1% (the data are noise-free), from the default grid and starts.
TEST(FitCli, CopperTableRecoversAlphaAndIndexWithoutNamingTheMetal) {
  const fs::path table = uniquePath("copper") += ".binary";
  const fs::path out = uniquePath("copper-fit") += ".json";
  ASSERT_EQ(
      runScatterlab({"synth", R"({"type":"conductor","metal":"Cu","alpha":0.17})", "--out", table.string()})
          .exitCode,
      0);
  const ProcessResult run = runScatterlab({"fit", table.string(), "--model", "conductor", "--metric", "ngan",
                                           "--samples", "30000", "--out", out.string(), "--json"});
  ASSERT_EQ(run.exitCode, 0) << describe(run);
  const json report = json::parse(run.out);
  EXPECT_NEAR(fittedParameter(report, "conductor.alpha"), 0.17, 0.01 * 0.17);
  const MetalIor& copper = *findMetal("Cu");
  const json written = json::parse(readFile(out));
  const char* channel[] = {"r", "g", "b"};
  for (int c = 0; c < 3; ++c) {
    const auto reflectance = [](double eta, double k) {
      return (sqr(eta - 1) + k * k) / (sqr(eta + 1) + k * k);
    };
    const double truth = reflectance(copper.eta[c], copper.k[c]);
    EXPECT_NEAR(fittedParameter(report, std::string("conductor.f0.") + channel[c]), truth, 0.01 * truth) << c;
    // The written material holds eta and k with that reflectance, no "metal".
    EXPECT_NEAR(reflectance(written.at("eta")[c].get<double>(), written.at("k")[c].get<double>()), truth,
                0.01 * truth)
        << c;
  }
  EXPECT_FALSE(written.contains("metal"));
  fs::remove(table);
  fs::remove(out);
}

// An RGL file, told by its content: fitted on the pairs it tabulates.
TEST(FitCli, FitsAnRglFileOnItsOwnPairs) {
  const fs::path file = fs::path(SCATTERLAB_DATA_DIR) / "rgl" / "cc_ibiza_sunset_rgb.bsdf";
  const ProcessResult run =
      runScatterlab(std::vector<std::string>{"fit", file.string(), "--model", "lambertian+ngan-cook-torrance",
                                             "--metric", "ngan", "--json"} +
                    Quick);
  ASSERT_LE(run.exitCode, 1) << describe(run);  // a poor fit of real data is an honest outcome
  const json report = json::parse(run.out);
  EXPECT_EQ(report.at("data").at("kind"), "rgl");
  // 7 tabulated elevations below 90 degrees x 32 x 32 colour nodes, less those below the horizon.
  const size_t usable = report.at("data").at("usable_cells").get<size_t>();
  EXPECT_EQ(usable + report.at("data").at("unreachable_cells").get<size_t>(), 7u * 32u * 32u);
  EXPECT_GT(usable, 6000u);
  EXPECT_TRUE(report.at("fit").at("converged").get<bool>());
  const ProcessResult text =
      runScatterlab(std::vector<std::string>{"fit", file.string(), "--model", "lambertian+ngan-cook-torrance",
                                             "--metric", "ngan"} +
                    Quick);
  expectMentions(text.out, {"direction pairs the file tabulates", "weight 1 each", "below the horizon"});
}

TEST(FitCli, PoorFitIsReportedAndNotWritten) {
  const fs::path out = uniquePath("poor") += ".json";
  // A Lambertian cannot reproduce a highlight: its relative error (1.0) is far above the
  // default 0.7.
  const ProcessResult lambertian =
      runScatterlab(std::vector<std::string>{"fit", Truth, "--model", "lambertian", "--metric", "ngan",
                                             "--out", out.string()} +
                    Quick);
  EXPECT_EQ(lambertian.exitCode, 1) << describe(lambertian);
  expectMentions(lambertian.out, {"verdict: POOR", "relative error of channel",
                                  "exceeds --max-relative-error", "not written"});
  EXPECT_FALSE(fs::exists(out));
  // One iteration: Ceres stops before converging, and says so.
  const ProcessResult stopped = runScatterlab(
      std::vector<std::string>{"fit", Truth, "--model", "lambertian+ngan-cook-torrance", "--metric", "ngan",
                               "--max-iterations", "1", "--out", out.string()} +
      Quick);
  EXPECT_EQ(stopped.exitCode, 1) << describe(stopped);
  expectMentions(stopped.out, {"verdict: POOR", "did not converge: NO_CONVERGENCE", "iterations"});
  EXPECT_FALSE(fs::exists(out));
}

// colonial-maple-223's Lambertian and Cook-Torrance albedos add up to more than 1: the fit
// is exact but the sum has no registry form.
TEST(FitCli, SumWithoutARegistryFormIsPoor) {
  const fs::path table = uniquePath("maple") += ".binary";
  ASSERT_EQ(runScatterlab({"synth", "--fit", fitFile().string(), "--name", "colonial-maple-223", "--out",
                           table.string()})
                .exitCode,
            0);
  const ProcessResult run =
      runScatterlab(std::vector<std::string>{"fit", table.string(), "--model",
                                             "lambertian+ngan-cook-torrance", "--metric", "ngan"} +
                    Quick);
  EXPECT_EQ(run.exitCode, 1) << describe(run);
  expectMentions(run.out, {"verdict: POOR", "no registry material", "channel r"});
  fs::remove(table);
}

TEST(FitCli, BadInputNamesTheOptionFileOrValueAndWritesNothing) {
  const fs::path out = uniquePath("never") += ".json";
  const std::string o = out.string();
  const std::vector<std::string> fit{"fit", Truth, "--out", o};
  expectBadInput(fit + std::vector<std::string>{"--model", "lambertian+ggx", "--metric", "ngan"},
                 {"--model", "\"ggx\" is not a known model", "allowed", "ngan-cook-torrance"});
  expectBadInput(fit + std::vector<std::string>{"--model", "dielectric", "--metric", "ngan"},
                 {"--model", "\"dielectric\" cannot be fitted", "delta"});
  expectBadInput(fit + std::vector<std::string>{"--model", "lambertian", "--metric", "l1"},
                 {"--metric", "\"l1\" is not a metric", "\"low-log\""});
  expectBadInput(
      fit + std::vector<std::string>{"--model", "lambertian", "--metric", "ngan", "--robust", "tukey"},
      {"--robust", "\"tukey\" is not a robust loss", "\"cauchy\""});
  expectBadInput(fit + std::vector<std::string>{"--model", "lambertian", "--metric", "ngan", "--lobes", "4"},
                 {"--lobes", "out of range", "[1, 3]"});
  expectBadInput(
      fit + std::vector<std::string>{"--model", "lambertian", "--metric", "ngan", "--robust-scale", "0.1"},
      {"--robust-scale", "--robust"});
  expectBadInput({"fit", Truth, "--model", "lambertian"}, {"--metric", "required"});
  expectBadInput(
      {"fit", (testOutputDir() / "absent.binary").string(), "--model", "lambertian", "--metric", "ngan"},
      {"absent.binary", "not found", "allowed"});
  expectBadInput({"fit", R"({"type":"lambertian","albedo":2})", "--model", "lambertian", "--metric", "ngan"},
                 {"albedo", "out of range"});
  expectBadInput(fit + std::vector<std::string>{"--model", "lambertian+conductor", "--metric", "ngan"},
                 {"--model", "fitted alone", R"({"type":"conductor","eta":1,"k":1e8})"});
  // An RGL file cut short: the file and the field whose data runs past the end.
  const fs::path truncated = uniquePath("truncated") += ".bsdf";
  const std::string rgl = readFile(fs::path(SCATTERLAB_DATA_DIR) / "rgl" / "cc_ibiza_sunset_rgb.bsdf");
  std::ofstream(truncated, std::ios::binary) << rgl.substr(0, rgl.size() / 2);
  expectBadInput({"fit", truncated.string(), "--model", "lambertian", "--metric", "ngan", "--out", o},
                 {truncated.string(), "field \"", "runs past the end"});
  fs::remove(truncated);
  // Missing parents are created (as everywhere); a file in their place is found before the fit.
  const fs::path blocker = uniquePath("blocker");
  std::ofstream(blocker) << "a file";
  expectBadInput({"fit", Truth, "--model", "lambertian", "--metric", "ngan", "--out",
                  (blocker / "sub" / "x.json").string()},
                 {"--out", "cannot create the directory"});
  EXPECT_FALSE(fs::exists(out));
}

TEST(FitCli, TableWithoutValidCellsIsBadInput) {
  const fs::path table = uniquePath("empty") += ".binary";
  MerlTable empty;
  for (size_t cell = 0; cell < merl::CellCount; ++cell) empty.setMissing(cell);
  writeMerl(table, empty);
  expectBadInput({"fit", table.string(), "--model", "lambertian", "--metric", "ngan"},
                 {table.string(), "no valid cells", "missing"});
  fs::remove(table);
}

}  // namespace fit_cli_test
}  // namespace scatterlab
