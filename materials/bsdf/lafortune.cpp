// The material registry's "lafortune" model (lafortune.h): its parameter spec and the function that builds
// it, listed in materials/registry/model_list.cpp.
#include "materials/bsdf/lafortune.h"

#include <memory>

#include "materials/registry/material_model.h"

namespace scatterlab {

namespace {

constexpr std::array<NamedChoice<LafortuneNormalization>, 2> LafortuneNormalizations{{
    {"ngan", LafortuneNormalization::Ngan},
    {"none", LafortuneNormalization::None},
}};

std::unique_ptr<BsdfModel> buildLafortune(const MaterialParameters& p) {
  const LafortuneLobe lobe{p.rgb("ks"), Vec3d(p.number("cx"), p.number("cy"), p.number("cz")),
                           p.number("exponent")};
  return std::make_unique<LafortuneBsdf>(p.rgb("kd"), std::vector<LafortuneLobe>{lobe},
                                         choiceValue(LafortuneNormalizations, p.choice("normalization")));
}

}  // namespace

MaterialModel lafortuneModel() {
  const ValueRange c = ValueRange::closed(-1.0, 1.0);
  return {
      .type = "lafortune",
      .description =
          "Lambertian plus one generalised cosine lobe rho max(0, C.(wi*wo))^n, optionally with Ngan's "
          "normalisation (n+2)/(2pi max(Cz^2, Cxy^2)^(n/2))",
      .citation =
          "Lafortune et al. 1997, Non-Linear Approximation of Reflectance Functions, eq. 4; Ngan et al. 2005",
      .parameters = {rgbParameter("kd", 0.5, "diffuse albedo per linear-RGB channel"),
                     rgbParameter("ks", 0.4, "lobe scale rho per linear-RGB channel"),
                     numberParameter("cx", c, -1.0, "lobe coefficient Cx"),
                     numberParameter("cy", c, -1.0, "lobe coefficient Cy"),
                     numberParameter("cz", c, 1.0, "lobe coefficient Cz"),
                     numberParameter("exponent", ValueRange::closed(0.0, 10000.0), 20.0, "lobe exponent n"),
                     {.name = "normalization",
                      .kind = ParameterKind::Choice,
                      .choices = choiceNames(LafortuneNormalizations),
                      .defaultValue = "ngan",
                      .description =
                          "\"ngan\": times (n+2)/(2pi max(Cz^2, Cxy^2)^(n/2)); \"none\": Lafortune's "
                          "raw lobe (albedo <= 1 is then the user's job)"}},
      .alternatives = {},
      .build = buildLafortune,
      .lobeWidthParameter = "exponent",
      .widerWhenLarger = false,
  };
}

}  // namespace scatterlab
