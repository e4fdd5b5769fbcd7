#include "materials/bsdf/rough_plastic.h"

#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>

#include "materials/bsdf/dielectric_index_spec.h"
#include "materials/bsdf/microfacet_spec.h"
#include "materials/registry/material_model.h"

namespace scatterlab {

std::unique_ptr<BsdfModel> makeRoughPlastic(MicrofacetType type, double alpha, const Rgb& kd, double eta) {
  // D divides by the roughness: 0 or a non-finite value has no meaningful lobe.
  if (!(alpha > 0.0) || !std::isfinite(alpha))
    throw std::invalid_argument("rough plastic: roughness must be positive and finite, got " +
                                std::to_string(alpha));
  if (!(eta >= 1.0) || !std::isfinite(eta))
    throw std::invalid_argument("rough plastic: the coating's index must be finite and >= 1, got " +
                                std::to_string(eta));
  for (int c = 0; c < 3; ++c)
    if (!(kd[c] >= 0.0 && kd[c] <= 1.0))
      throw std::invalid_argument("rough plastic: diffuse reflectance must be in [0, 1], got " +
                                  std::to_string(kd[c]));
  switch (type) {
    case MicrofacetType::Ggx:
      return std::make_unique<RoughPlasticBsdf<GgxDistribution<double>>>(
          GgxDistribution<double>(alpha, alpha), kd, eta);
    case MicrofacetType::Beckmann:
      return std::make_unique<RoughPlasticBsdf<BeckmannDistribution<double>>>(
          BeckmannDistribution<double>(alpha, alpha), kd, eta);
  }
  throw std::invalid_argument("unknown microfacet distribution");
}

// ---------------------------------------------------------------------------------------
// The material registry's "rough-plastic" model (materials/registry/model_list.h): the
// parameter spec and the function that builds it.

namespace {

std::unique_ptr<BsdfModel> buildRoughPlastic(const MaterialParameters& p) {
  return makeRoughPlastic(choiceValue(MicrofacetTypes, p.choice("distribution")), p.number("alpha"),
                          p.rgb("diffuse"), p.number("eta"));
}

}  // namespace

MaterialModel roughPlasticModel() {
  return {
      .type = "rough-plastic",
      .description =
          "Rough dielectric coating (GGX or Beckmann, isotropic) over a Lambertian base, internal "
          "reflections summed; energy-coupled: albedo <= 1, lossless for a white base",
      .citation =
          "Walter et al. 2007 eq. 20 (coating); Weidlich & Wilkie 2007 and Mitsuba 0.6 plastic/roughplastic "
          "(layer, 1 / (1 - kd Fdr) series, 1/eta^2); Kelemen & Szirmay-Kalos 2001 (1 - E coupling)",
      .parameters = {{.name = "distribution",
                      .kind = ParameterKind::Choice,
                      .choices = choiceNames(MicrofacetTypes),
                      .defaultValue = "ggx",
                      .description = "microfacet normal distribution of the coating"},
                     {.name = "alpha",
                      .kind = ParameterKind::Number,
                      .range = ValueRange::closed(0.001, 1.0),
                      .defaultValue = 0.1,
                      .description = "roughness of the coating (isotropic: the energy coupling tabulates the "
                                     "coating's albedo over the incident angle)"},
                     {.name = "diffuse",
                      .kind = ParameterKind::Rgb,
                      .range = ValueRange::closed(0.0, 1.0),
                      .defaultValue = 0.5,
                      .description = "reflectance of the base under the coating per linear-RGB channel"},
                     dielectricIndexParameter(DielectricIndexRange,
                                              "index of refraction of the coating relative to outside")},
      .alternatives = {},
      .build = buildRoughPlastic,
      .lobeWidthParameter = "alpha",
      .losslessExamples = {{{"type", "rough-plastic"}, {"alpha", 0.2}, {"diffuse", 1.0}, {"eta", 1.5}}},
  };
}

}  // namespace scatterlab
