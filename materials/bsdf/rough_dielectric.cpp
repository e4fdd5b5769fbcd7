#include "materials/bsdf/rough_dielectric.h"

#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>

#include "materials/bsdf/dielectric_index_spec.h"
#include "materials/bsdf/microfacet_spec.h"
#include "materials/registry/material_model.h"

namespace scatterlab {

std::unique_ptr<BsdfModel> makeRoughDielectric(MicrofacetType type, double alphaX, double alphaY, double eta,
                                               MultipleScattering multipleScattering) {
  // D divides by both roughnesses: 0 or a non-finite value has no meaningful lobe.
  for (const double alpha : {alphaX, alphaY}) {
    if (!(alpha > 0.0) || !std::isfinite(alpha))
      throw std::invalid_argument("microfacet roughness must be positive and finite, got " +
                                  std::to_string(alpha));
  }
  if (!(eta > 0.0) || !std::isfinite(eta) || eta == 1.0)
    throw std::invalid_argument("rough dielectric index must be positive, finite and not 1, got " +
                                std::to_string(eta));
  switch (type) {
    case MicrofacetType::Ggx:
      return std::make_unique<RoughDielectricBsdf<GgxDistribution<double>>>(
          GgxDistribution<double>(alphaX, alphaY), eta, multipleScattering);
    case MicrofacetType::Beckmann:
      return std::make_unique<RoughDielectricBsdf<BeckmannDistribution<double>>>(
          BeckmannDistribution<double>(alphaX, alphaY), eta, multipleScattering);
  }
  throw std::invalid_argument("unknown microfacet distribution");
}

// ---------------------------------------------------------------------------------------
// The material registry's "rough-dielectric" model (materials/registry/model_list.h): the
// parameter spec and the function that builds it.

namespace {

using nlohmann::json;

std::unique_ptr<BsdfModel> buildRoughDielectric(const MaterialParameters& p) {
  const Vec2d alpha = p.pair("alpha");
  const MultipleScattering multipleScattering = choiceValue(MultipleScatterings, p.choice("multiscatter"));
  // The compensation's albedo tables are per side and per |cos|: isotropic roughness only
  // (rough_dielectric_multiscatter.h).
  if (multipleScattering == MultipleScattering::KullaConty && alpha.x != alpha.y)
    throwMaterialKeyError(
        "alpha", json::array({alpha.x, alpha.y}),
        "is anisotropic, which \"multiscatter\": \"kulla-conty\" does not support",
        "one number in [0.001, 1] (isotropic) with \"multiscatter\": \"kulla-conty\", or \"multiscatter\": "
        "\"none\"");
  return makeRoughDielectric(choiceValue(MicrofacetTypes, p.choice("distribution")), alpha.x, alpha.y,
                             p.number("eta"), multipleScattering);
}

}  // namespace

MaterialModel roughDielectricModel() {
  return {
      .type = "rough-dielectric",
      .description =
          "Rough glass: GGX or Beckmann microfacet reflection and refraction, exact Fresnel, single "
          "scattering (loses energy as alpha grows) or with multiple-scattering compensation (lossless)",
      .citation =
          "Walter et al. 2007, Microfacet Models for Refraction through Rough Surfaces, eq. 16-21; Heitz "
          "2014 (height-correlated Smith G2, Beta form for refraction); Heitz 2018, Heitz & d'Eon 2014 "
          "(visible normals); Kulla & Conty 2017 (multiple-scattering compensation)",
      .parameters = joinParameters(
          {microfacetParameters(),
           {dielectricIndexParameter(RoughDielectricIndexRange,
                                     "index of refraction inside (below the surface) relative to outside"),
            multipleScatteringParameter("reflection and transmission parts and per-material albedo tables; "
                                        "isotropic alpha only")}}),
      .alternatives = {},
      .build = buildRoughDielectric,
      .lobeWidthParameter = "alpha",
      .losslessExamples =
          {{{"type", "rough-dielectric"}, {"alpha", 0.3}, {"eta", 1.5}, {"multiscatter", "kulla-conty"}}},
  };
}

}  // namespace scatterlab
