// Direction pairs from JSON (direction_pairs.h), the code `scatterlab eval` and the explorer's
// console API share: what is accepted and normalised, what is refused with which key, and the
// values and JSON of a model at the pairs.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include <nlohmann/json.hpp>

#include "materials/bsdf/direction_pairs.h"
#include "materials/bsdf/lambertian.h"

namespace scatterlab {
namespace direction_pairs_test {

using nlohmann::json;

std::string refusal(const json& value) {
  try {
    directionPairsFromJson(value);
  } catch (const DirectionError& error) {
    return error.what();
  }
  return "";
}

TEST(DirectionPairs, NearlyUnitDirectionsAreNormalised) {
  // Length 1 + 5e-6: within the tolerance, returned as the unit vector.
  const Vec3d w = unitDirectionFromJson(json::array({0.6, 0.0, 0.800004}), "wi");
  EXPECT_NEAR(glm::length(w), 1.0, 1e-15);
  EXPECT_NEAR(w.x, 0.6 / std::sqrt(0.36 + 0.800004 * 0.800004), 1e-15);
  const auto pairs = directionPairsFromJson(json::parse(R"([{"wo": [0, 0, 1], "wi": [1, 0, 0]}])"));
  ASSERT_EQ(pairs.size(), 1u);
  EXPECT_EQ(pairs[0].wi, Vec3d(1, 0, 0));
  EXPECT_EQ(pairs[0].wo, Vec3d(0, 0, 1));
}

TEST(DirectionPairs, RefusalsNameTheEntryAndKey) {
  EXPECT_NE(
      refusal(json::parse(R"([{"wi": [0, 0, 1], "wo": [0, 0, 1]}, {"wi": [0, 0, 1], "wo": [0, 2, 0]}])"))
          .find("[1].wo: [0,2,0] is not a unit vector (length 2)"),
      std::string::npos);
  EXPECT_NE(refusal(json::parse(R"([{"wi": [0, 0], "wo": [0, 0, 1]}])")).find("[0].wi"), std::string::npos);
  EXPECT_NE(refusal(json::parse(R"([{"wi": [0, 0, 1], "wo": [0, 0, 1], "x": 0}])")).find("[0].x"),
            std::string::npos);
  EXPECT_NE(refusal(json::parse(R"([{"wi": [0, 0, 1]}])")).find("has no \"wo\""), std::string::npos);
  EXPECT_NE(refusal(json::array()).find("is empty"), std::string::npos);
  EXPECT_NE(refusal(json::object()).find("not an array"), std::string::npos);
  // JSON text cannot hold them, but a value built in memory can.
  for (const double bad :
       {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::quiet_NaN()}) {
    const json pair{{"wi", json::array({0.0, 0.0, bad})}, {"wo", json::array({0.0, 0.0, 1.0})}};
    EXPECT_NE(refusal(json::array({pair})).find("[0].wi"), std::string::npos) << bad;
  }
}

TEST(DirectionPairs, ValuesAreTheModelsAndTheirJsonRoundTrips) {
  const LambertianBsdf model(Rgb(0.2, 0.4, 0.6));
  const std::vector<DirectionPair> pairs{{Vec3d(0, 0, 1), glm::normalize(Vec3d(0.3, 0.4, 0.8))},
                                         {Vec3d(0, 0, 1), Vec3d(0, 0, -1)}};
  const std::vector<PairValue> values = evaluatePairs(model, pairs);
  ASSERT_EQ(values.size(), 2u);
  EXPECT_EQ(values[0].f, model.eval(pairs[0].wi, pairs[0].wo));
  EXPECT_EQ(values[0].pdf, model.pdf(pairs[0].wi, pairs[0].wo));
  EXPECT_EQ(values[1].f, Rgb(0.0));  // below the surface: one-sided
  const json printed = json::parse(pairValuesJson(pairs, values).dump());
  ASSERT_EQ(printed.size(), 2u);
  for (int c = 0; c < 3; ++c) {
    EXPECT_EQ(printed[0]["f"][c].get<double>(), values[0].f[c]);
    EXPECT_EQ(printed[0]["wo"][c].get<double>(), pairs[0].wo[c]);
  }
  EXPECT_EQ(printed[0]["pdf"].get<double>(), values[0].pdf);
}

}  // namespace direction_pairs_test
}  // namespace scatterlab
