// The model of this example: a normalised Phong lobe about the mirror direction (Lafortune &
// Willems 1994, "Using the Modified Phong Reflectance Model for Physically Based Rendering",
// eq. 7, without its diffuse term):
//
//     f(wi, wo) = ks (n + 2) / (2 pi) max(0, cos alpha)^n,   cos alpha = wo . mirror(wi),
//
// sampled from the cosine-power lobe (n + 1) / (2 pi) cos^n alpha about mirror(wi); samples
// below the horizon are lost (sample() fails), so pdf() is that density for wo above it and 0
// below. Its albedo is at most ks (equal at normal incidence), so ks <= 1 conserves energy.
//
// Replace this file with your own model. It implements scatterlab's BsdfModel, whose
// conventions (materials/bsdf/bsdf.h, docs/own-bsdf.md) are: local frame with z the normal, wi and
// wo pointing away from the surface, eval = f without the cosine, pdf per solid angle of wo,
// sample weight = f |cos wo| / pdf.
#pragma once

#include <cmath>
#include <optional>

#include "materials/bsdf/bsdf.h"

namespace own_bsdf {

using scatterlab::Rgb;
using scatterlab::Vec2d;
using scatterlab::Vec3d;

inline constexpr double Pi = 3.14159265358979323846;

inline Vec3d mirror(const Vec3d& wi) { return {-wi.x, -wi.y, wi.z}; }

// f as a template of the parameters, so that eval (T = double) and the fitter's kernel
// (T = ceres::Jet, plugin.cpp) share one formula.
template <typename T> scatterlab::RgbT<T> examplePhongValue(const scatterlab::RgbT<T>& ks, const T& exponent,
                                                            const Vec3d& wi, const Vec3d& wo) {
  if (!(wi.z > 0) || !(wo.z > 0)) return scatterlab::RgbT<T>(T(0));
  const double cosAlpha = glm::dot(mirror(wi), wo);
  if (!(cosAlpha > 0)) return scatterlab::RgbT<T>(T(0));
  using std::pow;  // pow(double, ceres::Jet) is found by argument-dependent lookup
  return ks * ((exponent + T(2)) * T(0.5 / Pi) * pow(cosAlpha, exponent));
}

class ExamplePhong final : public scatterlab::BsdfModel {
 public:
  // pdfExponentScale != 1 makes a deliberately broken variant: pdf() then uses an exponent that
  // many times the sampler's, which the kit must reject (a negative control of your own).
  ExamplePhong(const Rgb& ks, double exponent, double pdfExponentScale = 1.0)
      : ks_(ks), exponent_(exponent), pdfExponent_(exponent * pdfExponentScale) {}

  Rgb eval(const Vec3d& wi, const Vec3d& wo,
           scatterlab::TransportMode = scatterlab::TransportMode::Radiance) const override {
    return examplePhongValue(ks_, exponent_, wi, wo);
  }

  double pdf(const Vec3d& wi, const Vec3d& wo,
             scatterlab::TransportMode = scatterlab::TransportMode::Radiance) const override {
    if (!(wi.z > 0) || !(wo.z > 0)) return 0.0;
    const double cosAlpha = glm::dot(mirror(wi), wo);
    return cosAlpha > 0 ? (pdfExponent_ + 1.0) * (0.5 / Pi) * std::pow(cosAlpha, pdfExponent_) : 0.0;
  }

  std::optional<scatterlab::BsdfSample> sample(
      const Vec3d& wi, double /*uLobe: one lobe*/, const Vec2d& u,
      scatterlab::TransportMode = scatterlab::TransportMode::Radiance) const override {
    if (!(wi.z > 0)) return std::nullopt;
    // cos alpha = u0^(1/(n+1)) inverts the cdf of (n + 1) cos^n alpha sin alpha on [0, pi/2].
    const double cosAlpha = std::pow(u.x, 1.0 / (exponent_ + 1.0));
    const double sinAlpha = std::sqrt(std::max(0.0, 1.0 - cosAlpha * cosAlpha));
    const double phi = 2.0 * Pi * u.y;
    const Vec3d local(sinAlpha * std::cos(phi), sinAlpha * std::sin(phi), cosAlpha);
    const Vec3d wo = scatterlab::Framed::fromNormal(mirror(wi)).toWorld(local);
    const double density = pdf(wi, wo);
    if (!(wo.z > 0) || !(density > 0)) return std::nullopt;
    return scatterlab::BsdfSample{wo, eval(wi, wo) * (wo.z / density), density,
                                  scatterlab::LobeFlags::GlossyReflection, 1.0};
  }

  scatterlab::LobeFlags flags() const override { return scatterlab::LobeFlags::GlossyReflection; }

 private:
  Rgb ks_;
  double exponent_;
  double pdfExponent_;
};

}  // namespace own_bsdf
