// The Disney "principled" BRDF: Burley 2012, "Physically-Based Shading at Disney" (SIGGRAPH
// course notes), section 5 and its reference implementation disney.brdf in Disney's BRDF
// Explorer (github.com/wdas/brdf, the version with anisotropic Smith G). One RGB base colour
// and ten scalars in [0, 1], with Cdlum = 0.3 r + 0.6 g + 0.1 b (the reference's luminance),
// Ctint = baseColor / Cdlum, FX = (1 - x)^5 (Schlick's weight) and theta_d the angle between
// wi (or wo) and h:
//   diffuse   (1/pi) mix(Fd, ss, subsurface) baseColor (1 - metallic)                 (5.3)
//             Fd  = mix(1, Fd90, FL) mix(1, Fd90, FV),   Fd90 = 0.5 + 2 roughness cos^2 theta_d
//             ss  = 1.25 (Fss (1 / (cos_i + cos_o) - 0.5) + 0.5),
//             Fss = mix(1, Fss90, FL) mix(1, Fss90, FV), Fss90 = roughness cos^2 theta_d
//             (Hanrahan-Krueger inspired; 1.25 roughly preserves the albedo)
//   sheen     FH sheen mix(1, Ctint, sheenTint) (1 - metallic)         (no 1/pi, as the reference)
//   specular  D_GTR2(h) F_s G_s / (4 cos_i cos_o), F_s = mix(Cspec0, 1, FH),
//             Cspec0 = mix(0.08 specular mix(1, Ctint, specularTint), baseColor, metallic),
//             GTR2 = anisotropic GGX with aspect = sqrt(1 - 0.9 anisotropic),
//             alpha_x = max(0.001, roughness^2 / aspect), alpha_y = max(0.001, roughness^2 aspect)
//   clearcoat 0.25 clearcoat D_GTR1(h) F_c G_c / (4 cos_i cos_o), GTR1 alpha = mix(0.1, 0.001,
//             clearcoatGloss), F_c = mix(0.04, 1, FH) (IOR 1.5), G_c = GGX Smith with alpha 0.25.
// The 0.001 floor of alpha_x, alpha_y is the reference's (each clamped after the aspect).
//
// Masking-shadowing: like disney.brdf, G = G1(wi) G1(wo), the SEPARABLE Smith form, for the
// specular lobe (anisotropic GGX G1 with the lobe's alpha_x, alpha_y) and the clearcoat (GGX G1
// with alpha 0.25), not the height-correlated G2 that conductor.h uses: so that values equal
// the BRDF Explorer's, which fitted Disney parameters refer to. (G1 G1 <= G2, so this reflects
// slightly less than the height-correlated form.)
//
// Colour: scatterlab colours are linear RGB. disney.brdf linearises its baseColor slider with
// x^2.2 (mon2lin); here baseColor IS the linear colour (Cdlin), and the default is the
// Explorer's default (0.82, 0.67, 0.16) linearised.
//
// Not energy-conserving: the retro-reflection term Fd90 > 1 lets a white, rough base reflect
// more than it receives at grazing incidence, the sheen is not normalised and the clearcoat is
// added on top without taking energy from the layers below (tests/materials/bsdf/disney_test.cpp
// measures by how much). Reciprocal: every factor is symmetric in wi and wo.
//
// Sampling: a mixture of a cosine-weighted hemisphere (diffuse, subsurface, sheen), GGX visible
// normals (Heitz 2018) for the specular lobe and GTR1 normals (Burley 2012 appendix B) for the
// clearcoat, with lobe probabilities that depend only on the parameters and wi, so that pdf() is
// the exact mixture density.
#pragma once

#include <array>

#include "materials/bsdf/bsdf.h"
#include "materials/bsdf/fresnel.h"
#include "materials/bsdf/gtr1.h"
#include "materials/bsdf/half_vector.h"
#include "materials/bsdf/microfacet.h"
#include "materials/core/warp.h"

namespace scatterlab {

// The smallest alpha_x, alpha_y of the specular lobe (disney.brdf's floor): roughness 0 is a
// very sharp GGX lobe, not a delta.
inline constexpr double DisneyMinAlpha = 0.001;

// The parameters, each in [0, 1]; defaults are disney.brdf's (baseColor linearised, see above).
template <typename T> struct DisneyParametersT {
  // (0.82, 0.67, 0.16)^2.2
  RgbT<T> baseColor = RgbT<T>(T(0.6462349993978065), T(0.4143473503120746), T(0.017744507984771743));
  T metallic = T(0);
  T subsurface = T(0);
  T specular = T(0.5);
  T specularTint = T(0);
  T roughness = T(0.5);
  T anisotropic = T(0);
  T sheen = T(0);
  T sheenTint = T(0.5);
  T clearcoat = T(0);
  T clearcoatGloss = T(1);
};
using DisneyParameters = DisneyParametersT<double>;

// disney.brdf's luminance approximation.
template <typename T> T disneyLuminance(const RgbT<T>& c) {
  return T(0.3) * c.x + T(0.6) * c.y + T(0.1) * c.z;
}

// What the parameters determine, independent of the directions.
template <typename T> struct DisneyTerms {
  RgbT<T> base;        // Cdlin
  RgbT<T> specularF0;  // Cspec0
  RgbT<T> sheenColor;  // sheen mix(1, Ctint, sheenTint)
  T dielectric;        // 1 - metallic: the weight of diffuse, subsurface and sheen
  T roughness, subsurface;
  T clearcoatWeight;  // 0.25 clearcoat
  GgxDistribution<T> specular;
  Gtr1Distribution<T> clearcoat;
  GgxDistribution<T> clearcoatMasking;  // GGX alpha 0.25: only its Smith G1 is used
};

// alpha_x, alpha_y of the specular lobe.
template <typename T> std::array<T, 2> disneySpecularAlpha(const T& roughness, const T& anisotropic) {
  using std::sqrt;
  const T aspect = sqrt(T(1) - T(0.9) * anisotropic);  // >= sqrt(0.1)
  const T alpha = roughness * roughness;
  const T alphaX = alpha / aspect, alphaY = alpha * aspect;
  const T minimum(DisneyMinAlpha);
  return {alphaX > minimum ? alphaX : minimum, alphaY > minimum ? alphaY : minimum};
}

template <typename T> DisneyTerms<T> disneyTerms(const DisneyParametersT<T>& p) {
  const T luminance = disneyLuminance(p.baseColor);
  // Hue and saturation only; a black base has no hue to tint with.
  const RgbT<T> tint = luminance > T(0) ? p.baseColor / luminance : RgbT<T>(T(1));
  const RgbT<T> one(T(1));
  const RgbT<T> dielectricF0 = T(0.08) * p.specular * (one + p.specularTint * (tint - one));
  const auto [alphaX, alphaY] = disneySpecularAlpha(p.roughness, p.anisotropic);
  const T clearcoatAlpha = T(0.1) + p.clearcoatGloss * T(0.001 - 0.1);
  return DisneyTerms<T>{p.baseColor,
                        dielectricF0 + p.metallic * (p.baseColor - dielectricF0),
                        p.sheen * (one + p.sheenTint * (tint - one)),
                        T(1) - p.metallic,
                        p.roughness,
                        p.subsurface,
                        T(0.25) * p.clearcoat,
                        GgxDistribution<T>(alphaX, alphaY),
                        Gtr1Distribution<T>(clearcoatAlpha),
                        GgxDistribution<T>(T(0.25), T(0.25))};
}

// The BRDF lobe by lobe (without the cosine of wo, bsdf.h conventions); their sum is f.
template <typename T> struct DisneyLobes {
  RgbT<T> diffuse;  // mix(Fd, ss, subsurface) base (1 - metallic) / pi
  RgbT<T> sheen;
  RgbT<T> specular;
  RgbT<T> clearcoat;

  RgbT<T> sum() const { return diffuse + sheen + specular + clearcoat; }
};

// The kernel shared by rendering (T = double) and fitting (T = ceres::Jet). One-sided: 0
// unless both directions are above the surface (so cos_i + cos_o > 0 and h is defined).
template <typename T>
DisneyLobes<T> disneyEvalLobes(const DisneyTerms<T>& terms, const Vec3<T>& wi, const Vec3<T>& wo) {
  if (!(wi.z > T(0)) || !(wo.z > T(0)))
    return DisneyLobes<T>{RgbT<T>(T(0)), RgbT<T>(T(0)), RgbT<T>(T(0)), RgbT<T>(T(0))};
  const Vec3<T> h = reflectionHalfVector(wi, wo);
  const T cosD = glm::dot(wi, h);
  const T weightI = fresnelSchlick(T(0), wi.z), weightO = fresnelSchlick(T(0), wo.z);
  const T weightH = fresnelSchlick(T(0), cosD);
  const auto towardGrazing = [&](const T& at90) {  // mix(1, at90, FL) mix(1, at90, FV)
    return (T(1) + (at90 - T(1)) * weightI) * (T(1) + (at90 - T(1)) * weightO);
  };
  const T cos2D = cosD * cosD;
  const T retroReflection = towardGrazing(T(0.5) + T(2) * terms.roughness * cos2D);
  const T flattened = towardGrazing(terms.roughness * cos2D);
  const T subsurface = T(1.25) * (flattened * (T(1) / (wi.z + wo.z) - T(0.5)) + T(0.5));
  const T diffuse = retroReflection + terms.subsurface * (subsurface - retroReflection);

  const T inverseCosines = T(1) / (T(4) * wi.z * wo.z);
  const T specularShape =
      terms.specular.D(h) * terms.specular.G1(wi) * terms.specular.G1(wo) * inverseCosines;
  const T clearcoatShape =
      terms.clearcoat.D(h) * terms.clearcoatMasking.G1(wi) * terms.clearcoatMasking.G1(wo) * inverseCosines;
  return DisneyLobes<T>{terms.base * (diffuse * terms.dielectric * T(InvPi)),
                        terms.sheenColor * (weightH * terms.dielectric),
                        fresnelSchlick(terms.specularF0, cosD) * specularShape,
                        RgbT<T>(terms.clearcoatWeight * fresnelSchlick(T(0.04), cosD) * clearcoatShape)};
}

template <typename T>
RgbT<T> disneyEval(const DisneyParametersT<T>& p, const Vec3<T>& wi, const Vec3<T>& wo) {
  return disneyEvalLobes(disneyTerms(p), wi, wo).sum();
}

class DisneyBsdf final : public BsdfModel {
 public:
  // Every parameter in [0, 1] (std::invalid_argument otherwise; the registry reports the range).
  explicit DisneyBsdf(const DisneyParameters& parameters);

  Rgb eval(const Vec3d& wi, const Vec3d& wo, TransportMode = TransportMode::Radiance) const override {
    return disneyEvalLobes(terms_, wi, wo).sum();
  }
  double pdf(const Vec3d& wi, const Vec3d& wo, TransportMode = TransportMode::Radiance) const override;
  std::optional<BsdfSample> sample(const Vec3d& wi, double uLobe, const Vec2d& u,
                                   TransportMode = TransportMode::Radiance) const override;
  LobeFlags flags() const override {
    return hasDiffuse_ ? LobeFlags::DiffuseReflection | LobeFlags::GlossyReflection
                       : LobeFlags::GlossyReflection;
  }
  bool isLossless() const override { return false; }

  // The probabilities of choosing the cosine (diffuse, subsurface, sheen), GGX (specular) and
  // GTR1 (clearcoat) sampler at wi; they sum to 1.
  struct LobeProbabilities {
    double diffuse = 0, specular = 1, clearcoat = 0;
  };
  LobeProbabilities lobeProbabilities(const Vec3d& wi) const;

  const DisneyParameters& parameters() const { return parameters_; }
  const DisneyTerms<double>& terms() const { return terms_; }

 private:
  DisneyParameters parameters_;
  DisneyTerms<double> terms_;
  bool hasDiffuse_, hasClearcoat_;
};

struct MaterialModel;

// The material registry's "disney" model (materials/registry/model_list.h).
MaterialModel disneyModel();

}  // namespace scatterlab
