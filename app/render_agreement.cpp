#include "app/render_agreement.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

#include "integrator/scene_presets.h"
#include "integrator/silhouette_mask.h"

namespace scatterlab {

namespace {

constexpr int Width = RenderAgreementWidth, Height = RenderAgreementHeight;
constexpr int FullDepth = 12;

// The preview scene with its light moved closer and made larger (radius 0.5, 1.95 units from the
// sphere's centre, to its right and in front): light paths hit the sphere 4 times as often as
// from the default light, and a BSDF-sampled ray from the ground finds the light through a
// glass sphere often enough for the path tracer's caustic to converge at these sample counts.
PresetLighting agreementLighting() {
  return PresetLighting{std::nullopt, PresetLight{Vec3d(1.4, -0.4, 1.3), 0.5, Rgb(100.0)}};
}

// Pixels wholly off the sphere (1.5 pixel widths clear of its silhouette).
std::vector<bool> offSphere(const Scene& scene) {
  const SilhouetteMask mask = silhouetteMask(scene.camera(), presetSphere(), 1.5);
  std::vector<bool> out(size_t(Width) * Height);
  for (int y = 0; y < Height; ++y)
    for (int x = 0; x < Width; ++x) out[size_t(y) * Width + x] = mask.at(x, y) == PixelRegion::Background;
  return out;
}

// The sphere's pixels summed into one block (compareRegion), per channel: the worst channel.
EstimatorPair compareRegionPair(const std::string& name, const RenderResult& a, const RenderResult& b,
                                const std::function<bool(int, int)>& include) {
  EstimatorPair out{name, {}, {}};
  for (int channel = 0; channel < 3; ++channel) {
    const Agreement r = compareRegion(a, b, channel, include);
    if (channel == 0 || r.pValue < out.worst.pValue) out.worst = r;
  }
  return out;
}

// Over the pixels where the path and light pilots are reliable and include(x, y) holds; the
// green channel. The relative variance of a typical pixel is the mean over pixels of the
// pixel's variance over the square of the mean over pixels of its value (a pixel's own value
// can be ~0).
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
    const double mean = value[i] / out.pixels;
    return renders[i]->statistics.seconds * (variance[i] / out.pixels) / (mean * mean) / 1e-4;
  };
  out.path = toOnePercent(0);
  out.light = toOnePercent(1);
  out.bdpt = toOnePercent(2);
  return out;
}

}  // namespace

RenderResult renderWith(const Scene& scene, IntegratorKind kind, int spp, uint64_t seed, int maxDepth) {
  RenderSettings settings;
  settings.samplesPerPixel = spp;
  settings.seed = seed;
  settings.varianceLayer = true;
  settings.integratorKind = kind;
  settings.integrator.maxDepth = maxDepth;
  return render(scene, settings);
}

bool PilotedRender::reliable(int x, int y, int channel) const {
  const double mean = pilot.color.pixel(x, y)[channel];
  const double predicted = pilot.variance.pixel(x, y)[channel] / 4.0;  // four times the samples
  return mean > 0 && std::sqrt(predicted) <= 0.1 * mean;
}

PilotedRender renderPiloted(const Scene& scene, IntegratorKind kind, int spp, uint64_t seed, int maxDepth) {
  return {renderWith(scene, kind, spp, seed, maxDepth),
          renderWith(scene, kind, std::max(spp / 4, 1), seed + 1000, maxDepth)};
}

EstimatorPair comparePixels(const std::string& name, const RenderResult& a, const RenderResult& b,
                            const std::function<bool(int, int, int)>& include) {
  constexpr int block = 1;
  EstimatorPair out{name, {}, {}};
  const int width = a.color.width(), height = a.color.height();
  for (int channel = 0; channel < 3; ++channel) {
    const Agreement r =
        compareBlocks(a, b, channel, block, [&](int x, int y) { return include(x, y, channel); });
    if (channel != 0 && r.pValue >= out.worst.pValue) continue;
    out.worst = r;
    out.largest.clear();
    double largest = 0;
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        const double varA = a.variance.pixel(x, y)[channel], varB = b.variance.pixel(x, y)[channel];
        if (!include(x, y, channel) || !(varA + varB > 0)) continue;
        const double valueA = a.color.pixel(x, y)[channel], valueB = b.color.pixel(x, y)[channel];
        const double z = zScore(valueA, varA, valueB, varB);
        if (std::abs(z) <= std::abs(largest)) continue;
        largest = z;
        std::ostringstream text;
        text << "largest |z| at pixel (" << x << ", " << y << ") channel "
             << "RGB"[channel] << ": z " << z << ", " << valueA << " vs " << valueB;
        out.largest = text.str();
      }
  }
  return out;
}

std::string ConvergenceSpeed::fastest() const {
  return path <= light && path <= bdpt ? "path" : light <= bdpt ? "light" : "bdpt";
}

// The comparisons, each in its own render of the preview scene:
//  1-3. Whole paths (maxDepth 12): path tracing and BDPT everywhere; light tracing on the
//       ground, where its last vertex before the eye is the Lambertian ground (on the sphere a
//       glossy lobe seen against the lit ground makes a light tracer's pixel a sum of rare, huge
//       contributions, far from normal at any affordable count). Light tracing cannot join a
//       delta vertex to the eye, so "the ground" is the pixels 1.5 pixel widths clear of the
//       sphere's silhouette, where the caustics and shadows the sphere throws still take part.
//  4.   Direct light (maxDepth 1), models without a delta lobe: path and light tracing, which
//       joins every point the light hits to the eye with the BSDF in importance mode, over the
//       pixels that show the sphere as one region (a light path has one vertex, so pixels are
//       independent; a wrong importance mode biases them all the same way).
//  5.   Models with transmission: the light inside the sphere (radius 0.6 at its centre), path
//       and light tracing on the ground. On a closed object lit from outside every refraction
//       in is paired with one out, and the 1/eta^2 of one cancels the eta^2 of the other in
//       either mode; a path that starts inside crosses the boundary once, so only this sees
//       whether importance mode leaves the 1/eta^2 out.
// The convergence speed is measured where the path and light pilots are reliable and, for a
// model with a delta lobe (which light tracing cannot join to the eye), on the ground only.
RenderAgreement compareEstimators(const MaterialFactory& material, uint64_t seed,
                                  const RenderAgreementOptions& options) {
  const int spp = options.pathSpp;
  const LobeFlags flags = material()->flags();
  const Scene scene = makePresetScene(ScenePreset::Preview, material(), agreementLighting(), Width, Height);
  const std::vector<bool> ground = offSphere(scene);
  const auto onGround = [&](int x, int y) { return bool(ground[size_t(y) * Width + x]); };
  RenderAgreement result;
  const auto count = [&](const RenderResult& r) {
    result.nonFiniteSamples += r.statistics.nonFiniteSamples;
    result.negativeSamples += r.statistics.negativeSamples;
  };

  const PilotedRender path = renderPiloted(scene, IntegratorKind::Path, spp, seed + 1, FullDepth);
  const RenderResult bdpt =
      renderWith(scene, IntegratorKind::Bdpt, std::max(spp / 4, 1), seed + 2, FullDepth);
  const PilotedRender light = renderPiloted(scene, IntegratorKind::Light, 2 * spp, seed + 3, FullDepth);
  for (const RenderResult* r : {&path.render, &bdpt, &light.render}) count(*r);
  result.speed = convergenceSpeed(
      path, bdpt, light, [&](int x, int y) { return !hasAny(flags, LobeFlags::Specular) || onGround(x, y); });
  std::vector<EstimatorPair>& out = result.pairs;
  out = {comparePixels("path-bdpt", path.render, bdpt,
                       [&](int x, int y, int c) { return path.reliable(x, y, c); }),
         comparePixels("path-light (ground)", path.render, light.render,
                       [&](int x, int y, int c) {
                         return onGround(x, y) && path.reliable(x, y, c) && light.reliable(x, y, c);
                       }),
         comparePixels("bdpt-light (ground)", bdpt, light.render,
                       [&](int x, int y, int c) { return onGround(x, y) && light.reliable(x, y, c); })};
  if (!hasAny(flags, LobeFlags::Specular)) {
    const RenderResult directPath = renderWith(scene, IntegratorKind::Path, 2 * spp, seed + 4, 1);
    const RenderResult directLight = renderWith(scene, IntegratorKind::Light, 16 * spp, seed + 5, 1);
    count(directPath);
    count(directLight);
    out.push_back(compareRegionPair("path-light (direct light, sphere)", directPath, directLight,
                                    [&](int x, int y) { return !onGround(x, y); }));
  }
  if (hasAny(flags, LobeFlags::Transmission)) {
    const Scene inside =
        makePresetScene(ScenePreset::Preview, material(),
                        PresetLighting{std::nullopt, PresetLight{Vec3d(0.0), 0.6, Rgb(30.0)}}, Width, Height);
    const PilotedRender insidePath = renderPiloted(inside, IntegratorKind::Path, spp, seed + 6, FullDepth);
    const PilotedRender insideLight =
        renderPiloted(inside, IntegratorKind::Light, 2 * spp, seed + 7, FullDepth);
    count(insidePath.render);
    count(insideLight.render);
    out.push_back(comparePixels(
        "path-light (light inside, ground)", insidePath.render, insideLight.render, [&](int x, int y, int c) {
          return onGround(x, y) && insidePath.reliable(x, y, c) && insideLight.reliable(x, y, c);
        }));
  }
  return result;
}

uint64_t renderAgreementSeed(const std::string& name) {
  uint64_t h = 14695981039346656037ull;
  for (const char c : name) h = (h ^ uint8_t(c)) * 1099511628211ull;
  return (h >> 8) * 16;
}

CheckReport renderAgreementReport(const std::string& material, const RenderAgreement& agreement,
                                  double threshold) {
  CheckReport report;
  for (const EstimatorPair& pair : agreement.pairs) {
    CheckRow row;
    row.material = material;
    row.test = "render " + pair.name;
    row.statistic = pair.worst.chi2;
    row.dof = pair.worst.dof;
    row.pValue = pair.worst.pValue;
    row.threshold = threshold;
    row.passed = pair.worst.dof >= 1 && pair.worst.pValue >= threshold;
    row.note = pair.worst.dof >= 1 ? "worst channel; " + (pair.largest.empty() ? "one region" : pair.largest)
                                   : "no pixel converged enough to compare; raise --render-agreement";
    report.rows.push_back(std::move(row));
  }
  if (!report.rows.empty()) {
    const ConvergenceSpeed& speed = agreement.speed;
    std::ostringstream text;
    text << "; seconds to 1% relative error per pixel (" << speed.pixels << " pixels): path " << speed.path
         << ", light " << speed.light << ", bdpt " << speed.bdpt << "; fastest " << speed.fastest();
    report.rows.front().note += text.str();
  }
  CheckRow finite;
  finite.material = material;
  finite.test = "render finite";
  finite.statistic = double(agreement.droppedSamples());
  finite.threshold = 0.0;
  finite.passed = agreement.droppedSamples() == 0;
  finite.note = "samples dropped over every render (" + std::to_string(agreement.nonFiniteSamples) +
                " not finite, " + std::to_string(agreement.negativeSamples) + " negative)";
  report.rows.push_back(std::move(finite));
  return report;
}

}  // namespace scatterlab
