// The adjoint of every BSDF (docs/validation.md section 7): path tracing carries radiance and
// calls a BSDF with TransportMode::Radiance; light tracing and BDPT's light subpaths carry
// importance and call it with TransportMode::Importance, f*(wi, wo) = f(wo, wi) with no 1/eta^2
// at a refraction (Veach 1997, sec. 5.2 and 10.1). The three are unbiased estimators of the same
// image, so their renders of the preview scene (the material on the sphere, the checkered
// ground, the small sphere light; no environment, so that every path starts at the light)
// agree within noise exactly when every mode of the material is right.
//
// The statistic is the renderer tests' block chi-square (render_test_support.h) with blocks of
// one pixel: the image is rendered at the block resolution, 16 x 12, because pixels of a
// splatting estimator are not independent (one light path adds to several pixels), while the
// film's variance of one pixel is exact (splat_film.h). Light tracing cannot join a delta
// vertex to the eye, so path and light tracing are compared off the sphere only (pixels 1.5
// pixel widths clear of its silhouette), where the caustics and shadows the sphere throws on the
// ground still take part, and on the sphere by a render of direct light alone (below).
// Every model of the registry (materialModels(): the list `scatterlab models` prints) with its
// defaults, the measured model with a table synthesised from a GGX conductor; subsurface
// materials are BSSRDFs, which only the path tracer renders (tested below). Each pair of
// estimators x channel x model is one test at p < 0.01 / (count), Sidak. Negative controls:
// a wrapper whose importance mode applies the radiance rule 1/eta^2 (what forgetting the mode
// does) and one whose importance mode is 5% brighter must be rejected.
#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <iostream>
#include <mutex>

#include "integrator/silhouette_mask.h"
#include "materials/measured/measurement_synthesis.h"
#include "materials/measured/merl_io.h"
#include "materials/registry/model_list.h"
#include "render_test_support.h"
#include "validation/chi_square.h"

namespace scatterlab {
namespace {

using nlohmann::json;
using namespace render_test;

constexpr int Width = 16, Height = 12;
constexpr int DirectLightTracingSpp = 16384;

// The preview scene with its light moved closer and made larger (radius 0.5, 1.95 units from the
// sphere's centre, to its right and in front): light paths hit the sphere 4 times as often as
// from the default light, and a BSDF-sampled ray from the ground finds the light through a
// glass sphere often enough for the path tracer's caustic to converge at these sample counts.
PresetLighting testLighting() {
  return PresetLighting{std::nullopt, PresetLight{Vec3d(1.4, -0.4, 1.3), 0.5, Rgb(100.0)}};
}

RenderResult renderWith(const Scene& scene, IntegratorKind kind, int spp, uint64_t seed, int maxDepth) {
  RenderSettings settings = settingsWith(spp, seed);
  settings.integratorKind = kind;
  settings.integrator.maxDepth = maxDepth;
  return render(scene, settings);
}

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

// Up to five comparisons x three channels per registry model, Sidak.
double threshold() {
  static const double value = sidakSignificance(0.01, 15 * int(registryCases().size()));
  return value;
}

// A material, built as often as scenes need it.
using MaterialFactory = std::function<std::unique_ptr<BsdfModel>()>;

// Pixels wholly off the sphere (1.5 pixel widths clear of its silhouette).
std::vector<bool> offSphere(const Scene& scene) {
  const SilhouetteMask mask = silhouetteMask(scene.camera(), presetSphere(), 1.5);
  std::vector<bool> out(size_t(Width) * Height);
  for (int y = 0; y < Height; ++y)
    for (int x = 0; x < Width; ++x) out[size_t(y) * Width + x] = mask.at(x, y) == PixelRegion::Background;
  return out;
}

// A light tracer's pixel that a few dozen light paths reach is far from normal (its splats
// are few, of unequal size, skewed to the right), and its variance estimate is 0 where none
// did; a path tracer's pixel where a few BSDF samples found the light through glass is the
// same. So the two are compared where an independent pilot render of each (a quarter of the
// samples, another seed) predicts a relative standard error below 0.1 for the render compared:
// the equivalent of 100 equal contributions or more. The pilot is independent of the renders
// compared, so choosing pixels by it cannot bias the statistic.
struct PilotedRender {
  RenderResult render, pilot;
  bool reliable(int x, int y, int channel) const {
    const double mean = pilot.color.pixel(x, y)[channel];
    const double predicted = pilot.variance.pixel(x, y)[channel] / 4.0;
    return mean > 0 && std::sqrt(predicted) <= 0.1 * mean;
  }
};
PilotedRender renderPiloted(const Scene& scene, IntegratorKind kind, int spp, uint64_t seed, int maxDepth) {
  return {renderWith(scene, kind, spp, seed, maxDepth),
          renderWith(scene, kind, spp / 4, seed + 1000, maxDepth)};
}

struct PairResult {
  std::string name;
  Agreement worst;      // the worst channel
  std::string largest;  // where the largest z of that channel is, for the failure message
};

template <typename Include> PairResult compareSphereRegion(const std::string& name, const RenderResult& a,
                                                           const RenderResult& b, const Include& include) {
  PairResult out{name, {}, {}};
  for (int channel = 0; channel < 3; ++channel) {
    const Agreement r = compareRegion(a, b, channel, include);
    if (channel == 0 || r.pValue < out.worst.pValue) out.worst = r;
  }
  return out;
}

// Pixel by pixel.
template <typename Include> PairResult comparePair(const std::string& name, const RenderResult& a,
                                                   const RenderResult& b, const Include& include) {
  constexpr int block = 1;
  PairResult out{name, {}, {}};
  for (int channel = 0; channel < 3; ++channel) {
    const Agreement r =
        compareBlocks(a, b, channel, block, [&](int x, int y) { return include(x, y, channel); });
    if (channel == 0 || r.pValue < out.worst.pValue) {
      out.worst = r;
      double largest = 0;
      for (int y = 0; y < Height; ++y)
        for (int x = 0; x < Width; ++x) {
          if (!include(x, y, channel) ||
              !(a.variance.pixel(x, y)[channel] + b.variance.pixel(x, y)[channel] > 0))
            continue;
          const double z = zScore(a.color.pixel(x, y)[channel], a.variance.pixel(x, y)[channel],
                                  b.color.pixel(x, y)[channel], b.variance.pixel(x, y)[channel]);
          if (std::abs(z) > std::abs(largest)) {
            largest = z;
            out.largest = "pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") z " +
                          std::to_string(z) + ": " + std::to_string(a.color.pixel(x, y)[channel]) + " vs " +
                          std::to_string(b.color.pixel(x, y)[channel]);
          }
        }
    }
  }
  return out;
}

// The comparisons, each in its own render of the preview scene:
//  1-3. Whole paths (maxDepth 12): path tracing and BDPT everywhere; light tracing on the
//       ground, where its last vertex before the eye is the Lambertian ground (on the sphere a
//       glossy lobe seen against the lit ground makes a light tracer's pixel a sum of rare, huge
//       contributions, far from normal at any affordable count).
//  4.   Direct light (maxDepth 1), models without a delta lobe: path and light tracing, which
//       joins every point the light hits to the eye with the BSDF in importance mode, over the
//       pixels that show the sphere as one region (a light path has one vertex, so pixels are
//       independent; a wrong importance mode biases them all the same way).
//  5.   Models with transmission: the light inside the sphere (radius 0.6 at its centre), path
//       and light tracing on the ground. On a closed object lit from outside every refraction
//       in is paired with one out, and the 1/eta^2 of one cancels the eta^2 of the other in
//       either mode; a path that starts inside crosses the boundary once, so only this sees
//       whether importance mode leaves the 1/eta^2 out.
//
// Besides, which estimator converges fastest on the material: per estimator, the seconds its
// render took times the relative variance of a typical pixel, the mean over pixels of the
// pixel's variance over the square of the mean over pixels of its value (a pixel's own value
// can be ~0): the time it would need to bring a typical pixel to 1% relative standard error is
// that / 1e-4 (variance falls as 1 / samples, time grows with them). Over the pixels where the
// path and light pilots are reliable and, for a model with a delta lobe (which light tracing
// cannot join to the eye), the ground only; the green channel.
struct ConvergenceSpeed {
  double path = 0.0, light = 0.0, bdpt = 0.0;  // seconds to 1% relative error per pixel
  int pixels = 0;
  std::string fastest() const {
    return path <= light && path <= bdpt ? "path" : light <= bdpt ? "light" : "bdpt";
  }
};

struct Comparison {
  std::vector<PairResult> pairs;
  ConvergenceSpeed speed;
};

ConvergenceSpeed convergenceSpeed(const PilotedRender& path, const RenderResult& bdpt,
                                  const PilotedRender& light, const std::function<bool(int, int)>& include) {
  ConvergenceSpeed out;
  const RenderResult* renders[3] = {&path.render, &light.render, &bdpt};
  double value[3] = {0, 0, 0}, variance[3] = {0, 0, 0};
  for (int y = 0; y < Height; ++y)
    for (int x = 0; x < Width; ++x) {
      if (!include(x, y) || !path.reliable(x, y, 1) || !light.reliable(x, y, 1)) continue;
      for (int i = 0; i < 3; ++i) {
        value[i] += renders[i]->color.pixel(x, y)[1];
        variance[i] += renders[i]->variance.pixel(x, y)[1];
      }
      ++out.pixels;
    }
  if (out.pixels == 0) return out;
  const auto toOnePercent = [&](int i) {
    return renders[i]->statistics.seconds * (variance[i] / out.pixels) / sqr(value[i] / out.pixels) / 1e-4;
  };
  out.path = toOnePercent(0);
  out.light = toOnePercent(1);
  out.bdpt = toOnePercent(2);
  return out;
}

Comparison compareEstimators(const MaterialFactory& material, uint64_t seed) {
  constexpr int Full = 12;
  const LobeFlags flags = material()->flags();
  const Scene scene = makePresetScene(ScenePreset::Preview, material(), testLighting(), Width, Height);
  const std::vector<bool> ground = offSphere(scene);
  const auto onGround = [&](int x, int y) { return bool(ground[size_t(y) * Width + x]); };
  const PilotedRender path = renderPiloted(scene, IntegratorKind::Path, 1024, seed + 1, Full);
  const RenderResult bdpt = renderWith(scene, IntegratorKind::Bdpt, 256, seed + 2, Full);
  const PilotedRender light = renderPiloted(scene, IntegratorKind::Light, 2048, seed + 3, Full);
  for (const RenderResult* r : {&path.render, &bdpt, &light.render})
    EXPECT_EQ(r->statistics.nonFiniteSamples, 0u);
  Comparison result;
  result.speed = convergenceSpeed(
      path, bdpt, light, [&](int x, int y) { return !hasAny(flags, LobeFlags::Specular) || onGround(x, y); });
  std::vector<PairResult>& out = result.pairs;
  out = {comparePair("path-bdpt", path.render, bdpt,
                     [&](int x, int y, int c) { return path.reliable(x, y, c); }),
         comparePair("path-light (ground)", path.render, light.render,
                     [&](int x, int y, int c) {
                       return onGround(x, y) && path.reliable(x, y, c) && light.reliable(x, y, c);
                     }),
         comparePair("bdpt-light (ground)", bdpt, light.render,
                     [&](int x, int y, int c) { return onGround(x, y) && light.reliable(x, y, c); })};
  if (!hasAny(flags, LobeFlags::Specular)) {
    out.push_back(
        compareSphereRegion("path-light (direct light, the sphere as one region)",
                            renderWith(scene, IntegratorKind::Path, 2048, seed + 4, 1),
                            renderWith(scene, IntegratorKind::Light, DirectLightTracingSpp, seed + 5, 1),
                            [&](int x, int y) { return !onGround(x, y); }));
  }
  if (hasAny(flags, LobeFlags::Transmission)) {
    const Scene inside =
        makePresetScene(ScenePreset::Preview, material(),
                        PresetLighting{std::nullopt, PresetLight{Vec3d(0.0), 0.6, Rgb(30.0)}}, Width, Height);
    const PilotedRender insidePath = renderPiloted(inside, IntegratorKind::Path, 1024, seed + 6, Full);
    const PilotedRender insideLight = renderPiloted(inside, IntegratorKind::Light, 2048, seed + 7, Full);
    out.push_back(comparePair(
        "path-light (light inside, ground)", insidePath.render, insideLight.render, [&](int x, int y, int c) {
          return onGround(x, y) && insidePath.reliable(x, y, c) && insideLight.reliable(x, y, c);
        }));
  }
  return result;
}

void report(const std::string& what, const PairResult& pair) {
  std::cout << "[ adjoint  ] " << what << " " << pair.name << ": worst channel chi2 " << pair.worst.chi2
            << " dof " << pair.worst.dof << " p " << pair.worst.pValue << "; largest |z|: " << pair.largest
            << "\n";
}

// Each material its own random numbers (the ground looks the same under every material, and
// with one seed for all its fluctuations would be one event counted many times): FNV-1a of
// the name, spaced for the seven renders above.
uint64_t seedOf(const std::string& name) {
  uint64_t h = 14695981039346656037ull;
  for (const char c : name) h = (h ^ uint8_t(c)) * 1099511628211ull;
  return (h >> 8) * 16;
}

class AdjointAgreement : public testing::TestWithParam<AdjointCase> {};

TEST_P(AdjointAgreement, PathLightAndBdptAgree) {
  const json& material = GetParam().material;
  const Comparison comparison =
      compareEstimators([&] { return makeBsdf(material); }, seedOf(GetParam().name));
  const ConvergenceSpeed& speed = comparison.speed;
  std::cout << "[ speed    ] " << GetParam().name << ": seconds to 1% relative error per pixel ("
            << speed.pixels << " pixels): path " << speed.path << ", light " << speed.light << ", bdpt "
            << speed.bdpt << "; fastest " << speed.fastest() << "\n";
  for (const PairResult& pair : comparison.pairs) {
    report(GetParam().name, pair);
    EXPECT_GE(pair.worst.pValue, threshold())
        << pair.name << ": chi2 " << pair.worst.chi2 << " dof " << pair.worst.dof;
    EXPECT_GE(pair.worst.dof, 1) << pair.name;
  }
}

std::string caseName(const testing::TestParamInfo<AdjointCase>& info) { return info.param.name; }
INSTANTIATE_TEST_SUITE_P(Grid, AdjointAgreement, testing::ValuesIn(registryCases()), caseName);

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
  for (const PairResult& pair : compareEstimators(material, seedOf(what)).pairs) {
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

class LightsAtInfinity : public testing::TestWithParam<SkyCase> {};

TEST_P(LightsAtInfinity, PathLightAndBdptAgree) {
  const Scene scene = skyScene(GetParam().sunDegrees);
  const PilotedRender path = renderPiloted(scene, IntegratorKind::Path, 1024, 501, 12);
  const RenderResult bdpt = renderWith(scene, IntegratorKind::Bdpt, 256, 502, 12);
  const PilotedRender light = renderPiloted(scene, IntegratorKind::Light, 2048, 503, 12);
  // Two scenes x three pairs x three channels.
  const double limit = sidakSignificance(0.01, 18);
  for (const PairResult& pair :
       {comparePair("path-bdpt", path.render, bdpt,
                    [&](int x, int y, int c) { return path.reliable(x, y, c); }),
        comparePair("path-light", path.render, light.render,
                    [&](int x, int y, int c) { return path.reliable(x, y, c) && light.reliable(x, y, c); }),
        comparePair("bdpt-light", bdpt, light.render,
                    [&](int x, int y, int c) { return light.reliable(x, y, c); })}) {
    report(GetParam().name, pair);
    EXPECT_GE(pair.worst.pValue, limit) << pair.name;
    EXPECT_GE(pair.worst.dof, 40) << pair.name;
  }
}

std::string skyName(const testing::TestParamInfo<SkyCase>& info) { return info.param.name; }
INSTANTIATE_TEST_SUITE_P(Grid, LightsAtInfinity,
                         testing::Values(SkyCase{"sky_map_sphere_light_and_sun", 10.0},
                                         SkyCase{"sky_map_sphere_light_and_delta_sun", 0.0}),
                         skyName);

struct ControlCase {
  std::string name;
  json material;
  bool radianceRule;  // importance mode answers as radiance mode does
  double scale;       // importance mode's values times this
};
void PrintTo(const ControlCase& c, std::ostream* out) { *out << c.name; }

class AdjointControl : public testing::TestWithParam<ControlCase> {};

TEST_P(AdjointControl, IsRejected) {
  const ControlCase& c = GetParam();
  EXPECT_TRUE(rejected(c.name, [&] {
    return std::make_unique<WrongImportance>(makeBsdf(c.material), c.radianceRule, c.scale);
  }));
}

std::string controlName(const testing::TestParamInfo<ControlCase>& info) { return info.param.name; }
// The 1/eta^2 rule in importance mode, on rough glass: light tracing enters and leaves a sphere
// lit from outside in importance mode and the two scalings cancel; the light inside the sphere
// (comparison 5) sees it. And importance 5% brighter than radiance, on the registry's first
// model (Lambertian).
INSTANTIATE_TEST_SUITE_P(
    Controls, AdjointControl,
    testing::Values(ControlCase{"radiance_rule_in_importance_mode",
                                {{"type", "rough-dielectric"}, {"alpha", 0.3}, {"eta", 1.5}},
                                true,
                                1.0},
                    ControlCase{"importance_five_percent_brighter", {{"type", "lambertian"}}, false, 1.05}),
    controlName);

}  // namespace
}  // namespace scatterlab
