// The "measured" material type in the registry: it needs its file, reads a MERL table or an RGL
// file told apart by content (under any name), names the file when it is bad, resolves a
// relative path against the material file's directory, and is listed with a "path" parameter.
// A bare path of a measured file is a material argument of its own.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

#include "materials/measured/measured_file.h"
#include "materials/measured/rgl_brdf.h"
#include "materials/measured/tabulated_brdf.h"
#include "materials/registry/material_file.h"
#include "materials/registry/model_list.h"
#include "materials/registry/spec_validation.h"
#include "measured_test_support.h"

namespace scatterlab {
namespace measured_registry_test {

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

const fs::path ShippedRgl = fs::path(SCATTERLAB_DATA_DIR) / "rgl" / "cc_ibiza_sunset_rgb.bsdf";

// A MERL table and an RGL file under names that say nothing (or the other format's extension).
struct DisguisedFiles {
  fs::path merl = scratchPath("merl-named-bsdf") += ".bsdf";
  fs::path rgl = scratchPath("rgl-named-binary") += ".binary";
  DisguisedFiles() {
    writeMerl(merl, measured_test::synthesise({json{{"type", "lambertian"}}}).table);
    fs::copy_file(ShippedRgl, rgl);
  }
  ~DisguisedFiles() {
    fs::remove(merl);
    fs::remove(rgl);
  }
};

TEST(MeasuredMaterial, FormatIsToldByContentNotByName) {
  const DisguisedFiles files;
  EXPECT_EQ(measuredFormatOf(files.merl), MeasuredFormat::Merl);
  EXPECT_EQ(measuredFormatOf(files.rgl), MeasuredFormat::Rgl);
  EXPECT_EQ(measuredFormatOf(fs::path(SCATTERLAB_DATA_DIR) / "rgl" / "README.md"), std::nullopt);
  EXPECT_EQ(measuredFormatOf(files.merl.parent_path() / "no-such-file"), std::nullopt);

  const auto merl = makeBsdf(json{{"type", "measured"}, {"file", files.merl.string()}});
  EXPECT_NE(dynamic_cast<const TabulatedBrdf*>(merl.get()), nullptr);
  const auto rgl = makeBsdf(json{{"type", "measured"}, {"file", files.rgl.string()}});
  const auto* rglModel = dynamic_cast<const RglBrdf*>(rgl.get());
  ASSERT_NE(rglModel, nullptr);
  EXPECT_EQ(rglModel->description(), "TeckWrap vinyl wrapping film (Ibiza Sunset RD02)");
  // The same model as the reader's own: eval agrees to the last bit.
  const auto direct = readRglBrdf(ShippedRgl);
  const Vec3d wi = directionFromDegrees(30, 10), wo = directionFromDegrees(35, 185);
  EXPECT_EQ(rgl->eval(wi, wo), direct->eval(wi, wo));
}

TEST(MeasuredMaterial, ABarePathIsAMeasuredMaterial) {
  const DisguisedFiles files;
  for (const fs::path& path : {files.merl, files.rgl, ShippedRgl})
    EXPECT_EQ(loadMaterialArgument(path.string()), (json{{"type", "measured"}, {"file", path.string()}}))
        << path;
}

TEST(MeasuredMaterial, ABadRglFileIsNamedWithItsField) {
  std::ifstream in(ShippedRgl, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const fs::path path = scratchPath("cut") += ".bsdf";
  std::ofstream(path, std::ios::binary) << bytes.substr(0, bytes.size() / 2);
  const std::string message = buildErrorOf(json{{"type", "measured"}, {"file", path.string()}});
  for (const std::string& fragment : {std::string("material key \"file\""), path.string(),
                                      std::string("field \""), std::string("RGL .bsdf")})
    EXPECT_NE(message.find(fragment), std::string::npos) << fragment << " not in " << message;
  fs::remove(path);
}

TEST(MeasuredMaterial, AFileThatIsNeitherJsonNorMeasuredSaysBoth) {
  const fs::path path = scratchPath("garbage") += ".binary";
  std::ofstream(path) << "garbage";
  std::string message;
  try {
    loadMaterialArgument(path.string());
  } catch (const MaterialError& error) {
    message = error.what();
  }
  for (const std::string& fragment :
       {path.string(), std::string("neither JSON"), std::string("truncated"), std::string("RGL .bsdf")})
    EXPECT_NE(message.find(fragment), std::string::npos) << fragment << " not in " << message;
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

}  // namespace measured_registry_test
}  // namespace scatterlab
