// The parameters the rough microfacet models share (conductor.h, rough_dielectric.h,
// rough_plastic.h): the normal distribution, the roughness alpha and multiple scattering
// between microfacets, described once so that every model offers them the same way
// (materials/registry/parameter_spec.h).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "materials/bsdf/kulla_conty.h"
#include "materials/bsdf/microfacet_type.h"
#include "materials/registry/parameter_spec.h"

namespace scatterlab {

inline constexpr std::array<NamedChoice<MicrofacetType>, 2> MicrofacetTypes{{
    {"ggx", MicrofacetType::Ggx},
    {"beckmann", MicrofacetType::Beckmann},
}};
inline constexpr std::array<NamedChoice<MultipleScattering>, 2> MultipleScatterings{{
    {"none", MultipleScattering::None},
    {"kulla-conty", MultipleScattering::KullaConty},
}};

// The microfacet normals of the rough models (conductor, rough dielectric): "distribution"
// and the pair "alpha".
std::vector<ParameterSpec> microfacetParameters();

// Multiple scattering between microfacets (conductor.h, rough_dielectric.h). Off by default:
// the single-scattering model is the published one (and the one measured-data fits use);
// existing materials keep their meaning. `lobe`: what the model's compensation lobe has.
ParameterSpec multipleScatteringParameter(const std::string& lobe);

}  // namespace scatterlab
