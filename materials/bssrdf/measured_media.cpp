#include "materials/bssrdf/measured_media.h"

#include <algorithm>
#include <array>

namespace scatterlab {

namespace {
// Jensen et al. 2001, Figure 5 (pbrt-v3's SubsurfaceParameterTable): sigma_s', sigma_a in mm^-1.
const std::array<MeasuredMedium, 12> Media{{
    {"Apple", {2.29, 2.39, 1.97}, {0.0030, 0.0034, 0.046}, 1.3},
    {"Chicken1", {0.15, 0.21, 0.38}, {0.015, 0.077, 0.19}, 1.3},
    {"Chicken2", {0.19, 0.25, 0.32}, {0.018, 0.088, 0.20}, 1.3},
    {"Cream", {7.38, 5.47, 3.15}, {0.0002, 0.0028, 0.0163}, 1.3},
    {"Ketchup", {0.18, 0.07, 0.03}, {0.061, 0.97, 1.45}, 1.3},
    {"Marble", {2.19, 2.62, 3.00}, {0.0021, 0.0041, 0.0071}, 1.5},
    {"Potato", {0.68, 0.70, 0.55}, {0.0024, 0.0090, 0.12}, 1.3},
    {"Skimmilk", {0.70, 1.22, 1.90}, {0.0014, 0.0025, 0.0142}, 1.3},
    {"Skin1", {0.74, 0.88, 1.01}, {0.032, 0.17, 0.48}, 1.3},
    {"Skin2", {1.09, 1.59, 1.79}, {0.013, 0.070, 0.145}, 1.3},
    {"Spectralon", {11.6, 20.4, 14.9}, {0.0, 0.0, 0.0}, 1.3},
    {"Wholemilk", {2.55, 3.21, 3.77}, {0.0011, 0.0024, 0.014}, 1.3},
}};
}  // namespace

std::span<const MeasuredMedium> measuredMedia() { return Media; }

const MeasuredMedium* findMeasuredMedium(std::string_view name) {
  const auto it =
      std::find_if(Media.begin(), Media.end(), [&](const MeasuredMedium& m) { return name == m.name; });
  return it == Media.end() ? nullptr : &*it;
}

std::vector<std::string> measuredMediumNames() {
  std::vector<std::string> names;
  for (const MeasuredMedium& medium : Media) names.emplace_back(medium.name);
  return names;
}

}  // namespace scatterlab
