// The complex index of refraction of the conductors (conductor.h, smooth_conductor.h), as a
// named metal (metals.h) or as eta and k, the same way for every conductor model
// (materials/registry/parameter_spec.h).
#pragma once

#include <string>
#include <vector>

#include "materials/core/math.h"
#include "materials/registry/parameter_spec.h"

namespace scatterlab {

// "metal", and its alternative "eta" with "k".
std::vector<ParameterSpec> conductorIndexParameters();
// {{"metal"}, {"eta", "k"}}: a material gives one or the other (MaterialModel::alternatives).
std::vector<std::vector<std::string>> conductorIndexAlternatives();

struct ConductorIndex {
  Rgb eta, k;
};

// The index the validated parameters give: the named metal's, or eta and k.
ConductorIndex conductorIndex(const MaterialParameters& p);

}  // namespace scatterlab
