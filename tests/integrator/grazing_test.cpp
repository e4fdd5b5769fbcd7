// No non-finite pixel for any catalog material at grazing views (docs/validation.md section 7):
// every example BSDF of data/materials, every BSDF model's defaults, and a measured table,
// rendered where almost every camera ray grazes the surface (a narrow view of the sphere's
// silhouette, and a ground plane seen from 0.01 units above), under a map with a very bright
// pixel. The film drops and counts non-finite samples; here none may occur. (Subsurface
// materials are BSSRDFs, which the renderer does not take yet.)
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "integrator/render.h"
#include "materials/measured/measurement_synthesis.h"
#include "materials/measured/merl_io.h"
#include "materials/registry/material_file.h"
#include "materials/registry/model_list.h"
#include "materials/registry/spec_validation.h"
#include "render_test_support.h"

namespace scatterlab {
namespace grazing_test {

using nlohmann::json;
using namespace render_test;
namespace fs = std::filesystem;

struct CatalogEntry {
  std::string name;
  json material;
};

bool isBsdf(const json& material) {
  const MaterialModel* model = findMaterialModel(material.value("type", std::string()));
  return model && model->kind == MaterialKind::Bsdf;
}

std::vector<CatalogEntry> catalog() {
  std::vector<CatalogEntry> out;
  for (const auto& file : fs::directory_iterator(fs::path(SCATTERLAB_DATA_DIR) / "materials"))
    if (file.path().extension() == ".json") {
      const json material = loadMaterialArgument(file.path());
      if (isBsdf(material)) out.push_back({file.path().stem().string(), material});
    }
  for (const MaterialModel& model : materialModels())
    if (model.type != "measured" && model.kind == MaterialKind::Bsdf)
      out.push_back({model.type + " (defaults)", {{"type", model.type}}});
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.name < b.name; });
  return out;
}

// A map with a pixel of radiance 1e4 (a sun) over a dim sky.
Environment harshMap() {
  Image map = smoothSkyMap(16);
  map.setRgb(20, 5, Rgb(1e4));
  return Environment::fromMap(map);
}

void expectFinite(const RenderResult& result, const std::string& what) {
  EXPECT_EQ(result.statistics.droppedSamples(), 0u) << what;
  // The view does show the surface: at least a third of the camera rays meet it.
  EXPECT_GT(result.statistics.vertices, result.statistics.samples / 3) << what;
  for (float v : result.color.data()) {
    ASSERT_TRUE(std::isfinite(v)) << what;
    ASSERT_GE(v, 0.0f) << what;
  }
}

void renderGrazing(const std::string& name, const json& material) {
  const Environment env = harshMap();
  RenderSettings settings = settingsWith(4, 9, false);
  settings.albedoLayer = true;
  // The sphere's right silhouette (seen from 4 units away it is asin(1/4) off the centre, at
  // x = 4 / sqrt(15) on the plane y = 0) through a 2 degree field of view: every pixel within
  // 0.07 units of the rim, where camera rays meet the surface at up to 90 degrees.
  Scene rim;
  rim.addSphere(presetSphere(), rim.addMaterial(makeBsdf(material)));
  rim.setEnvironment(env);
  rim.setCamera(PinholeCamera::lookAt(Vec3d(0, -4, 0), Vec3d(4.0 / std::sqrt(15.0), 0, 0), Vec3d(0, 0, 1),
                                      2.0, 16, 16));
  expectFinite(render(rim, settings), name + " at the sphere's rim");
  // A ground plane seen from just above, and a sphere lying on it.
  Scene ground;
  const int id = ground.addMaterial(makeBsdf(material));
  ground.addPlane(Plane{Vec3d(0.0), Vec3d(0, 0, 1), Vec3d(1, 0, 0)}, id);
  ground.addSphere(Sphere{Vec3d(0, 30, 1), 1.0}, id);
  ground.setEnvironment(env);
  ground.setCamera(PinholeCamera::lookAt(Vec3d(0, 0, 0.01), Vec3d(0, 30, 0.0), Vec3d(0, 0, 1), 10.0, 16, 16));
  expectFinite(render(ground, settings), name + " on a grazing ground plane");
}

TEST(Grazing, EveryCatalogMaterialStaysFinite) {
  const std::vector<CatalogEntry> entries = catalog();
  EXPECT_GE(entries.size(), 40u);
  for (const CatalogEntry& entry : entries) renderGrazing(entry.name, entry.material);
}

TEST(Grazing, MeasuredMaterialStaysFinite) {
  // A measured table of a glossy conductor with missing cells beyond 80 degrees: the
  // tabulated model's grazing fill-in and its sampler's mixture take part.
  const auto model = makeBsdf({{"type", "conductor"}, {"alpha", 0.1}, {"metal", "Au"}});
  MeasurementPerturbation perturbation;
  perturbation.missingAboveDeg = 80.0;
  const MeasurementSynthesizer synthesizer({model.get()}, perturbation);
  const MerlTable table = synthesizer.synthesize();
  const fs::path file = scratchPath("gold") += ".binary";
  writeMerl(file, table);
  renderGrazing("measured", {{"type", "measured"}, {"file", file.string()}});
  fs::remove(file);
}

}  // namespace grazing_test
}  // namespace scatterlab
