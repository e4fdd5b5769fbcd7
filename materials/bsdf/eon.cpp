#include "materials/bsdf/eon.h"

#include <memory>

#include "materials/core/lobe_choice.h"
#include "materials/registry/material_model.h"

namespace scatterlab {

// The paper's fits of the LTC matrix entries to the EON lobe (section 5.2), in the frame whose
// x axis is wi's azimuth.
EonCltc::EonCltc(const Vec3d& wi, double r) {
  const double mu = std::clamp(wi.z, 0.0, 1.0);
  a_ = 1.0 + r * (0.303392 + (-0.518982 + 0.111709 * mu) * mu + (-0.276266 + 0.335918 * mu) * r);
  b_ = r * (-1.16407 + 1.15859 * mu + (0.150815 - 0.150105 * mu) * r) / (mu * mu * mu - 1.43545);
  c_ = 1.0 + (0.20013 + (-0.506373 + 0.261777 * mu) * mu) * r;
  d_ = ((0.540852 + (-1.01625 + 0.475392 * mu) * mu) * r) / (-1.0743 + mu * (0.0725628 + mu));
  s_ = 0.5 * (1.0 + 1.0 / std::sqrt(d_ * d_ + 1.0));
  const double length = std::sqrt(wi.x * wi.x + wi.y * wi.y);
  if (length > 0) {
    x_ = Vec3d(wi.x / length, wi.y / length, 0.0);
    y_ = Vec3d(-x_.y, x_.x, 0.0);
  }
}

std::optional<Vec3d> EonCltc::sample(const Vec2d& u) const {
  // Uniform on the disk, then the part of it whose hemisphere point h has (M h).z = d h.x +
  // h.z > 0: for d <= 0 that is x <= v sqrt(1 - y^2), v = 1/sqrt(1 + d^2), reached by the
  // affine map below (Jacobian s, so still uniform); for d > 0 its mirror image.
  const double radius = std::sqrt(u.x), phi = 2.0 * Pi * u.y;
  const double y = radius * std::sin(phi);
  const double chord = safeSqrt(1.0 - y * y);
  double x = -((1.0 - s_) * chord + s_ * radius * std::cos(phi));
  if (d_ > 0) x = -x;
  const Vec3d h(x, y, safeSqrt(1.0 - x * x - y * y));
  const Vec3d m(a_ * h.x + b_ * h.z, c_ * h.y, d_ * h.x + h.z);
  if (!(m.z > 0)) return std::nullopt;  // on the clipping boundary (round-off)
  const Vec3d w = glm::normalize(m);
  return w.x * x_ + w.y * y_ + Vec3d(0.0, 0.0, w.z);
}

double EonCltc::pdf(const Vec3d& wo) const {
  if (!(wo.z > 0)) return 0.0;
  const Vec3d w(glm::dot(wo, x_), glm::dot(wo, y_), wo.z);
  // adj(M) w = det(M) M^-1 w; h = that, normalised, has density h.z / (pi s), and the
  // Jacobian of w = M h / |M h| gives |M h|^3 / det M with |M h| = det M / |adj(M) w|.
  const Vec3d adjW(c_ * (w.x - b_ * w.z), (a_ - b_ * d_) * w.y, -c_ * (d_ * w.x - a_ * w.z));
  if (!(adjW.z > 0)) return 0.0;
  const double determinant = c_ * (a_ - b_ * d_);
  const double lengthSquared = glm::dot(adjW, adjW);
  return sqr(determinant / lengthSquared) * adjW.z / (Pi * s_);
}

double EonBsdf::uniformProbability(double mu, double r) {
  if (!(r > 0)) return 0.0;
  mu = std::clamp(mu, 0.0, 1.0);
  return std::clamp(std::pow(r, 0.1) * (0.162925 + mu * (-0.372058 + (0.538233 - 0.290822 * mu) * mu)), 0.0,
                    1.0);
}

double EonBsdf::pdf(const Vec3d& wi, const Vec3d& wo, TransportMode) const {
  if (!(wi.z > 0) || !(wo.z > 0)) return 0.0;
  const double pUniform = uniformProbability(wi.z, r_);
  return pUniform * uniformHemispherePdf() + (1.0 - pUniform) * EonCltc(wi, r_).pdf(wo);
}

std::optional<BsdfSample> EonBsdf::sample(const Vec3d& wi, double uLobe, const Vec2d& u,
                                          TransportMode) const {
  if (!(wi.z > 0)) return std::nullopt;
  const double pUniform = uniformProbability(wi.z, r_);
  const EonCltc cltc(wi, r_);
  const std::optional<Vec3d> wo = chooseLobe(uLobe, pUniform).lobe == 0
                                      ? std::optional<Vec3d>(sampleUniformHemisphere(u))
                                      : cltc.sample(u);
  if (!wo || !(wo->z > 0)) return std::nullopt;
  // The mixture's density, computed as pdf() computes it.
  const double density = pUniform * uniformHemispherePdf() + (1.0 - pUniform) * cltc.pdf(*wo);
  if (!(density > 0)) return std::nullopt;
  return BsdfSample{*wo, eval(wi, *wo) * (wo->z / density), density, LobeFlags::DiffuseReflection, 1.0};
}

// ---------------------------------------------------------------------------------------
// The material registry's "eon" model (materials/registry/model_list.h): the
// parameter spec and the function that builds it.

namespace {

constexpr std::array<NamedChoice<EonAlbedo>, 2> EonAlbedos{{
    {"fitted", EonAlbedo::Fitted},
    {"analytic", EonAlbedo::Analytic},
}};

std::unique_ptr<BsdfModel> buildEon(const MaterialParameters& p) {
  return std::make_unique<EonBsdf>(p.rgb("albedo"), p.number("roughness"),
                                   choiceValue(EonAlbedos, p.choice("directional_albedo")));
}

}  // namespace

MaterialModel eonModel() {
  return {
      .type = "eon",
      .description =
          "Energy-preserving rough diffuse (EON): Fujii's Oren-Nayar plus a multiple-scattering lobe, "
          "clipped-LTC sampling",
      .citation =
          "Portsmouth, Kutz & Hill 2025, EON: A Practical Energy-Preserving Rough Diffuse BRDF, JCGT 14(1) "
          "(eq. 3-10, section 5); Fujii 2013, A tiny improvement of Oren-Nayar reflectance model",
      .parameters = {rgbParameter("albedo", 0.8, "single-scattering albedo rho per linear-RGB channel"),
                     numberParameter("roughness", ValueRange::closed(0.0, 1.0), 0.5,
                                     "EON roughness r (0: Lambert); not Oren-Nayar's sigma in radians"),
                     {.name = "directional_albedo",
                      .kind = ParameterKind::Choice,
                      .choices = choiceNames(EonAlbedos),
                      .defaultValue = "fitted",
                      .description =
                          "FON albedo in the multiple-scattering lobe: the paper's fit (\"fitted\", "
                          "white albedo 1 within 5.4e-4) or the analytic form (\"analytic\", exactly 1)"}},
      .alternatives = {},
      .build = buildEon,
      .lobeWidthParameter = "roughness",
      .losslessExamples =
          {{{"type", "eon"}, {"albedo", 1.0}, {"roughness", 0.7}, {"directional_albedo", "analytic"}}},
  };
}

}  // namespace scatterlab
