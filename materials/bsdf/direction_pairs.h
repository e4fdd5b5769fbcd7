// Direction pairs given from outside (a file, the command line, the explorer's console API)
// and a model's values at them: what `scatterlab eval` prints and `window.scatterlab.eval`
// returns, from this one code (docs/explorer.md, "Evaluating a material at given directions").
//
// A pair is {"wi": [x, y, z], "wo": [x, y, z]} in the model's local frame (z = normal, both
// pointing away from the surface, bsdf.h). Each direction must be a unit vector within
// UnitLengthTolerance; it is normalised before use, so that a direction written with a few
// digits evaluates as the unit vector it stands for.
#pragma once

#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "materials/bsdf/bsdf.h"

namespace scatterlab {

// A direction or pair that is not what the format allows. The message names the key
// ("[3].wi", "wo"), the value given and what is allowed.
class DirectionError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// | |w| - 1 | allowed before a direction is refused as not unit: a unit vector printed with 6
// significant digits per component (C's %g) is off by at most 5e-6 relative.
inline constexpr double UnitLengthTolerance = 1e-5;

struct DirectionPair {
  Vec3d wi{0, 0, 1}, wo{0, 0, 1};
};

// [x, y, z]: three finite numbers of length 1 within the tolerance; returned normalised.
// `key` names the value in messages. Throws DirectionError.
Vec3d unitDirectionFromJson(const nlohmann::json& value, const std::string& key);

// {"wi": [x, y, z], "wo": [x, y, z]} and no other key. `key` prefixes the keys in messages.
DirectionPair directionPairFromJson(const nlohmann::json& value, const std::string& key = "");

// A non-empty array of pairs; messages name the entry ("[3].wo").
std::vector<DirectionPair> directionPairsFromJson(const nlohmann::json& value);

// f (RGB, sr^-1, no cosine) and pdf (per solid angle of wo) of one pair, in radiance transport.
struct PairValue {
  Rgb f{0.0};
  double pdf = 0.0;
};
std::vector<PairValue> evaluatePairs(const BsdfModel& model, std::span<const DirectionPair> pairs);

// [{"wi": [...], "wo": [...], "f": [r, g, b], "pdf": p}, ...]: the directions as evaluated
// (normalised), every number in full precision.
nlohmann::json pairValuesJson(std::span<const DirectionPair> pairs, std::span<const PairValue> values);

}  // namespace scatterlab
