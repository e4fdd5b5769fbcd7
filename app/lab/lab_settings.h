// How much work `scatterlab lab` does per material, in its two modes. The numbers are chosen
// for a 2-core machine: `--quick` runs the five showcase materials in
// well under 2 minutes, the full report in well under 15 (the report's timings table shows
// what each phase cost).
//
//                         quick                         full
// check (BSDF kit)        2e5 samples, 32 x 64 cells,   1e6 samples, 64 x 128 cells,
//                         wi 0, 45, 80                  wi 0, 30, 60, 85, 89, + negative controls
// check (subsurface kit)  2e5 samples, 32 radius bins   1e6 samples, 64 radius bins, + controls
// lobes                   wi 0, 30, 60, 80 in the plane of incidence, 181 directions (361 with transmission)
// albedo curve            19 angles, quadrature on      19 angles, 32 x 64 cells, 1e5 probes
//                         16 x 32 cells, 2e4 probes
// random walk             2e5 paths per channel         2e6 paths per channel
// fits (metric ngan)      Lambert + Cook-Torrance (Ngan), + GGX, + Ward (Ngan); Blinn-Phong;
//                         a GGX conductor with its index fitted
//                         on a 30,000-cell stratified   on every usable cell (about 1e6 of a
//                         subset, 128 grid points,      MERL table, 7,000 pairs of an RGL file),
//                         2 starts                      256 grid points, 3 starts
// renders (2 maps; a      160 x 160, 64 spp             256 x 256, 256 spp
// measured material
// and its 5 fits each)
// preview scene (the      128 x 96, 32 spp              256 x 192, 128 spp
// material alone, first map)
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "validation/bsdf_check.h"

namespace scatterlab {

struct LabSettings {
  bool quick = false;
  uint64_t seed = 1;
  BsdfCheckOptions kit;
  bool negativeControls = false;

  std::vector<double> lobeAnglesDeg{0, 30, 60, 80};
  int lobeDirections = 181;  // over the upper half of the plane of incidence (twice over the whole circle)

  std::vector<double> albedoAnglesDeg;
  int albedoCosThetaCells = 16, albedoPhiCells = 32;
  size_t albedoProbeSamples = 20000;

  double slicePhiDiffDeg = 90.0;  // the theta_h / theta_d image slice of measured data

  uint64_t walkPaths = 200000;  // per channel
  int profileBins = 24;

  std::vector<std::pair<std::string, std::string>> fitFamilies;  // name, --model spec
  size_t fitSamples = 30000;  // stratified subset of the usable cells; 0: all
  int fitGridPoints = 256, fitStarts = 3;
  size_t fitGridSamples = 20000, fitStartSamples = 100000;  // fitting/brdf_fit.h FitOptions

  int renderSize = 160;  // square renders of the material sphere (renders_section.h)
  int renderSpp = 64;
  int renderMaxDepth = 12;
  int previewWidth = 128, previewHeight = 96, previewSpp = 32;  // the preview scene (renders_section.h)

  static LabSettings quickMode(uint64_t seed);
  static LabSettings fullMode(uint64_t seed);
  nlohmann::json toJson() const;
};

}  // namespace scatterlab
