// Published Ngan et al. fits: every line of the shipped files parses, maps to registry
// materials, and (within the registry's ranges) builds; malformed lines say where.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>

#include "materials/measured/ngan_fits.h"
#include "materials/registry/spec_validation.h"

namespace scatterlab {
namespace ngan_fits_test {

using nlohmann::json;
namespace fs = std::filesystem;

fs::path fitsDir() { return fs::path(SCATTERLAB_DATA_DIR) / "published-fits"; }

std::string errorOf(const std::string& line) {
  try {
    parsePublishedFitLine(line);
  } catch (const MaterialError& error) {
    return error.what();
  }
  return "";
}

TEST(PublishedFits, EveryShippedFileHasItsEightySixMaterials) {
  for (const char* file : {"ngan_cooktorrance.fit", "ngan_ward.fit", "ngan_ashikhminshirley.fit",
                           "ngan_blinnphong.fit", "ngan_lafortune.fit"}) {
    SCOPED_TRACE(file);
    const auto fits = readPublishedFits(fitsDir() / file);
    std::set<std::string> names;
    for (const PublishedFit& fit : fits) names.insert(fit.name);
    EXPECT_EQ(fits.size(), 86u);  // 86 of the 100 MERL materials have published fits
    EXPECT_EQ(names.size(), 86u);
    EXPECT_TRUE(names.contains("alum-bronze"));
  }
}

// Each line builds, except those whose values lie outside the registry's ranges, which are
// rejected with the registry's message (data/published-fits/README.md lists them).
TEST(PublishedFits, LinesBuildOrAreRejectedByTheRegistry) {
  std::set<std::string> rejected;
  for (const char* file : {"ngan_cooktorrance.fit", "ngan_ward.fit", "ngan_ashikhminshirley.fit",
                           "ngan_blinnphong.fit", "ngan_lafortune.fit"})
    for (const PublishedFit& fit : readPublishedFits(fitsDir() / file))
      for (const json& component : fit.components()) {
        try {
          makeBsdf(component);
        } catch (const MaterialError& error) {
          EXPECT_NE(std::string(error.what()).find("out of range"), std::string::npos) << error.what();
          rejected.insert(std::string(file) + ":" + fit.name);
        }
      }
  EXPECT_EQ(rejected.size(), 12u)
      << "5 Blinn-Phong sharpness > 1e5, 5 Lafortune sharpness > 1e4, 2 Lafortune albedo > 1";
  EXPECT_TRUE(rejected.contains("ngan_lafortune.fit:black-phenolic"));
  EXPECT_TRUE(rejected.contains("ngan_blinnphong.fit:specular-violet-phenolic"));
}

TEST(PublishedFits, CookTorranceLineMapsToTheNganType) {
  const PublishedFit fit = parsePublishedFitLine(
      "alum-bronze = Aggregate(Lambertian(albedo = [0.0886, 0.0602, 0.0299]), NganCookTorrance(albedo = "
      "[0.118, "
      "0.0698, 0.0371], eta = 0.203, roughness = 0.0367))");
  EXPECT_EQ(fit.name, "alum-bronze");
  EXPECT_EQ(fit.lobeModel, "NganCookTorrance");
  const auto components = fit.components();
  ASSERT_EQ(components.size(), 2u);
  EXPECT_EQ(components[0], (json{{"type", "lambertian"}, {"albedo", {0.0886, 0.0602, 0.0299}}}));
  EXPECT_EQ(components[1], (json{{"type", "ngan-cook-torrance"},
                                 {"albedo", {0.118, 0.0698, 0.0371}},
                                 {"eta", 0.203},
                                 {"roughness", 0.0367}}));
}

TEST(PublishedFits, LafortuneAndBlinnPhongMapToTheirRegistryTypes) {
  const auto lafortune =
      parsePublishedFitLine(
          "x = Aggregate(Lambertian(albedo = [0.1, 0.2, 0.3]), NganLafortune(albedo = [0.01, "
          "0.02, 0.03], Cxy = -0.577, Cz = 0.5, sharpness = 400.0))")
          .components();
  EXPECT_EQ(lafortune[1], (json{{"type", "lafortune"},
                                {"kd", 0.0},
                                {"ks", {0.01, 0.02, 0.03}},
                                {"cx", -0.577},
                                {"cy", -0.577},
                                {"cz", 0.5},
                                {"exponent", 400.0},
                                {"normalization", "ngan"}}));
  const auto blinn =
      parsePublishedFitLine(
          "y = Aggregate(Lambertian(albedo = [0.1, 0.2, 0.3]), NganBlinnPhong(albedo = [0.01, 0.02, "
          "0.03], sharpness = 5000))")
          .components();
  EXPECT_EQ(blinn[1],
            (json{{"type", "blinn-phong"}, {"kd", 0.0}, {"ks", {0.01, 0.02, 0.03}}, {"exponent", 5000}}));
}

TEST(PublishedFits, MalformedLinesSayWhatAndWhere) {
  EXPECT_NE(errorOf("no equals sign").find("name = Aggregate"), std::string::npos);
  EXPECT_NE(
      errorOf("x = Aggregate(Lambertian(albedo = [0.1, 0.2]), NganWard(albedo = [1,1,1], roughness = 0.1))")
          .find("\"albedo\" must be [r, g, b]"),
      std::string::npos);
  EXPECT_NE(errorOf("x = Aggregate(Lambertian(albedo = [0.1, 0.2, 0.3]), NganWard(albedo = [1,1,1]))")
                .find("\"roughness\" is missing"),
            std::string::npos);
  EXPECT_NE(errorOf("x = Aggregate(Lambertian(albedo = [0.1, 0.2, 0.3]), Fancy(a = 1))")
                .find("unknown lobe model \"Fancy\""),
            std::string::npos);
  const std::string column = errorOf(
      "x = Aggregate(Lambertian(albedo = [0.1, 0.2, 0.3]), NganWard(albedo = [1,1,1], "
      "roughness = abc))");
  EXPECT_NE(column.find("expected a finite number at column 92"), std::string::npos) << column;
}

TEST(PublishedFits, FileErrorsNameTheFileAndLine) {
  const fs::path dir = fs::path(SCATTERLAB_TEST_OUTPUT_DIR) / "published-fits";
  fs::create_directories(dir);
  const fs::path bad = dir / "bad.fit";
  std::ofstream(bad) << "# comment\n\nok = Aggregate(Lambertian(albedo = [0.1, 0.2, 0.3]), NganWard(albedo = "
                        "[0.1, 0.1, 0.1], roughness = 0.1))\nbroken = Aggregate(\n";
  try {
    readPublishedFits(bad);
    FAIL() << "no error";
  } catch (const MaterialError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find(bad.string()), std::string::npos) << message;
    EXPECT_NE(message.find("line 4"), std::string::npos) << message;
  }
  try {
    readPublishedFits(dir / "absent.fit");
    FAIL() << "no error";
  } catch (const MaterialError& error) {
    EXPECT_NE(std::string(error.what()).find("not found"), std::string::npos);
  }
}

}  // namespace ngan_fits_test
}  // namespace scatterlab
