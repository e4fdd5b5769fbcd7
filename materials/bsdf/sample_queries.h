// Sampling queries given from outside (`scatterlab eval --samples FILE`) and what a model's
// sample() returns for them, so that scatterlab's sampler can be compared with another
// implementation's, or with the Python package's (docs/python.md), number for number.
//
// A query is {"wi": [x, y, z], "u_lobe": a, "u": [b, c]}: the incident direction in the local
// frame (a unit vector within direction_pairs.h's UnitLengthTolerance, normalised before use) and
// the three random numbers sample() takes, each in [0, 1).
#pragma once

#include <span>
#include <vector>

#include <nlohmann/json.hpp>

#include "materials/bsdf/bsdf.h"

namespace scatterlab {

struct SampleQuery {
  Vec3d wi{0, 0, 1};
  double uLobe = 0.0;
  Vec2d u{0.0};
};

// A non-empty array of queries; throws DirectionError naming the entry and key ("[2].u").
std::vector<SampleQuery> sampleQueriesFromJson(const nlohmann::json& value);

// [{"wi", "u_lobe", "u", "valid", "wo", "weight", "pdf", "delta"}, ...] in radiance transport,
// every number in full precision; a failed sample has "valid": false and zeros elsewhere.
nlohmann::json sampleQueryValuesJson(const BsdfModel& model, std::span<const SampleQuery> queries);

}  // namespace scatterlab
