// `scatterlab render`: material spheres rendered by one of the renderer's estimators
// (integrator/render.h: path tracing, light tracing, BDPT, SPPM). One material gives
// PREFIX.exr (linear float RGB, optional albedo / normal / variance layers) and PREFIX.png
// (sRGB, exposure); several give a gallery: one labelled contact sheet as PREFIX.exr and
// PREFIX.png. Every input is validated before any rendering, and nothing is written unless
// everything is written (atomic files; a failure of the second file removes the first).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "integrator/render.h"
#include "integrator/scene_presets.h"

namespace scatterlab {

struct RenderCommandOptions {
  std::vector<std::string> materials;  // inline JSON or files; two or more: a gallery
  std::string integrator = "path";
  std::string scene = "sphere";
  std::string env;  // empty: the scene's own (white for sphere and preview, none for caustic)
  double envStrength = 1.0;
  double envRotateDegrees = 0.0;
  int spp = 64;
  std::string resolution = "256x256";
  int threads = 0;
  uint64_t seed = 1;
  int maxDepth = 12;
  std::string estimator;  // empty: mis (the path tracer's only)
  // The preview and caustic scenes' area light (integrator/scene_presets.h); 0 or empty: the
  // default.
  std::vector<double> lightPosition;
  double lightRadius = 0.0;
  double lightStrength = 0.0;  // times the default radiance
  bool noLight = false;
  // SPPM only; 0: the default (one photon per pixel; SppmSettings' radius).
  int64_t photons = 0;
  double sppmRadius = 0.0;
  std::string subsurface = "diffusion";  // diffusion or walk (integrator/subsurface.h)
  std::string filter = "box";
  double exposure = 0.0;
  std::vector<std::string> layers;  // albedo, normal, variance
  std::vector<std::string> labels;  // gallery labels, one per material
  int columns = 0;
  std::string out;
  bool json = false;
};

CLI::App* addRenderCommand(CLI::App& app, RenderCommandOptions& options);

// Returns 0; bad input throws MaterialError or InputError (exit 2) before anything is written.
int runRenderCommand(const RenderCommandOptions& options);

// One material rendered as the command renders it, validated the same way (all but --out, which
// it does not use), writing nothing: what --json prints (with "exr" and "png" null) and the
// images. The progress line on stderr with `progress`. The Python package's sl.render
// (docs/python.md).
struct RenderReport {
  nlohmann::json report;
  RenderResult result;
};
RenderReport renderReport(const RenderCommandOptions& options, bool progress);

// "WxH" (or "N" for N x N) within the renderer's limits (integrator/render.h), or nothing.
struct Resolution {
  int width = 0, height = 0;
};
std::optional<Resolution> parseResolution(const std::string& text);

}  // namespace scatterlab
