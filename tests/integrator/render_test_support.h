// What the renderer's tests share: scenes built from registry materials, small procedural
// environment maps (no files), per-pixel statistics from the variance layer, scratch paths.
#pragma once

#include <gtest/gtest.h>

#include <unistd.h>

#include <atomic>
#include <cmath>
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "integrator/block_statistic.h"
#include "integrator/environment.h"
#include "integrator/render.h"
#include "integrator/scene_presets.h"
#include "materials/registry/spec_validation.h"

namespace scatterlab::render_test {

inline std::filesystem::path scratchPath(const std::string& stem) {
  static std::atomic<int> counter{0};
  const auto dir = std::filesystem::path(SCATTERLAB_TEST_OUTPUT_DIR) / "integrator";
  std::filesystem::create_directories(dir);
  const auto path = dir / (stem + "-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
  std::filesystem::remove_all(path);
  return path;
}

// The peers' material-sphere scene with `material` at width x height.
inline Scene sphereScene(const nlohmann::json& material, const Environment& environment, int width,
                         int height = 0) {
  return makePresetScene(ScenePreset::MaterialSphere, makeBsdf(material), environment, width,
                         height ? height : width);
}

inline RenderSettings settingsWith(int spp, uint64_t seed, bool variance = true) {
  RenderSettings s;
  s.samplesPerPixel = spp;
  s.seed = seed;
  s.varianceLayer = variance;
  return s;
}

// A smooth procedural sky (map space, +Z up): a blue gradient above, brown below, and a soft
// warm glow (Gaussian lobe of angular width ~0.35 rad) toward (1, -1, 1); dynamic range ~15,
// so that every estimator converges at a few dozen samples per pixel.
inline Image smoothSkyMap(int height = 32) {
  Image map(2 * height, height);
  const Vec3d glow = glm::normalize(Vec3d(1, -1, 1));
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < 2 * height; ++x) {
      const Vec3d w = Environment::directionFromEquirect({(x + 0.5) / (2 * height), (y + 0.5) / height});
      Rgb sky = w.z > 0 ? Rgb(0.35, 0.55, 1.0) * (0.4 + 0.6 * w.z) : Rgb(0.3, 0.25, 0.2);
      sky += Rgb(6.0, 5.0, 3.0) * std::exp((glm::dot(w, glow) - 1.0) / 0.06);
      map.setRgb(x, y, sky);
    }
  return map;
}

// A harder map: zero in a band, a small hot spot and coloured patches, for the sampler tests.
inline Image patchyMap(int height = 16) {
  Image map(2 * height, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < 2 * height; ++x) {
      Rgb v(0.2 + 0.1 * ((x * 7 + y * 3) % 5), 0.1 * (x % 3), 0.05 * (y % 4));
      if (y >= height / 2 && y < height / 2 + 2) v = Rgb(0.0);  // a black band below the horizon
      if (x == 5 && y == 3) v = Rgb(200.0, 150.0, 100.0);       // a sun-like pixel
      map.setRgb(x, y, v);
    }
  return map;
}

// The variance of pixel (x, y)'s mean for a per-pixel test, made robust: a variance estimated
// from a few dozen samples of a skewed distribution is often too small, so this is the larger
// of the pixel's own estimate and the mean over its 3 x 3 neighbourhood (variance changes
// slowly over a sphere), per channel.
inline Rgb robustPixelVariance(const Image& variance, int x, int y) {
  Rgb sum(0.0);
  int count = 0;
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      const int nx = x + dx, ny = y + dy;
      if (nx < 0 || ny < 0 || nx >= variance.width() || ny >= variance.height()) continue;
      sum += variance.rgb(nx, ny);
      ++count;
    }
  return glm::max(variance.rgb(x, y), sum / double(count));
}

}  // namespace scatterlab::render_test
