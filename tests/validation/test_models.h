// Small models that exist only to exercise the kit: each is either correct in a way the
// production models do not cover (a delta lobe) or wrong in exactly one way.
#pragma once

#include <limits>

#include "materials/bsdf/lambertian.h"

namespace scatterlab::test_models {

// With probability `mirrorProbability` a perfect mirror (a delta lobe), otherwise a
// Lambertian lobe: a correct mixture, the shape of a smooth plastic.
class MirrorPlusDiffuse final : public BsdfModel {
 public:
  MirrorPlusDiffuse(double mirrorProbability, double claimedProbability)
      : p_(mirrorProbability), claimed_(claimedProbability), diffuse_(Rgb(1.0)) {}
  explicit MirrorPlusDiffuse(double mirrorProbability)
      : MirrorPlusDiffuse(mirrorProbability, mirrorProbability) {}

  Rgb eval(const Vec3d& wi, const Vec3d& wo, TransportMode) const override {
    return (1 - p_) * diffuse_.eval(wi, wo);
  }
  double pdf(const Vec3d& wi, const Vec3d& wo, TransportMode) const override {
    return (1 - p_) * diffuse_.pdf(wi, wo);
  }
  std::optional<BsdfSample> sample(const Vec3d& wi, double uLobe, const Vec2d& u,
                                   TransportMode) const override {
    if (wi.z <= 0) return std::nullopt;
    if (uLobe < p_)
      return BsdfSample{Vec3d(-wi.x, -wi.y, wi.z), Rgb(1.0), claimed_, LobeFlags::SpecularReflection};
    auto s = diffuse_.sample(wi, uLobe, u);
    if (!s) return s;
    s->pdf *= 1 - p_;
    s->weight = eval(wi, s->wo, TransportMode::Radiance) * s->wo.z / s->pdf;
    return s;
  }
  LobeFlags flags() const override { return LobeFlags::SpecularReflection | LobeFlags::DiffuseReflection; }
  bool isLossless() const override { return true; }

 private:
  double p_, claimed_;
  LambertianBsdf diffuse_;
};

// A Lambertian whose sample() weight is off by `factor`: distribution and pdf are right, so
// only the consistency check can see it.
class WrongWeightLambertian final : public BsdfModel {
 public:
  explicit WrongWeightLambertian(double factor) : factor_(factor), base_(Rgb(0.5)) {}
  Rgb eval(const Vec3d& wi, const Vec3d& wo, TransportMode) const override { return base_.eval(wi, wo); }
  double pdf(const Vec3d& wi, const Vec3d& wo, TransportMode) const override { return base_.pdf(wi, wo); }
  std::optional<BsdfSample> sample(const Vec3d& wi, double uLobe, const Vec2d& u,
                                   TransportMode) const override {
    auto s = base_.sample(wi, uLobe, u);
    if (s) s->weight *= factor_;
    return s;
  }
  LobeFlags flags() const override { return base_.flags(); }

 private:
  double factor_;
  LambertianBsdf base_;
};

// A Lambertian (albedo 0.5) whose sampled weight is `faultyWeight` for samples with
// uLobe < fraction: NaN by default, or a negative value. eval and pdf stay the Lambertian's, so
// a renderer's connections and next-event estimation stay sound and only sampling meets the fault.
class FaultyWeightLambertian final : public BsdfModel {
 public:
  explicit FaultyWeightLambertian(double fraction,
                                  const Rgb& faultyWeight = Rgb(std::numeric_limits<double>::quiet_NaN()))
      : fraction_(fraction), faultyWeight_(faultyWeight) {}
  Rgb eval(const Vec3d& wi, const Vec3d& wo, TransportMode) const override { return base_.eval(wi, wo); }
  double pdf(const Vec3d& wi, const Vec3d& wo, TransportMode) const override { return base_.pdf(wi, wo); }
  std::optional<BsdfSample> sample(const Vec3d& wi, double uLobe, const Vec2d& u,
                                   TransportMode) const override {
    auto s = base_.sample(wi, uLobe, u);
    if (s && uLobe < fraction_) s->weight = faultyWeight_;
    return s;
  }
  LobeFlags flags() const override { return base_.flags(); }

 private:
  double fraction_;
  Rgb faultyWeight_;
  LambertianBsdf base_{Rgb(0.5)};
};

// A Lambertian whose density is `scale` times too large everywhere: sample() and pdf() agree
// with each other, and the weight is eval |cos| / pdf of both, so only the normalisation of
// the pdf (and what the albedo makes of it) is wrong.
class ScaledPdfLambertian final : public BsdfModel {
 public:
  explicit ScaledPdfLambertian(double scale) : scale_(scale) {}
  Rgb eval(const Vec3d& wi, const Vec3d& wo, TransportMode) const override { return base_.eval(wi, wo); }
  double pdf(const Vec3d& wi, const Vec3d& wo, TransportMode) const override {
    return scale_ * base_.pdf(wi, wo);
  }
  std::optional<BsdfSample> sample(const Vec3d& wi, double uLobe, const Vec2d& u,
                                   TransportMode) const override {
    auto s = base_.sample(wi, uLobe, u);
    if (!s) return s;
    s->pdf *= scale_;
    s->weight /= scale_;
    return s;
  }
  LobeFlags flags() const override { return base_.flags(); }

 private:
  double scale_;
  LambertianBsdf base_{Rgb(0.5)};
};

// Reflects on the whole upper hemisphere but samples only phi in (0, pi) with a doubled
// cosine density: self-consistent where it samples, blind to half of its own reflectance.
class HalfSupportSampler final : public BsdfModel {
 public:
  Rgb eval(const Vec3d& wi, const Vec3d& wo, TransportMode) const override { return base_.eval(wi, wo); }
  double pdf(const Vec3d& wi, const Vec3d& wo, TransportMode) const override {
    return wo.y > 0 ? 2.0 * base_.pdf(wi, wo) : 0.0;
  }
  std::optional<BsdfSample> sample(const Vec3d& wi, double uLobe, const Vec2d& u,
                                   TransportMode) const override {
    auto s = base_.sample(wi, uLobe, u);
    if (!s || s->wo.y == 0) return std::nullopt;
    s->wo.y = std::abs(s->wo.y);
    s->pdf = pdf(wi, s->wo, TransportMode::Radiance);
    s->weight = eval(wi, s->wo, TransportMode::Radiance) * s->wo.z / s->pdf;
    return s;
  }
  LobeFlags flags() const override { return base_.flags(); }

 private:
  LambertianBsdf base_{Rgb(0.5)};
};

// f = albedo (1 + wi.x) / pi: energy-conserving for |wi.x| small, sampled exactly
// (cosine-weighted), but f(wi, wo) != f(wo, wi).
class NonReciprocalDiffuse final : public BsdfModel {
 public:
  Rgb eval(const Vec3d& wi, const Vec3d& wo, TransportMode) const override {
    return base_.eval(wi, wo) * (1.0 + 0.5 * wi.x);
  }
  double pdf(const Vec3d& wi, const Vec3d& wo, TransportMode) const override { return base_.pdf(wi, wo); }
  std::optional<BsdfSample> sample(const Vec3d& wi, double uLobe, const Vec2d& u,
                                   TransportMode) const override {
    auto s = base_.sample(wi, uLobe, u);
    if (s) s->weight *= 1.0 + 0.5 * wi.x;
    return s;
  }
  LobeFlags flags() const override { return base_.flags(); }

 private:
  LambertianBsdf base_{Rgb(0.5)};
};

}  // namespace scatterlab::test_models
