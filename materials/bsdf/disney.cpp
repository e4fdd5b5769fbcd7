#include "materials/bsdf/disney.h"

#include <array>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>

#include "materials/core/lobe_choice.h"
#include "materials/registry/material_model.h"

namespace scatterlab {
namespace {

// Every lobe that can reflect anything keeps at least this share of the samples, split evenly,
// so that no lobe is left to the others' tails when the heuristic weights below misjudge it.
constexpr double LobeProbabilityFloor = 0.1;

void requireUnit(double value, const char* name) {
  if (!(value >= 0.0 && value <= 1.0))
    throw std::invalid_argument(std::string("Disney BRDF: ") + name + " must be in [0, 1], got " +
                                std::to_string(value));
}

}  // namespace

DisneyBsdf::DisneyBsdf(const DisneyParameters& p) : parameters_(p), terms_(disneyTerms(p)) {
  requireUnit(p.baseColor.x, "baseColor (r)");
  requireUnit(p.baseColor.y, "baseColor (g)");
  requireUnit(p.baseColor.z, "baseColor (b)");
  requireUnit(p.metallic, "metallic");
  requireUnit(p.subsurface, "subsurface");
  requireUnit(p.specular, "specular");
  requireUnit(p.specularTint, "specularTint");
  requireUnit(p.roughness, "roughness");
  requireUnit(p.anisotropic, "anisotropic");
  requireUnit(p.sheen, "sheen");
  requireUnit(p.sheenTint, "sheenTint");
  requireUnit(p.clearcoat, "clearcoat");
  requireUnit(p.clearcoatGloss, "clearcoatGloss");
  // The diffuse, subsurface and sheen terms vanish identically for a metal, or for a black base
  // without sheen; the clearcoat without clearcoat. Such lobes are never sampled.
  hasDiffuse_ = terms_.dielectric > 0 && (disneyLuminance(p.baseColor) > 0 || p.sheen > 0);
  hasClearcoat_ = p.clearcoat > 0;
}

// In proportion to rough estimates of each lobe's albedo at wi: (1 - metallic) (luminance of
// the base + sheen) for the cosine lobe, the luminance of the specular Fresnel term at wi for
// the GGX lobe, 0.25 clearcoat times its Fresnel term at wi for the GTR1 lobe; mixed with an
// even split over the lobes that are present (LobeProbabilityFloor). Only the parameters and
// wi enter, so pdf() is the exact density of the mixture.
DisneyBsdf::LobeProbabilities DisneyBsdf::lobeProbabilities(const Vec3d& wi) const {
  const double cosI = std::clamp(wi.z, 0.0, 1.0);
  const double diffuse =
      hasDiffuse_ ? terms_.dielectric * (disneyLuminance(terms_.base) + parameters_.sheen) : 0.0;
  const double specular = disneyLuminance(fresnelSchlick(terms_.specularF0, cosI));
  const double clearcoat = hasClearcoat_ ? terms_.clearcoatWeight * fresnelSchlick(0.04, cosI) : 0.0;
  const double total = diffuse + specular + clearcoat;
  const double lobes = 1.0 + (hasDiffuse_ ? 1.0 : 0.0) + (hasClearcoat_ ? 1.0 : 0.0);
  const double floorShare = total > 0 ? LobeProbabilityFloor / lobes : 1.0 / lobes;
  const double scale = total > 0 ? (1.0 - LobeProbabilityFloor) / total : 0.0;
  LobeProbabilities p;
  p.diffuse = hasDiffuse_ ? diffuse * scale + floorShare : 0.0;
  p.clearcoat = hasClearcoat_ ? clearcoat * scale + floorShare : 0.0;
  p.specular = 1.0 - p.diffuse - p.clearcoat;
  return p;
}

double DisneyBsdf::pdf(const Vec3d& wi, const Vec3d& wo, TransportMode) const {
  if (!(wi.z > 0) || !(wo.z > 0)) return 0.0;
  const LobeProbabilities p = lobeProbabilities(wi);
  const Vec3d h = reflectionHalfVector(wi, wo);
  double density = p.specular * reflectedDensity(terms_.specular.pdfVisible(wi, h), wo, h);
  if (hasDiffuse_) density += p.diffuse * cosineHemispherePdf(wo.z);
  if (hasClearcoat_) density += p.clearcoat * reflectedDensity(terms_.clearcoat.pdfClassic(h), wo, h);
  return density;
}

std::optional<BsdfSample> DisneyBsdf::sample(const Vec3d& wi, double uLobe, const Vec2d& u,
                                             TransportMode) const {
  if (!(wi.z > 0)) return std::nullopt;
  const LobeProbabilities p = lobeProbabilities(wi);
  // Absent lobes have probability 0 (lobeProbabilities) and are never chosen.
  const std::array<double, 3> probabilities{p.diffuse, p.specular, p.clearcoat};
  Vec3d wo;
  LobeFlags lobe = LobeFlags::GlossyReflection;
  switch (chooseLobe(uLobe, probabilities).lobe) {
    case 0:
      wo = sampleCosineHemisphere(u);
      lobe = LobeFlags::DiffuseReflection;
      break;
    case 2: wo = reflect(wi, terms_.clearcoat.sampleClassic(u)); break;
    default: wo = reflect(wi, terms_.specular.sampleVisible(wi, u));
  }
  if (!(wo.z > 0)) return std::nullopt;
  // The mixture density and the weight from (wi, wo) alone, as pdf() and eval() compute them.
  const double density = pdf(wi, wo);
  if (!(density > 0)) return std::nullopt;
  return BsdfSample{wo, eval(wi, wo) * (wo.z / density), density, lobe, 1.0};
}

// ---------------------------------------------------------------------------------------
// The material registry's "disney" model (materials/registry/model_list.h): the
// parameter spec and the function that builds it.

namespace {

using nlohmann::json;

std::unique_ptr<BsdfModel> buildDisney(const MaterialParameters& p) {
  DisneyParameters d;
  d.baseColor = p.rgb("baseColor");
  d.metallic = p.number("metallic");
  d.subsurface = p.number("subsurface");
  d.specular = p.number("specular");
  d.specularTint = p.number("specularTint");
  d.roughness = p.number("roughness");
  d.anisotropic = p.number("anisotropic");
  d.sheen = p.number("sheen");
  d.sheenTint = p.number("sheenTint");
  d.clearcoat = p.number("clearcoat");
  d.clearcoatGloss = p.number("clearcoatGloss");
  return std::make_unique<DisneyBsdf>(d);
}

}  // namespace

MaterialModel disneyModel() {
  const DisneyParameters d;  // disney.brdf's defaults
  const ValueRange unit = ValueRange::closed(0.0, 1.0);
  return {
      .type = "disney",
      .description =
          "Disney principled BRDF as disney.brdf: retro-reflective diffuse or subsurface, sheen, "
          "anisotropic GGX specular, GTR1 clearcoat (not energy-conserving)",
      .citation =
          "Burley 2012, Physically-Based Shading at Disney, section 5 and appendix B; BRDF Explorer "
          "disney.brdf (separable Smith G)",
      .parameters =
          {{.name = "baseColor",
            .kind = ParameterKind::Rgb,
            .range = unit,
            .defaultValue = json::array({d.baseColor.x, d.baseColor.y, d.baseColor.z}),
            .description = "base colour per linear-RGB channel (the BRDF Explorer's default "
                           "(0.82, 0.67, 0.16) is gamma 2.2, linearised here)"},
           numberParameter("metallic", unit, d.metallic, "0 dielectric, 1 metal (specular tinted by base)"),
           numberParameter("subsurface", unit, d.subsurface,
                           "blend from the diffuse to the Hanrahan-Krueger-like subsurface shape"),
           numberParameter("specular", unit, d.specular, "dielectric specular F0 = 0.08 specular"),
           numberParameter("specularTint", unit, d.specularTint,
                           "tints the dielectric F0 toward the base hue"),
           numberParameter(
               "roughness", unit, d.roughness,
               "alpha = roughness^2 (alpha_x, alpha_y >= 0.001); also the diffuse retro-reflection"),
           numberParameter(
               "anisotropic", unit, d.anisotropic,
               "aspect sqrt(1 - 0.9 anisotropic): alpha_x = alpha / aspect, alpha_y = alpha aspect"),
           numberParameter("sheen", unit, d.sheen, "grazing sheen strength"),
           numberParameter("sheenTint", unit, d.sheenTint, "tints the sheen toward the base hue"),
           numberParameter("clearcoat", unit, d.clearcoat,
                           "clearcoat layer strength (weight 0.25 clearcoat)"),
           numberParameter("clearcoatGloss", unit, d.clearcoatGloss,
                           "clearcoat GTR1 alpha = 0.1 (gloss 0) .. 0.001 (gloss 1)")},
      .alternatives = {},
      .build = buildDisney,
      .lobeWidthParameter = "roughness",
  };
}

}  // namespace scatterlab
