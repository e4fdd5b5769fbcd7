// The materials `scatterlab check` runs when given none: one per model family and sampling
// strategy, including the hard cases (strong anisotropy, a narrow lobe).
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace scatterlab {

struct ShowcaseMaterial {
  std::string name;
  nlohmann::json material;
};

std::vector<ShowcaseMaterial> showcaseMaterials();

}  // namespace scatterlab
