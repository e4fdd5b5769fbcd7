// A BSDF made of a user's own functions: the small adapter that lets the test kit
// (validation/check_bsdf.h) check a model living in another renderer without writing a
// BsdfModel subclass (docs/own-bsdf.md).
//
//     auto model = scatterlab::FunctionBsdf(
//         [&](const Vec3d& wi, const Vec3d& wo) { return myEval(wi, wo); },     // Rgb or double
//         [&](const Vec3d& wi, const Vec3d& wo) { return myPdf(wi, wo); },      // double
//         [&](const Vec3d& wi, const Vec2d& u) { return mySample(wi, u); });    // optional<Vec3d>
//     EXPECT_TRUE(scatterlab::passesBsdfCheck(model));
//
// The functions must follow scatterlab's conventions (materials/bsdf/bsdf.h); convert yours:
//  - Local shading frame: z is the shading normal, x the tangent. Both directions are unit
//    vectors pointing AWAY from the surface: wi is the given one (toward the viewer), wo the
//    sampled one (toward the light). A renderer whose incoming direction points toward the
//    surface negates it; one that samples "wi" swaps the two.
//  - eval(wi, wo): the BSDF value f in 1/sr per linear-RGB channel (or one number for all
//    three), WITHOUT the cosine factor. An eval that includes |cos wo| (Mitsuba 3's does): set
//    evalIncludesCosine and the adapter divides it out.
//  - pdf(wi, wo): the density of sample() per unit SOLID ANGLE of wo (a density per projected
//    solid angle is multiplied by |cos wo| first), 0 where sample() never goes; exact, since the
//    kit integrates it and compares it with sample()'s histogram.
//  - sample: (wi, u) or (wi, uLobe, u) with uLobe in [0, 1) (to choose a lobe) and u in
//    [0, 1)^2, returning either std::optional<Vec3d> (the direction; the adapter computes
//    pdf(wi, wo) and weight = eval |cos wo| / pdf), or std::optional<BsdfSample> with your own
//    weight = f |cos wo| / pdf and pdf, which the kit then checks against eval and pdf. No value
//    (std::nullopt) when sampling fails, e.g. below the horizon; never NaN.
//  - No delta (mirror) lobes through this adapter: they need BsdfSample's discrete
//    probabilities and LobeFlags::Specular, so write a BsdfModel for them.
#pragma once

#include <cmath>
#include <optional>
#include <type_traits>
#include <utility>

#include "materials/bsdf/bsdf.h"

namespace scatterlab {

struct FunctionBsdfOptions {
  // What the model scatters into (the kit checks transmission from both sides when it has
  // LobeFlags::Transmission).
  LobeFlags flags = LobeFlags::GlossyReflection | LobeFlags::DiffuseReflection;
  bool evalIncludesCosine = false;  // eval returns f |cos wo|; the adapter divides by |cos wo|
  bool reciprocal = true;           // false: the reciprocity rows are listed, not tested
  bool lossless = false;            // true: the kit checks the white furnace (albedo = 1)
  double losslessAccuracy = 0.0;    // how far from 1 the albedo may be by construction (bsdf.h)
};

template <typename Eval, typename Pdf, typename Sample> class FunctionBsdf final : public BsdfModel {
 public:
  FunctionBsdf(Eval eval, Pdf pdf, Sample sample, FunctionBsdfOptions options = {})
      : eval_(std::move(eval)), pdf_(std::move(pdf)), sample_(std::move(sample)), options_(options) {}

  Rgb eval(const Vec3d& wi, const Vec3d& wo, TransportMode = TransportMode::Radiance) const override {
    const Rgb f = Rgb(eval_(wi, wo));
    if (!options_.evalIncludesCosine) return f;
    const double cosine = std::abs(wo.z);
    return cosine > 0 ? f / cosine : Rgb(0.0);
  }

  double pdf(const Vec3d& wi, const Vec3d& wo, TransportMode = TransportMode::Radiance) const override {
    return double(pdf_(wi, wo));
  }

  std::optional<BsdfSample> sample(const Vec3d& wi, double uLobe, const Vec2d& u,
                                   TransportMode mode = TransportMode::Radiance) const override {
    auto drawn = [&] {
      if constexpr (std::is_invocable_v<const Sample&, const Vec3d&, double, const Vec2d&>)
        return sample_(wi, uLobe, u);
      else
        return sample_(wi, u);
    }();
    using Drawn = std::decay_t<decltype(drawn)>;
    if constexpr (std::is_same_v<Drawn, std::optional<BsdfSample>>) {
      return drawn;
    } else {
      static_assert(std::is_same_v<Drawn, std::optional<Vec3d>>,
                    "sample must return std::optional<Vec3d> or std::optional<BsdfSample>");
      if (!drawn) return std::nullopt;
      const double density = pdf(wi, *drawn, mode);
      if (!(density > 0)) return std::nullopt;
      const LobeFlags lobe = drawn->z * wi.z > 0 ? LobeFlags::Reflection : LobeFlags::Transmission;
      return BsdfSample{*drawn, eval(wi, *drawn, mode) * (std::abs(drawn->z) / density), density,
                        options_.flags & (lobe | LobeFlags::Diffuse | LobeFlags::Glossy), 1.0};
    }
  }

  LobeFlags flags() const override { return options_.flags; }
  bool isLossless() const override { return options_.lossless; }
  double losslessAccuracy() const override { return options_.losslessAccuracy; }
  bool isReciprocal() const override { return options_.reciprocal; }

 private:
  Eval eval_;
  Pdf pdf_;
  Sample sample_;
  FunctionBsdfOptions options_;
};

}  // namespace scatterlab
