#include "materials/bsdf/conductor.h"

#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>

#include "materials/bsdf/conductor_index_spec.h"
#include "materials/bsdf/kulla_conty_conductor.h"
#include "materials/bsdf/microfacet_spec.h"
#include "materials/registry/material_model.h"

namespace scatterlab {

std::unique_ptr<BsdfModel> makeMicrofacetConductor(MicrofacetType type, double alphaX, double alphaY,
                                                   const Rgb& eta, const Rgb& k, MicrofacetSampling sampling,
                                                   MultipleScattering multipleScattering) {
  // D divides by both roughnesses: 0 or a non-finite value has no meaningful lobe.
  for (const double alpha : {alphaX, alphaY}) {
    if (!(alpha > 0.0) || !std::isfinite(alpha))
      throw std::invalid_argument("microfacet roughness must be positive and finite, got " +
                                  std::to_string(alpha));
  }
  const auto make =
      [&]<typename Distribution>(const Distribution& distribution) -> std::unique_ptr<BsdfModel> {
    if (multipleScattering == MultipleScattering::KullaConty)
      return std::make_unique<KullaContyConductorBsdf<Distribution>>(distribution, eta, k, sampling);
    return std::make_unique<MicrofacetConductorBsdf<Distribution>>(distribution, eta, k, sampling);
  };
  switch (type) {
    case MicrofacetType::Ggx: return make(GgxDistribution<double>(alphaX, alphaY));
    case MicrofacetType::Beckmann: return make(BeckmannDistribution<double>(alphaX, alphaY));
  }
  throw std::invalid_argument("unknown microfacet distribution");
}

// ---------------------------------------------------------------------------------------
// The material registry's "conductor" model (materials/registry/model_list.h): the
// parameter spec and the function that builds it.

namespace {

constexpr std::array<NamedChoice<MicrofacetSampling>, 2> MicrofacetSamplings{{
    {"visible", MicrofacetSampling::Visible},
    {"classic", MicrofacetSampling::Classic},
}};

std::unique_ptr<BsdfModel> buildConductor(const MaterialParameters& p) {
  const ConductorIndex index = conductorIndex(p);
  const Vec2d alpha = p.pair("alpha");
  return makeMicrofacetConductor(choiceValue(MicrofacetTypes, p.choice("distribution")), alpha.x, alpha.y,
                                 index.eta, index.k, choiceValue(MicrofacetSamplings, p.choice("sampling")),
                                 choiceValue(MultipleScatterings, p.choice("multiscatter")));
}

}  // namespace

MaterialModel conductorModel() {
  return {
      .type = "conductor",
      .description = "Rough metal: anisotropic GGX or Beckmann microfacets, exact conductor Fresnel",
      .citation =
          "Walter et al. 2007 (microfacet BRDF); Heitz 2014 (Smith height-correlated G2); "
          "Heitz 2018 (GGX visible normals); Kulla & Conty 2017 (multiple-scattering compensation)",
      .parameters = joinParameters({microfacetParameters(),
                                    conductorIndexParameters(),
                                    {{.name = "sampling",
                                      .kind = ParameterKind::Choice,
                                      .choices = choiceNames(MicrofacetSamplings),
                                      .defaultValue = "visible",
                                      .description = "visible-normal sampling, or classic D cos sampling"},
                                     multipleScatteringParameter("tabulated albedos")}}),
      .alternatives = conductorIndexAlternatives(),
      .build = buildConductor,
      .lobeWidthParameter = "alpha",
      .losslessExamples = {{{"type", "conductor"},
                            {"distribution", "ggx"},
                            {"alpha", 0.3},
                            {"multiscatter", "kulla-conty"},
                            {"eta", {1, 1, 1}},
                            {"k", {1e8, 1e8, 1e8}}},
                           {{"type", "conductor"},
                            {"distribution", "beckmann"},
                            {"alpha", 0.3},
                            {"multiscatter", "kulla-conty"},
                            {"eta", {1, 1, 1}},
                            {"k", {1e8, 1e8, 1e8}}},
                           {{"type", "conductor"},
                            {"alpha", {0.3, 0.1}},
                            {"multiscatter", "kulla-conty"},
                            {"eta", {1, 1, 1}},
                            {"k", {1e8, 1e8, 1e8}}}},
  };
}

}  // namespace scatterlab
