// The "measured" material type in the registry: it needs its file, names the file when it
// is bad, resolves a relative path against the material file's directory, and is listed
// with a "path" parameter.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

#include "materials/measured/tabulated_brdf.h"
#include "materials/registry/material_file.h"
#include "materials/registry/model_list.h"
#include "materials/registry/spec_validation.h"
#include "measured_test_support.h"

namespace scatterlab {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;
using measured_test::scratchPath;

std::string buildErrorOf(const json& material) {
  try {
    makeBsdf(material);
  } catch (const MaterialError& error) {
    return error.what();
  }
  return "";
}

TEST(MeasuredMaterial, NeedsItsFile) {
  const std::string message = buildErrorOf(json{{"type", "measured"}});
  EXPECT_NE(message.find("material key \"file\" is missing"), std::string::npos) << message;
  EXPECT_NE(buildErrorOf(json{{"type", "measured"}, {"file", 3}}).find("has the wrong type"),
            std::string::npos);
  EXPECT_NE(buildErrorOf(json{{"type", "measured"}, {"file", ""}}).find("is empty"), std::string::npos);
}

TEST(MeasuredMaterial, ABadFileIsNamedWithItsProblem) {
  const fs::path path = scratchPath("bad") += ".binary";
  std::ofstream(path) << "not a table";
  const std::string message = buildErrorOf(json{{"type", "measured"}, {"file", path.string()}});
  EXPECT_NE(message.find("material key \"file\""), std::string::npos) << message;
  EXPECT_NE(message.find(path.string()), std::string::npos) << message;
  EXPECT_NE(message.find("truncated"), std::string::npos) << message;
  fs::remove(path);
}

TEST(MeasuredMaterial, RelativeFileResolvesAgainstTheMaterialFile) {
  const fs::path dir = scratchPath("materials");
  fs::create_directories(dir / "tables");
  writeMerl(dir / "tables" / "white.binary", measured_test::synthesise({json{{"type", "lambertian"}}}).table);
  std::ofstream(dir / "white.json") << R"({"type": "measured", "file": "tables/white.binary"})";
  const json material = loadMaterialArgument((dir / "white.json").string());
  EXPECT_EQ(material["file"], (dir / "tables" / "white.binary").string());
  const auto model = makeBsdf(material);
  EXPECT_NEAR(model->eval(directionFromDegrees(20, 0), directionFromDegrees(50, 100)).x, 0.8 * InvPi, 1e-6);
  // Absolute paths and inline JSON are left as they are.
  const json inlineMaterial = loadMaterialArgument(R"({"type": "measured", "file": "tables/white.binary"})");
  EXPECT_EQ(inlineMaterial["file"], "tables/white.binary");
  fs::remove_all(dir);
}

TEST(MeasuredMaterial, IsListedWithAPathParameter) {
  const json catalog = materialCatalogJson();
  const auto measured =
      std::find_if(catalog.begin(), catalog.end(), [](const json& m) { return m["type"] == "measured"; });
  ASSERT_NE(measured, catalog.end());
  ASSERT_EQ((*measured)["parameters"].size(), 1u);
  EXPECT_EQ((*measured)["parameters"][0]["name"], "file");
  EXPECT_EQ((*measured)["parameters"][0]["kind"], "path");
  EXPECT_TRUE((*measured)["parameters"][0]["default"].is_null());
  EXPECT_EQ(completeMaterial(json{{"type", "measured"}, {"file", "x.binary"}}),
            (json{{"type", "measured"}, {"file", "x.binary"}}));
  EXPECT_FALSE(withScaledRoughness(json{{"type", "measured"}, {"file", "x.binary"}}, 1.1).has_value());
}

}  // namespace
}  // namespace scatterlab
