#include "materials/bsdf/direction_pairs.h"

#include <cmath>
#include <cstdio>

namespace scatterlab {

namespace {

using nlohmann::json;

const std::string DirectionAllowed =
    "[x, y, z], three finite numbers with x^2 + y^2 + z^2 = 1 (to within 1e-5) in the local frame, z = "
    "normal";
const std::string PairAllowed = "an object {\"wi\": [x, y, z], \"wo\": [x, y, z]}";

[[noreturn]] void refuse(const std::string& key, const json& value, const std::string& problem,
                         const std::string& allowed) {
  throw DirectionError(key + ": " + value.dump() + " " + problem + "; allowed: " + allowed);
}

std::string joinKey(const std::string& prefix, const std::string& key) {
  return prefix.empty() ? key : prefix + "." + key;
}

json vectorJson(const Vec3d& v) { return json::array({v.x, v.y, v.z}); }

}  // namespace

Vec3d unitDirectionFromJson(const json& value, const std::string& key) {
  if (!value.is_array() || value.size() != 3)
    refuse(key, value, "is not an array of 3 numbers", DirectionAllowed);
  Vec3d w(0.0);
  for (int i = 0; i < 3; ++i) {
    if (!value[i].is_number()) refuse(key, value, "has a component that is not a number", DirectionAllowed);
    w[i] = value[i].get<double>();
    // JSON has no NaN or infinity, but a number too large for a double parses as infinity.
    if (!std::isfinite(w[i])) refuse(key, value, "has a component that is not finite", DirectionAllowed);
  }
  const double length = std::sqrt(w.x * w.x + w.y * w.y + w.z * w.z);
  if (!(std::abs(length - 1.0) <= UnitLengthTolerance)) {
    char problem[64];
    std::snprintf(problem, sizeof problem, "is not a unit vector (length %.9g)", length);
    refuse(key, value, problem, DirectionAllowed);
  }
  return w / length;
}

DirectionPair directionPairFromJson(const json& value, const std::string& key) {
  const std::string name = key.empty() ? "pair" : key;
  if (!value.is_object()) refuse(name, value, "is not an object", PairAllowed);
  for (const auto& [member, memberValue] : value.items())
    if (member != "wi" && member != "wo")
      refuse(joinKey(key, member), memberValue, "is not a key of a direction pair", PairAllowed);
  DirectionPair pair;
  for (const char* member : {"wi", "wo"}) {
    const auto found = value.find(member);
    if (found == value.end()) refuse(name, value, std::string("has no \"") + member + "\"", PairAllowed);
    (member[1] == 'i' ? pair.wi : pair.wo) = unitDirectionFromJson(*found, joinKey(key, member));
  }
  return pair;
}

std::vector<DirectionPair> directionPairsFromJson(const json& value) {
  const std::string allowed = "a non-empty JSON array of " + PairAllowed + " objects";
  if (!value.is_array())
    refuse("directions", value.is_object() ? json("{...}") : value, "is not an array", allowed);
  if (value.empty()) refuse("directions", value, "is empty", allowed);
  std::vector<DirectionPair> pairs;
  pairs.reserve(value.size());
  for (size_t i = 0; i < value.size(); ++i)
    pairs.push_back(directionPairFromJson(value[i], '[' + std::to_string(i) + ']'));
  return pairs;
}

std::vector<PairValue> evaluatePairs(const BsdfModel& model, std::span<const DirectionPair> pairs) {
  std::vector<PairValue> values;
  values.reserve(pairs.size());
  for (const DirectionPair& pair : pairs)
    values.push_back({model.eval(pair.wi, pair.wo), model.pdf(pair.wi, pair.wo)});
  return values;
}

json pairValuesJson(std::span<const DirectionPair> pairs, std::span<const PairValue> values) {
  json out = json::array();
  for (size_t i = 0; i < pairs.size() && i < values.size(); ++i)
    out.push_back({{"wi", vectorJson(pairs[i].wi)},
                   {"wo", vectorJson(pairs[i].wo)},
                   {"f", vectorJson(values[i].f)},
                   {"pdf", values[i].pdf}});
  return out;
}

}  // namespace scatterlab
