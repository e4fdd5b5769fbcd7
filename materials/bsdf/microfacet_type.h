// The microfacet normal distributions a model can be built with (microfacet.h); what a
// material's "distribution" key selects.
#pragma once

namespace scatterlab {

enum class MicrofacetType { Ggx, Beckmann };

}  // namespace scatterlab
