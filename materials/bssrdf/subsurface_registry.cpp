#include "materials/bssrdf/subsurface_registry.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "materials/bsdf/dielectric_index_spec.h"
#include "materials/bssrdf/measured_media.h"
#include "materials/bssrdf/subsurface_far_field_brdf.h"
#include "materials/registry/model_list.h"
#include "materials/registry/spec_validation.h"

namespace scatterlab {

namespace {

using nlohmann::json;

constexpr std::array<NamedChoice<ProfileModel>, 4> Profiles{{{"dipole", ProfileModel::Dipole},
                                                             {"better-dipole", ProfileModel::BetterDipole},
                                                             {"beam-diffusion", ProfileModel::BeamDiffusion},
                                                             {"burley", ProfileModel::Burley}}};
constexpr std::array<NamedChoice<BurleyFit>, 3> BurleyFits{
    {{"searchlight", BurleyFit::Searchlight},
     {"diffuse", BurleyFit::DiffuseTransmission},
     {"searchlight-dmfp", BurleyFit::SearchlightDiffuseMfp}}};
constexpr std::array<NamedChoice<SubsurfaceBoundary>, 2> Boundaries{
    {{"smooth", SubsurfaceBoundary::Smooth}, {"rough", SubsurfaceBoundary::Rough}}};

// Jensen et al. 2001 use 1.3 for every medium but marble (1.5).
constexpr double DefaultEta = 1.3;
constexpr double DefaultRoughness = 0.1;
const ValueRange EtaRange{0.0, 4.0, true, false};
const ValueRange RoughnessRange = ValueRange::closed(0.001, 1.0);

// Defaults that depend on other keys, and combinations the spec cannot rule out.
void completeDependent(MaterialParameters& p, json& completed) {
  if (!p.has("eta")) {
    const MeasuredMedium* medium = p.has("medium") ? findMeasuredMedium(p.choice("medium")) : nullptr;
    const double eta = medium ? medium->eta : DefaultEta;
    p.set("eta", eta);
    completed["eta"] = eta;
  }
  const bool rough = p.choice("boundary") == "rough";
  if (rough && !p.has("roughness")) {
    p.set("roughness", DefaultRoughness);
    completed["roughness"] = DefaultRoughness;
  }
  // A rough boundary is the rough dielectric, with its index limit (dielectric_index_spec.h):
  // refused here, when the material is read, not when a render builds the boundary.
  if (rough && !RoughDielectricIndexRange.contains(p.number("eta")))
    throwMaterialKeyError("eta", completed["eta"], "is outside what a rough boundary can refract through",
                          "eta " + RoughDielectricIndexRange.describe() +
                              " with \"boundary\": \"rough\" (or \"boundary\": \"smooth\")");
  if (!rough && p.has("roughness"))
    throwMaterialKeyError("roughness", completed["roughness"], "applies to a rough boundary only",
                          "\"roughness\" with \"boundary\": \"rough\"");
  const bool burley = p.choice("profile") == "burley";
  if (burley && !p.has("burley_fit")) {
    p.set("burley_fit", std::string("searchlight"));
    completed["burley_fit"] = "searchlight";
  }
  if (!burley && p.has("burley_fit"))
    throwMaterialKeyError("burley_fit", completed["burley_fit"], "applies to the burley profile only",
                          "\"burley_fit\" with \"profile\": \"burley\"");
}

// Mean free paths from 1 nm to 1 km: beyond them a profile's values, which go as 1 / d^2 and
// exp(-r / d), overflow or vanish in double precision (R(r) of infinity, NaN averages).
constexpr double MinExtinction = 1e-6, MaxExtinction = 1e6;  // sigma_t = sigma_s + sigma_a, mm^-1

// Refuses a (scaled) medium outside that range, naming the key that put it there: "scale"
// when the description alone is inside it, else the coefficients the description gives.
void checkLengthScale(const MaterialParameters& p, const ScatteringMedium& medium, double scale,
                      const json& completed) {
  for (int c = 0; c < 3; ++c) {
    const double sigmaT = medium.sigmaS[c] + medium.sigmaA[c];
    if (sigmaT >= MinExtinction && sigmaT <= MaxExtinction) continue;
    const double unscaled = sigmaT / scale;
    const bool scaleMovedIt = scale != 1.0 && unscaled >= MinExtinction && unscaled <= MaxExtinction;
    const std::string key = scaleMovedIt       ? "scale"
                            : p.has("sigma_s") ? (medium.sigmaA[c] > medium.sigmaS[c] ? "sigma_a" : "sigma_s")
                            : p.has("mfp")     ? "mfp"
                                               : "scale";
    char value[64];
    std::snprintf(value, sizeof value, "%g", sigmaT);
    throwMaterialKeyError(
        key, completed.value(key, json()),
        std::string("gives an extinction sigma_s + sigma_a of ") + value + " mm^-1 in channel " + "rgb"[c] +
            (scale != 1.0 ? " (after \"scale\")" : "") + ", where the profile's values overflow",
        "sigma_s + sigma_a, times \"scale\", in [1e-6, 1e6] mm^-1 in every channel (mean free "
        "paths from 1 nm to 1 km)");
  }
}

// The medium the description gives, before the profile is built (scaled).
ScatteringMedium mediumOf(const MaterialParameters& p, ProfileModel model, const json& completed) {
  const double g = p.number("g"), eta = p.number("eta"), scale = p.number("scale");
  ScatteringMedium medium;
  medium.g = g;
  medium.eta = eta;
  if (p.has("medium")) {
    const MeasuredMedium* measured = findMeasuredMedium(p.choice("medium"));
    if (!measured) throw std::logic_error("medium \"" + p.choice("medium") + "\" listed but not found");
    medium.sigmaS = measured->sigmaSPrime / (1.0 - g);
    medium.sigmaA = measured->sigmaA;
  } else if (p.has("sigma_s")) {
    medium.sigmaS = p.rgb("sigma_s");
    medium.sigmaA = p.rgb("sigma_a");
    for (int c = 0; c < 3; ++c)
      if (!(medium.sigmaS[c] + medium.sigmaA[c] > 0))
        throwMaterialKeyError("sigma_a", completed["sigma_a"],
                              "leaves a channel with sigma_s + sigma_a = 0 (channel " + std::to_string(c) +
                                  ": no interaction, no profile)",
                              "sigma_s + sigma_a > 0 in every channel");
  } else {
    try {
      medium = mediumFromReflectance(model, p.rgb("reflectance"), p.rgb("mfp"), g, eta);
    } catch (const std::invalid_argument& error) {
      throwMaterialKeyError("reflectance", completed["reflectance"],
                            std::string("is out of reach (") + error.what() + ")",
                            "a reflectance the profile can produce at this eta and g");
    }
  }
  medium.sigmaS *= scale;
  medium.sigmaA *= scale;
  checkLengthScale(p, medium, scale, completed);
  return medium;
}

SubsurfaceMaterial buildSubsurface(const MaterialParameters& p, const json& completed) {
  SubsurfaceMaterial material;
  material.model = choiceValue(Profiles, p.choice("profile"));
  material.burleyFit =
      p.has("burley_fit") ? choiceValue(BurleyFits, p.choice("burley_fit")) : BurleyFit::Searchlight;
  material.boundary = choiceValue(Boundaries, p.choice("boundary"));
  material.roughness = p.has("roughness") ? p.number("roughness") : 0.0;
  material.medium = mediumOf(p, material.model, completed);
  try {
    material.profile = makeProfile(material.model, material.medium, material.burleyFit);
  } catch (const std::invalid_argument& error) {
    // The medium is what the user gave; burley_fit may be its default.
    const std::string key = p.has("sigma_s") ? "sigma_a" : p.has("reflectance") ? "reflectance" : "medium";
    throwMaterialKeyError(key, completed.value(key, json()),
                          "cannot be described with \"burley_fit\": " +
                              completed.value("burley_fit", json()).dump() + " (" + error.what() + ")",
                          "a medium with absorption, or \"burley_fit\": \"searchlight\" or \"diffuse\" for "
                          "one without");
  }
  // Nothing that is accepted may render or print as NaN: the profile at its own scale.
  bool finite = std::isfinite(material.profile->totalReflectance()[0]) &&
                std::isfinite(material.profile->totalReflectance()[1]) &&
                std::isfinite(material.profile->totalReflectance()[2]);
  for (int c = 0; c < 3 && finite; ++c) {
    const double mfp = 1.0 / (material.medium.sigmaS[c] + material.medium.sigmaA[c]);
    for (const double r : {0.01 * mfp, mfp, 10.0 * mfp}) {
      const Rgb value = material.profile->eval(r);
      finite = finite && std::isfinite(value[0]) && std::isfinite(value[1]) && std::isfinite(value[2]);
    }
  }
  if (!finite)
    throwMaterialKeyError("profile", completed["profile"],
                          "gives non-finite values for this medium (total reflectance or R(r))",
                          "a medium the profile can describe: another \"profile\", or other coefficients");
  return material;
}

ParameterSpec rgbParameter(std::string name, const ValueRange& range, std::string description) {
  return {.name = std::move(name),
          .kind = ParameterKind::Rgb,
          .range = range,
          .description = std::move(description)};
}

}  // namespace

MaterialModel subsurfaceMaterialModel() {
  return {
      .type = "subsurface",
      .kind = MaterialKind::Subsurface,
      .description =
          "Subsurface scattering (BSSRDF): a radial diffusion profile per RGB channel, sampled exactly "
          "(radius and multi-axis probe), behind a smooth or rough dielectric boundary",
      .citation =
          "Jensen et al. 2001 (dipole, measured media); d'Eon 2012 (better dipole); Habel et al. 2013 and "
          "pbrt-v3 (photon beam diffusion); Christensen & Burley 2015 (normalised diffusion); King et al. "
          "2013 (probe sampling)",
      .parameters =
          {{.name = "profile",
            .kind = ParameterKind::Choice,
            .choices = choiceNames(Profiles),
            .defaultValue = "burley",
            .description = "the diffusion profile R(r)"},
           {.name = "medium",
            .kind = ParameterKind::Choice,
            .choices = measuredMediumNames(),
            .defaultValue = "Skin1",
            .description = "a measured medium of Jensen et al. 2001 (reduced coefficients, mm^-1)"},
           rgbParameter("sigma_s", ValueRange::atLeast(0.0),
                        "scattering coefficient per channel, mm^-1, with \"sigma_a\""),
           rgbParameter("sigma_a", ValueRange::atLeast(0.0),
                        "absorption coefficient per channel, mm^-1, with \"sigma_s\""),
           rgbParameter("reflectance", ValueRange::closed(0.0, 1.0),
                        "diffuse colour: the profile's total diffuse reflectance per channel, with \"mfp\""),
           rgbParameter("mfp", ValueRange::above(0.0),
                        "mean free path 1 / sigma_t per channel, mm, with \"reflectance\""),
           {.name = "eta",
            .kind = ParameterKind::Number,
            .range = EtaRange,
            .description =
                "index of refraction inside relative to outside; default: the medium's (1.3, Marble 1.5), "
                "else 1.3; a rough boundary needs it " +
                RoughDielectricIndexRange.describe()},
           {.name = "g",
            .kind = ParameterKind::Number,
            .range = ValueRange{-1.0, 1.0, true, true},
            .defaultValue = 0.0,
            .description = "Henyey-Greenstein mean cosine (a medium's table sigma_s' is kept: sigma_s = "
                           "sigma_s' / (1 - g))"},
           {.name = "scale",
            .kind = ParameterKind::Number,
            .range = ValueRange::above(0.0),
            .defaultValue = 1.0,
            .description = "multiplies every coefficient (divides every length): 10 for a scene in cm"},
           {.name = "burley_fit",
            .kind = ParameterKind::Choice,
            .choices = choiceNames(BurleyFits),
            .description =
                "burley only (default \"searchlight\"): the shape factor s(A) fitted to a searchlight "
                "(d = mfp / s), diffuse transmission (d = mfp / s), or a searchlight with the diffuse mean "
                "free path (d = dmfp / s)"},
           {.name = "boundary",
            .kind = ParameterKind::Choice,
            .choices = choiceNames(Boundaries),
            .defaultValue = "smooth",
            .description =
                "the interface of the medium (for rendering): smooth or rough dielectric of index eta"},
           {.name = "roughness",
            .kind = ParameterKind::Number,
            .range = RoughnessRange,
            .description = "GGX alpha of a rough boundary (default 0.1)"}},
      .alternatives = {{"medium"}, {"sigma_s", "sigma_a"}, {"reflectance", "mfp"}},
      .build = nullptr,
      .completeDependent = completeDependent,
  };
}

bool isSubsurfaceMaterial(const json& material) {
  if (!material.is_object()) return false;
  const auto type = material.find("type");
  if (type == material.end() || !type->is_string()) return false;
  const MaterialModel* model = findMaterialModel(type->get<std::string>());
  return model && model->kind == MaterialKind::Subsurface;
}

SubsurfaceMaterial makeSubsurface(const json& material) { return makeSubsurface(validateMaterial(material)); }

SubsurfaceMaterial makeSubsurface(const ValidatedMaterial& validated) {
  if (validated.model->kind != MaterialKind::Subsurface)
    throwMaterialKeyError("type", validated.model->type, "is a BSDF model, not a subsurface material",
                          "\"subsurface\"");
  return buildSubsurface(validated.parameters, validated.completed);
}

std::unique_ptr<BsdfModel> makeFarFieldBsdf(const json& material) {
  if (!isSubsurfaceMaterial(material)) return makeBsdf(material);
  return std::make_unique<SubsurfaceFarFieldBrdf>(makeSubsurface(material).bssrdf());
}

}  // namespace scatterlab
