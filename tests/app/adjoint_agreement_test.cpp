// The adjoint of every BSDF (docs/validation.md section 7) by the agreement of path tracing,
// light tracing and BDPT on the preview scene (app/render_agreement.h says why and how). Every
// model of the registry (materialModels(): the list `scatterlab models` prints) with its
// defaults, the measured model with a table synthesised from a GGX conductor; subsurface
// materials are BSSRDFs, which only the path tracer renders. Each pair of estimators x channel
// x model is one test at p < 0.01 / (count), Sidak. Negative controls: a wrapper whose
// importance mode applies the radiance rule 1/eta^2 (what forgetting the mode does) and one
// whose importance mode is 5% brighter must be rejected.
#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <iostream>
#include <mutex>

#include "app/render_agreement.h"
#include "integrator/render_test_support.h"
#include "materials/measured/measurement_synthesis.h"
#include "materials/measured/merl_io.h"
#include "materials/registry/model_list.h"
#include "validation/chi_square.h"

namespace scatterlab {
namespace adjoint_agreement_test {

using nlohmann::json;
using namespace render_test;

constexpr int Width = RenderAgreementWidth, Height = RenderAgreementHeight;

struct AdjointCase {
  std::string name;
  json material;
};
void PrintTo(const AdjointCase& c, std::ostream* out) { *out << c.name; }

// The measured model's table: a GGX gold conductor synthesised into MERL form once per run.
const std::string& measuredTable() {
  static const std::string path = [] {
    const auto model = makeBsdf({{"type", "conductor"}, {"alpha", 0.2}, {"metal", "Au"}});
    const MerlTable table = MeasurementSynthesizer({model.get()}, MeasurementPerturbation{}).synthesize();
    const std::filesystem::path file = scratchPath("adjoint-gold") += ".binary";
    writeMerl(file, table);
    return file.string();
  }();
  return path;
}

// Called when gtest registers the tests, not during static initialisation (the registry's
// specs are built from globals of its own translation unit).
std::vector<AdjointCase> registryCases() {
  std::vector<AdjointCase> out;
  for (const MaterialModel& model : materialModels()) {
    if (model.kind != MaterialKind::Bsdf) continue;
    json material{{"type", model.type}};
    if (model.type == "measured") material["file"] = measuredTable();
    std::string name = model.type;
    std::replace(name.begin(), name.end(), '-', '_');
    out.push_back({name, material});
  }
  return out;
}

double threshold() {
  static const double value =
      sidakSignificance(0.01, RenderAgreementTestsPerMaterial * int(registryCases().size()));
  return value;
}

void report(const std::string& what, const EstimatorPair& pair) {
  std::cout << "[ adjoint  ] " << what << " " << pair.name << ": worst channel chi2 " << pair.worst.chi2
            << " dof " << pair.worst.dof << " p " << pair.worst.pValue << "; " << pair.largest << "\n";
}

class AdjointAgreement : public ::testing::TestWithParam<AdjointCase> {};

TEST_P(AdjointAgreement, PathLightAndBdptAgree) {
  const json& material = GetParam().material;
  const RenderAgreement comparison =
      compareEstimators([&] { return makeBsdf(material); }, renderAgreementSeed(GetParam().name));
  EXPECT_EQ(comparison.droppedSamples(), 0u);
  const ConvergenceSpeed& speed = comparison.speed;
  std::cout << "[ speed    ] " << GetParam().name << ": seconds to 1% relative error per pixel ("
            << speed.pixels << " pixels): path " << speed.path << ", light " << speed.light << ", bdpt "
            << speed.bdpt << "; fastest " << speed.fastest() << "\n";
  for (const EstimatorPair& pair : comparison.pairs) {
    report(GetParam().name, pair);
    EXPECT_GE(pair.worst.pValue, threshold())
        << pair.name << ": chi2 " << pair.worst.chi2 << " dof " << pair.worst.dof;
    EXPECT_GE(pair.worst.dof, 1) << pair.name;
  }
}

std::string caseName(const ::testing::TestParamInfo<AdjointCase>& info) { return info.param.name; }
INSTANTIATE_TEST_SUITE_P(Grid, AdjointAgreement, ::testing::ValuesIn(registryCases()), caseName);

// ---- Negative controls: models whose importance mode is wrong.

// Forwards to `inner`, with importance mode replaced by `importance(mode)`'s result and scaled.
class WrongImportance final : public BsdfModel {
 public:
  WrongImportance(std::unique_ptr<BsdfModel> inner, bool radianceRule, double scale)
      : inner_(std::move(inner)), radianceRule_(radianceRule), scale_(scale) {}

  Rgb eval(const Vec3d& wi, const Vec3d& wo, TransportMode mode) const override {
    return inner_->eval(wi, wo, modeFor(mode)) * factor(mode);
  }
  double pdf(const Vec3d& wi, const Vec3d& wo, TransportMode mode) const override {
    return inner_->pdf(wi, wo, modeFor(mode));
  }
  std::optional<BsdfSample> sample(const Vec3d& wi, double uLobe, const Vec2d& u,
                                   TransportMode mode) const override {
    std::optional<BsdfSample> s = inner_->sample(wi, uLobe, u, modeFor(mode));
    if (s) s->weight *= factor(mode);
    return s;
  }
  LobeFlags flags() const override { return inner_->flags(); }
  double interiorIndex() const override { return inner_->interiorIndex(); }

 private:
  TransportMode modeFor(TransportMode mode) const { return radianceRule_ ? TransportMode::Radiance : mode; }
  double factor(TransportMode mode) const { return mode == TransportMode::Importance ? scale_ : 1.0; }

  std::unique_ptr<BsdfModel> inner_;
  bool radianceRule_;
  double scale_;
};

// True when some comparison rejects.
bool rejected(const std::string& what, const MaterialFactory& material) {
  bool any = false;
  for (const EstimatorPair& pair : compareEstimators(material, renderAgreementSeed(what)).pairs) {
    report(what, pair);
    any |= pair.worst.pValue < threshold();
  }
  return any;
}

// ---- Lights at infinity: the environment and the sun start light paths on the plane
// perpendicular to them (emission.h), the infinite ground included. The estimator agreement
// test's scene (a smooth sky map, a sphere light and a sun of 10 degrees), and the same with a
// delta sun, which BSDF sampling never finds; a Lambertian sphere. Path tracing, BDPT and
// light tracing (on reliable pixels, as above) agree pixel by pixel.
struct SkyCase {
  std::string name;
  double sunDegrees;
};
void PrintTo(const SkyCase& c, std::ostream* out) { *out << c.name; }

Scene skyScene(double sunDegrees) {
  Scene scene;
  scene.addSphere(presetSphere(), scene.addMaterial(makeBsdf({{"type", "lambertian"}, {"albedo", 0.7}})));
  const int ground = scene.addCheckerMaterial(makeBsdf({{"type", "lambertian"}, {"albedo", 0.7}}),
                                              makeBsdf({{"type", "lambertian"}, {"albedo", 0.3}}), 0.5);
  scene.addPlane(Plane{Vec3d(0, 0, -1), Vec3d(0, 0, 1), Vec3d(1, 0, 0)}, ground);
  scene.setEnvironment(Environment::fromMap(smoothSkyMap(32)));
  scene.addSphereLight(Sphere{Vec3d(-2.0, -1.5, 1.5), 0.8}, Rgb(3.0, 2.5, 2.0));
  scene.addSun(SunLight(Vec3d(1, -0.5, 1.2), Rgb(1.0, 0.9, 0.8), sunDegrees));
  scene.setCamera(
      PinholeCamera::lookAt(Vec3d(0, -4.5, 1.2), Vec3d(0, 0, -0.2), Vec3d(0, 0, 1), 45.0, Width, Height));
  return scene;
}

class LightsAtInfinity : public ::testing::TestWithParam<SkyCase> {};

TEST_P(LightsAtInfinity, PathLightAndBdptAgree) {
  const Scene scene = skyScene(GetParam().sunDegrees);
  const PilotedRender path = renderPiloted(scene, IntegratorKind::Path, 1024, 501, 12);
  const RenderResult bdpt = renderWith(scene, IntegratorKind::Bdpt, 256, 502, 12);
  const PilotedRender light = renderPiloted(scene, IntegratorKind::Light, 2048, 503, 12);
  // Two scenes x three pairs x three channels.
  const double limit = sidakSignificance(0.01, 18);
  for (const EstimatorPair& pair :
       {comparePixels("path-bdpt", path.render, bdpt,
                      [&](int x, int y, int c) { return path.reliable(x, y, c); }),
        comparePixels("path-light", path.render, light.render,
                      [&](int x, int y, int c) { return path.reliable(x, y, c) && light.reliable(x, y, c); }),
        comparePixels("bdpt-light", bdpt, light.render,
                      [&](int x, int y, int c) { return light.reliable(x, y, c); })}) {
    report(GetParam().name, pair);
    EXPECT_GE(pair.worst.pValue, limit) << pair.name;
    EXPECT_GE(pair.worst.dof, 40) << pair.name;
  }
}

std::string skyName(const ::testing::TestParamInfo<SkyCase>& info) { return info.param.name; }
INSTANTIATE_TEST_SUITE_P(Grid, LightsAtInfinity,
                         ::testing::Values(SkyCase{"sky_map_sphere_light_and_sun", 10.0},
                                           SkyCase{"sky_map_sphere_light_and_delta_sun", 0.0}),
                         skyName);

struct ControlCase {
  std::string name;
  json material;
  bool radianceRule;  // importance mode answers as radiance mode does
  double scale;       // importance mode's values times this
};
void PrintTo(const ControlCase& c, std::ostream* out) { *out << c.name; }

class AdjointControl : public ::testing::TestWithParam<ControlCase> {};

TEST_P(AdjointControl, IsRejected) {
  const ControlCase& c = GetParam();
  EXPECT_TRUE(rejected(c.name, [&] {
    return std::make_unique<WrongImportance>(makeBsdf(c.material), c.radianceRule, c.scale);
  }));
}

std::string controlName(const ::testing::TestParamInfo<ControlCase>& info) { return info.param.name; }
// The 1/eta^2 rule in importance mode, on rough glass: light tracing enters and leaves a sphere
// lit from outside in importance mode and the two scalings cancel; the light inside the sphere
// (comparison 5) sees it. And importance 5% brighter than radiance, on the registry's first
// model (Lambertian).
INSTANTIATE_TEST_SUITE_P(
    Controls, AdjointControl,
    ::testing::Values(ControlCase{"radiance_rule_in_importance_mode",
                                  {{"type", "rough-dielectric"}, {"alpha", 0.3}, {"eta", 1.5}},
                                  true,
                                  1.0},
                      ControlCase{"importance_five_percent_brighter", {{"type", "lambertian"}}, false, 1.05}),
    controlName);

}  // namespace adjoint_agreement_test
}  // namespace scatterlab
