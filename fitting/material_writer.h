// The fitted model as one registry material, which `scatterlab check` and `render` accept.
//
// The registry has no sum of materials, but `blend` is f = w fA + (1 - w) fB per channel, so a
// sum of parts with per-channel weights c_i (sum c_i = 1) is the chain
//   blend(w_1, [P_1, blend(w_2, [P_2, ... blend(w_(n-1), [P_(n-1), P_n])])]),
//   w_i = c_i / (1 - c_1 - ... - c_(i-1)).
// A part that must be carried with weight W (a conductor's fitted scale, or 1 for a model
// without a linear scale) takes c = W. A scalable part (its RGB scales v_j multiply all of
// it: an albedo, Phong's kd and ks) can take any c >= max_j v_j by writing v_j / c; the
// scalable parts share what the others leave, R = 1 - sum W, in proportion to their
// max_j v_j. So the sum is writable exactly when, per channel, sum W + sum max_j v_j <= 1 (the
// parts reflect at most what an energy-conserving sum of unit-albedo lobes would); when no
// part is scalable, a black Lambertian takes the remainder. One scalable part alone is
// written as it is.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "fitting/fit_model.h"

namespace scatterlab::fitting {

struct WrittenMaterial {
  std::optional<nlohmann::json> material;  // completed and validated by the registry
  std::string problem;                     // why there is none
};

WrittenMaterial writeMaterial(const std::vector<FittedPart>& parts);

}  // namespace scatterlab::fitting
