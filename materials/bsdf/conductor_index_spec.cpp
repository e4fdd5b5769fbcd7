#include "materials/bsdf/conductor_index_spec.h"

#include <stdexcept>

#include "materials/bsdf/metals.h"

namespace scatterlab {

namespace {

std::vector<std::string> metalNames() {
  std::vector<std::string> names;
  for (const MetalIor& metal : namedMetals()) names.emplace_back(metal.name);
  return names;
}

}  // namespace

std::vector<ParameterSpec> conductorIndexParameters() {
  return {{.name = "metal",
           .kind = ParameterKind::Choice,
           .choices = metalNames(),
           .defaultValue = "Au",
           .description = "a named metal's complex index of refraction, reduced to RGB"},
          {.name = "eta",
           .kind = ParameterKind::Rgb,
           .range = ValueRange::above(0.0),
           .description = "real part of the complex index of refraction per channel, with \"k\""},
          {.name = "k",
           .kind = ParameterKind::Rgb,
           .range = ValueRange::atLeast(0.0),
           .description = "extinction coefficient (imaginary part) per channel, with \"eta\""}};
}

std::vector<std::vector<std::string>> conductorIndexAlternatives() { return {{"metal"}, {"eta", "k"}}; }

ConductorIndex conductorIndex(const MaterialParameters& p) {
  if (!p.has("metal")) return {p.rgb("eta"), p.rgb("k")};
  const MetalIor* metal = findMetal(p.choice("metal"));
  if (!metal) throw std::logic_error("metal \"" + p.choice("metal") + "\" listed but not found");
  return {metal->eta, metal->k};
}

}  // namespace scatterlab
