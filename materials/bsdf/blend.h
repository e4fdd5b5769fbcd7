// Blend of two materials, per linear-RGB channel c:
//   f = w_c fA + (1 - w_c) fB,   pdf = wbar pA + (1 - wbar) pB,   wbar = (w_r + w_g + w_b) / 3
// (pbrt-v3's MixMaterial and Mitsuba's blendbsdf with a scalar weight; the per-channel weight
// only colours the value, so the pdf stays a two-component mixture with one sampling weight).
// sample() chooses A with probability wbar by uLobe and hands the chosen model uLobe remapped
// to a fresh uniform number, then reports the MIXTURE's value and density at the sampled wo
// (the other component is evaluated there too), so that sample(), eval() and pdf() agree.
//
// Delta lobes. A delta sample of A is a direction with discrete probability P_A under A's
// sampler, so the mixture produces it with probability wbar P_A; its coefficient in the mixture
// is w c_A, so the weight is (w / wbar) times A's weight. B's continuous density at that
// direction does not add to a discrete probability (it gives the single direction measure
// zero), and B's value there is not part of the delta contribution. Two components with delta
// lobes are rejected: their discrete directions can coincide (a mirror and a smooth dielectric
// both reflect specularly), and the mixture's probability of such a direction would need both
// components' probabilities, which the BsdfModel interface does not give for a given direction.
//
// The mixture is lossless when both components are (every channel's albedo is a convex
// combination of 1 and 1) at every incident direction: reflection-only models are one-sided
// (bsdf.h) and transmissive ones two-sided, so a reflection model blended with a transmissive
// one reflects only the transmissive part of light arriving from below, and is not lossless.
// It is reciprocal when both components are. Below the surface there is one medium:
// blending two transmissive models of different interior indices is rejected, and a blend with
// one transmissive component has that component's interior index.
#pragma once

#include <memory>

#include "materials/bsdf/bsdf.h"

namespace scatterlab {

class BlendBsdf final : public BsdfModel {
 public:
  // `weight` per channel in [0, 1]: how much of the first model. Throws std::invalid_argument
  // for a weight outside [0, 1], a missing model, two models with delta lobes, or two
  // transmissive models with different interior indices (the message says which).
  BlendBsdf(std::unique_ptr<BsdfModel> first, std::unique_ptr<BsdfModel> second, const Rgb& weight);

  Rgb eval(const Vec3d& wi, const Vec3d& wo, TransportMode mode = TransportMode::Radiance) const override;
  double pdf(const Vec3d& wi, const Vec3d& wo, TransportMode mode = TransportMode::Radiance) const override;
  std::optional<BsdfSample> sample(const Vec3d& wi, double uLobe, const Vec2d& u,
                                   TransportMode mode = TransportMode::Radiance) const override;

  LobeFlags flags() const override { return first_->flags() | second_->flags(); }
  bool isLossless() const override;
  // A convex combination is no further from 1 than its worse component.
  double losslessAccuracy() const override;
  bool isReciprocal() const override { return first_->isReciprocal() && second_->isReciprocal(); }
  double interiorIndex() const override { return interiorIndex_; }

  const BsdfModel& first() const { return *first_; }
  const BsdfModel& second() const { return *second_; }
  const Rgb& weight() const { return weight_; }
  // wbar: the probability that sample() uses the first model.
  double firstProbability() const { return firstProbability_; }

 private:
  std::unique_ptr<BsdfModel> first_, second_;
  Rgb weight_;
  double firstProbability_;
  double interiorIndex_ = 1.0;
};

struct MaterialModel;

// The material registry's "blend" model (materials/registry/model_list.h).
MaterialModel blendModel();

}  // namespace scatterlab
