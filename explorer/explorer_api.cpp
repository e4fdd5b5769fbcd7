// The explorer's door into the models (docs/explorer.md): C functions exported from the
// WebAssembly build of materials/, called by the page's script (explorer/page/explorer.js).
// Every number the page shows comes from here: the registry builds the model from its JSON
// description, and f, pdf and samples are the model's own eval, pdf and sample, the code the
// scatterlab executable runs. The page computes only where to look (directions of a plot) and
// how to draw.
//
// Strings are returned as pointers to a buffer that stays valid until the next call that
// returns a string; the page copies them at once (UTF8ToString). Arrays are passed as pointers
// into the module's memory (HEAPF64).
#include <emscripten/emscripten.h>

#include <cmath>
#include <cstdint>
#include <list>
#include <map>
#include <memory>
#include <string>
#include <utility>

#include <nlohmann/json.hpp>

#include "materials/bsdf/direction_pairs.h"
#include "materials/bssrdf/subsurface_registry.h"
#include "materials/core/rng.h"
#include "materials/core/spherical.h"
#include "materials/registry/material_file.h"
#include "materials/registry/model_list.h"
#include "materials/registry/parameter_spec.h"
#include "materials/registry/spec_validation.h"

namespace scatterlab {
namespace {

using nlohmann::json;

std::string returned;  // what the last string-returning call returned
const char* hold(const json& value) {
  returned = value.dump();
  return returned.c_str();
}
json errorJson(const std::string& message) { return {{"error", message}}; }

struct BuiltModel {
  std::unique_ptr<BsdfModel> model;
  json completed;
};

// A material from the page: JSON text of an object (the page passes objects as
// JSON.stringify'd text). Errors are the registry's own messages.
json parseMaterial(const char* text) {
  const std::string argument = text ? text : "";
  if (!isInlineMaterial(argument))
    throw MaterialError(
        "material: " + json(argument).dump() +
        " is not a material; allowed: a JSON object such as {\"type\": \"lambertian\"} (as text or "
        "as an object)");
  return loadMaterialArgument(argument);
}

BuiltModel build(const json& material) { return {makeFarFieldBsdf(material), completeMaterial(material)}; }

// Models built by handle (the page's views), and a few by description (the console API), so
// that a measured table is read once, not at every call.
std::map<int, BuiltModel> handles;
int nextHandle = 1;

constexpr size_t CachedDescriptions = 8;
std::list<std::pair<std::string, BuiltModel>> byDescription;  // most recently used first

const BuiltModel& cachedModel(const json& material) {
  const std::string key = material.dump();
  for (auto it = byDescription.begin(); it != byDescription.end(); ++it)
    if (it->first == key) {
      byDescription.splice(byDescription.begin(), byDescription, it);
      return byDescription.front().second;
    }
  byDescription.emplace_front(key, build(material));
  if (byDescription.size() > CachedDescriptions) byDescription.pop_back();
  return byDescription.front().second;
}

const BsdfModel* modelOf(int handle) {
  const auto found = handles.find(handle);
  return found == handles.end() ? nullptr : found->second.model.get();
}

json flagsJson(const BsdfModel& model) {
  const LobeFlags flags = model.flags();
  return {{"transmission", hasAny(flags, LobeFlags::Transmission)},
          {"delta", hasAny(flags, LobeFlags::Specular)},
          {"nonDelta", hasAny(flags, LobeFlags::Diffuse | LobeFlags::Glossy)}};
}

}  // namespace
}  // namespace scatterlab

using namespace scatterlab;

extern "C" {

// The registry's catalog, as `scatterlab models --json` prints it.
EMSCRIPTEN_KEEPALIVE const char* scatterlab_catalog() { return hold(materialCatalogJson()); }

// Validates and builds a material: {"handle", "material" (completed), "flags"}, or {"error"}
// with the registry's message (the key, the value given and what is allowed).
EMSCRIPTEN_KEEPALIVE const char* scatterlab_build(const char* material) {
  try {
    BuiltModel built = build(parseMaterial(material));
    const json flags = flagsJson(*built.model);
    const json completed = built.completed;
    const int handle = nextHandle++;
    handles.emplace(handle, std::move(built));
    return hold({{"handle", handle}, {"material", completed}, {"flags", flags}});
  } catch (const std::exception& error) {
    return hold(errorJson(error.what()));
  }
}

EMSCRIPTEN_KEEPALIVE void scatterlab_release(int handle) { handles.erase(handle); }

// f and pdf at `count` pairs: `pairs` holds wi, wo (6 doubles per pair, unit vectors in the
// local frame), `out` receives f_r, f_g, f_b, pdf (4 doubles per pair). Radiance transport, as
// `scatterlab eval`. Returns 0, or -1 for an unknown handle.
EMSCRIPTEN_KEEPALIVE int scatterlab_eval_pairs(int handle, const double* pairs, int count, double* out) {
  const BsdfModel* model = modelOf(handle);
  if (!model) return -1;
  for (int i = 0; i < count; ++i) {
    const double* p = pairs + 6 * i;
    const Vec3d wi(p[0], p[1], p[2]), wo(p[3], p[4], p[5]);
    const Rgb f = model->eval(wi, wo);
    double* o = out + 4 * i;
    o[0] = f.x;
    o[1] = f.y;
    o[2] = f.z;
    o[3] = model->pdf(wi, wo);
  }
  return 0;
}

// The console API's eval and pdf: exactly what `scatterlab eval --json` prints for the material
// (JSON text) at the pairs (JSON text of [{"wi", "wo"}, ...]), checked by the same code
// (direction_pairs.h): {"material", "values": [{"wi", "wo", "f", "pdf"}]} or {"error"}.
EMSCRIPTEN_KEEPALIVE const char* scatterlab_eval_json(const char* material, const char* pairsText) {
  try {
    json pairsJson;
    try {
      pairsJson = json::parse(pairsText ? pairsText : "");
    } catch (const json::parse_error&) {
      throw DirectionError(
          "directions: not valid JSON; allowed: [{\"wi\": [x, y, z], \"wo\": [x, y, z]}, ...]");
    }
    const std::vector<DirectionPair> pairs = directionPairsFromJson(pairsJson);
    const BuiltModel& built = cachedModel(parseMaterial(material));
    const std::vector<PairValue> values = evaluatePairs(*built.model, pairs);
    return hold({{"material", built.completed}, {"values", pairValuesJson(pairs, values)}});
  } catch (const std::exception& error) {
    return hold(errorJson(error.what()));
  }
}

// `count` draws of the model's own sampler at wi, with the counter-based generator of the test
// kit (rng.h: uLobe first, then u) under `seed`: the same seed gives the same samples.
// `out` receives 8 doubles per draw: wo (3), pdf, weight (3), 1 for a delta lobe; a draw where
// the sampler returned nothing has pdf 0 and weight 0. Returns the number of failed draws, or
// -1 for an unknown handle.
EMSCRIPTEN_KEEPALIVE int scatterlab_sample(int handle, double wiX, double wiY, double wiZ, int count,
                                           double seed, double* out) {
  const BsdfModel* model = modelOf(handle);
  if (!model) return -1;
  CounterRng rng(static_cast<uint64_t>(seed), 0);
  const Vec3d wi(wiX, wiY, wiZ);
  int failed = 0;
  for (int i = 0; i < count; ++i) {
    const double uLobe = rng.uniform();
    const Vec2d u = rng.uniform2D();
    const std::optional<BsdfSample> s = model->sample(wi, uLobe, u);
    double* o = out + 8 * i;
    if (!s) {
      ++failed;
      for (int k = 0; k < 8; ++k) o[k] = 0.0;
      continue;
    }
    o[0] = s->wo.x;
    o[1] = s->wo.y;
    o[2] = s->wo.z;
    o[3] = s->pdf;
    o[4] = s->weight.x;
    o[5] = s->weight.y;
    o[6] = s->weight.z;
    o[7] = s->isDelta() ? 1.0 : 0.0;
  }
  return failed;
}

// The directional albedo at each theta of `thetaDeg` (azimuth phiDeg): the Monte Carlo mean of
// the sampler's weights f |cos wo| / pdf, whose expectation is the albedo (the sampler is
// exact, as the kit proves), over strata x strata stratified (u0, u1) with uLobe random.
// Counted in energyTransportMode (bsdf.h: power through refractions). `out` receives r, g, b
// and the standard error of the mean of their average (ignoring the stratification, so an
// upper bound) per angle. Returns the number of draws whose weight was negative or not finite
// (left out of the mean), or -1 for an unknown handle.
EMSCRIPTEN_KEEPALIVE int scatterlab_albedo(int handle, const double* thetaDeg, int count, double phiDeg,
                                           int strata, double seed, double* out) {
  const BsdfModel* model = modelOf(handle);
  if (!model || strata < 1) return -1;
  const TransportMode mode = energyTransportMode(*model);
  const double draws = double(strata) * strata;
  int invalid = 0;
  for (int k = 0; k < count; ++k) {
    const Vec3d wi = directionFromDegrees(thetaDeg[k], phiDeg);
    CounterRng rng(static_cast<uint64_t>(seed), static_cast<uint64_t>(k));
    Rgb sum(0.0);
    double sumSquares = 0.0;
    for (int i = 0; i < strata; ++i)
      for (int j = 0; j < strata; ++j) {
        const double uLobe = rng.uniform();
        const Vec2d jitter = rng.uniform2D();
        const Vec2d u((i + jitter.x) / strata, (j + jitter.y) / strata);
        const std::optional<BsdfSample> s = model->sample(wi, uLobe, u, mode);
        if (!s) continue;  // a failed draw scatters nothing: weight 0
        const Rgb& w = s->weight;
        if (!(std::isfinite(w.x) && std::isfinite(w.y) && std::isfinite(w.z)) || w.x < 0 || w.y < 0 ||
            w.z < 0) {
          ++invalid;
          continue;
        }
        sum += w;
        const double mean = (w.x + w.y + w.z) / 3.0;
        sumSquares += mean * mean;
      }
    const Rgb albedo = sum / draws;
    const double average = (albedo.x + albedo.y + albedo.z) / 3.0;
    const double variance = std::max(sumSquares / draws - average * average, 0.0);
    double* o = out + 4 * k;
    o[0] = albedo.x;
    o[1] = albedo.y;
    o[2] = albedo.z;
    o[3] = std::sqrt(variance / draws);
  }
  return invalid;
}

}  // extern "C"
