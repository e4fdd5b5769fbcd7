#include "materials/bsdf/sample_queries.h"

#include "materials/bsdf/direction_pairs.h"

namespace scatterlab {

namespace {

using nlohmann::json;

const std::string QueryAllowed =
    "an object {\"wi\": [x, y, z], \"u_lobe\": a, \"u\": [b, c]}, a, b, c in [0, 1)";

[[noreturn]] void refuse(const std::string& key, const json& value, const std::string& problem) {
  throw DirectionError(key + ": " + value.dump() + " " + problem + "; allowed: " + QueryAllowed);
}

double unitInterval(const json& value, const std::string& key) {
  if (!value.is_number()) refuse(key, value, "is not a number");
  const double u = value.get<double>();
  if (!(u >= 0.0 && u < 1.0)) refuse(key, value, "is not in [0, 1)");
  return u;
}

SampleQuery sampleQueryFromJson(const json& value, const std::string& key) {
  if (!value.is_object()) refuse(key, value, "is not an object");
  for (const auto& [member, memberValue] : value.items())
    if (member != "wi" && member != "u_lobe" && member != "u")
      refuse(key + "." + member, memberValue, "is not a key of a sampling query");
  for (const char* member : {"wi", "u_lobe", "u"})
    if (!value.contains(member)) refuse(key, value, std::string("has no \"") + member + "\"");
  SampleQuery query;
  query.wi = unitDirectionFromJson(value["wi"], key + ".wi");
  query.uLobe = unitInterval(value["u_lobe"], key + ".u_lobe");
  const json& u = value["u"];
  if (!u.is_array() || u.size() != 2) refuse(key + ".u", u, "is not an array of 2 numbers");
  query.u = {unitInterval(u[0], key + ".u[0]"), unitInterval(u[1], key + ".u[1]")};
  return query;
}

json vectorJson(const Vec3d& v) { return json::array({v.x, v.y, v.z}); }

}  // namespace

std::vector<SampleQuery> sampleQueriesFromJson(const json& value) {
  if (!value.is_array())
    refuse("samples", value.is_object() ? json("{...}") : value, "is not an array of queries");
  if (value.empty()) refuse("samples", value, "is empty");
  std::vector<SampleQuery> queries;
  queries.reserve(value.size());
  for (size_t i = 0; i < value.size(); ++i)
    queries.push_back(sampleQueryFromJson(value[i], '[' + std::to_string(i) + ']'));
  return queries;
}

json sampleQueryValuesJson(const BsdfModel& model, std::span<const SampleQuery> queries) {
  json out = json::array();
  for (const SampleQuery& q : queries) {
    const std::optional<BsdfSample> s = model.sample(q.wi, q.uLobe, q.u);
    const BsdfSample value = s.value_or(BsdfSample{Vec3d(0.0), Rgb(0.0), 0.0});
    out.push_back({{"wi", vectorJson(q.wi)},
                   {"u_lobe", q.uLobe},
                   {"u", json::array({q.u.x, q.u.y})},
                   {"valid", s.has_value()},
                   {"wo", vectorJson(value.wo)},
                   {"weight", vectorJson(value.weight)},
                   {"pdf", value.pdf},
                   {"delta", s && s->isDelta()}});
  }
  return out;
}

}  // namespace scatterlab
