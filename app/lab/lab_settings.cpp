#include "app/lab/lab_settings.h"

#include <nlohmann/json.hpp>

#include "fitting/fit_model.h"

namespace scatterlab {

namespace {

std::vector<double> albedoAngles() {
  std::vector<double> angles;
  for (int theta = 0; theta <= 85; theta += 5) angles.push_back(theta);
  angles.push_back(89);
  return angles;
}

LabSettings common(uint64_t seed) {
  LabSettings s;
  s.seed = seed;
  s.kit.seed = seed;
  s.albedoAnglesDeg = albedoAngles();
  s.fitFamilies = {{"Lambert + Cook-Torrance (Ngan)", "lambertian+ngan-cook-torrance"},
                   {"Lambert + GGX", std::string("lambertian+") + fitting::WhiteConductorSpec},
                   {"Lambert + Ward (Ngan)", "lambertian+ngan-ward"},
                   {"Blinn-Phong", "blinn-phong"},
                   {"GGX conductor, index fitted", "conductor"}};
  return s;
}

}  // namespace

LabSettings LabSettings::quickMode(uint64_t seed) {
  LabSettings s = common(seed);
  s.quick = true;
  s.kit.samples = 200000;
  s.kit.thetaBins = 32;
  s.kit.phiBins = 64;
  s.kit.wiThetaDeg = {0, 45, 80};
  s.kit.reciprocityPairs = 2000;
  s.walkPaths = 200000;
  s.fitSamples = 30000;
  s.fitGridPoints = 128;
  s.fitStarts = 2;
  s.fitGridSamples = 10000;
  s.fitStartSamples = 0;  // the whole subset: no separate refinement
  s.renderSize = 160;
  s.renderSpp = 64;
  return s;
}

LabSettings LabSettings::fullMode(uint64_t seed) {
  LabSettings s = common(seed);
  s.quick = false;
  s.kit.samples = 1000000;
  s.kit.thetaBins = 64;
  s.kit.phiBins = 128;
  s.kit.wiThetaDeg = {0, 30, 60, 85, 89};
  s.negativeControls = true;
  s.albedoCosThetaCells = 32;
  s.albedoPhiCells = 64;
  s.albedoProbeSamples = 100000;
  s.walkPaths = 2000000;
  s.fitSamples = 0;
  s.renderSize = 256;
  s.renderSpp = 256;
  s.previewWidth = 256;
  s.previewHeight = 192;
  s.previewSpp = 128;
  return s;
}

nlohmann::json LabSettings::toJson() const {
  return {
      {"mode", quick ? "quick" : "full"},
      {"seed", seed},
      {"check",
       {{"samples", kit.samples},
        {"grid", {kit.thetaBins, kit.phiBins}},
        {"wi_theta_deg", kit.wiThetaDeg},
        {"wi_phi_deg", kit.wiPhiDeg},
        {"alpha", kit.alpha},
        {"reciprocity_pairs", kit.reciprocityPairs},
        {"negative_controls", negativeControls}}},
      {"lobes", {{"wi_theta_deg", lobeAnglesDeg}, {"directions", lobeDirections}}},
      {"albedo",
       {{"wi_theta_deg", albedoAnglesDeg},
        {"grid", {albedoCosThetaCells, albedoPhiCells}},
        {"probe_samples", albedoProbeSamples}}},
      {"slice_phi_d_deg", slicePhiDiffDeg},
      {"walk_paths_per_channel", walkPaths},
      {"fits",
       {{"families", fitFamilies},
        {"samples", fitSamples},
        {"grid_points", fitGridPoints},
        {"starts", fitStarts},
        {"grid_samples", fitGridSamples},
        {"start_samples", fitStartSamples}}},
      {"profile_bins", profileBins},
      {"renders", {{"size", renderSize}, {"samples_per_pixel", renderSpp}, {"max_depth", renderMaxDepth}}},
      {"preview", {{"size", {previewWidth, previewHeight}}, {"samples_per_pixel", previewSpp}}}};
}

}  // namespace scatterlab
