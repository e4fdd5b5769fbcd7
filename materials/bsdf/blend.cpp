#include "materials/bsdf/blend.h"

#include <algorithm>

#include <memory>
#include <stdexcept>
#include <string>

#include "materials/core/lobe_choice.h"
#include "materials/registry/material_model.h"
#include "materials/registry/spec_validation.h"

namespace scatterlab {

namespace {

bool isTransmissive(const BsdfModel& model) { return hasAny(model.flags(), LobeFlags::Transmission); }

}  // namespace

BlendBsdf::BlendBsdf(std::unique_ptr<BsdfModel> first, std::unique_ptr<BsdfModel> second, const Rgb& weight)
    : first_(std::move(first)),
      second_(std::move(second)),
      weight_(weight),
      firstProbability_((weight.x + weight.y + weight.z) / 3.0) {
  if (!first_ || !second_) throw std::invalid_argument("blend: both models are needed");
  for (int c = 0; c < 3; ++c)
    if (!(weight[c] >= 0.0 && weight[c] <= 1.0))
      throw std::invalid_argument("blend: the weight must be in [0, 1] in every channel, got " +
                                  std::to_string(weight[c]));
  if (hasAny(first_->flags(), LobeFlags::Specular) && hasAny(second_->flags(), LobeFlags::Specular))
    throw std::invalid_argument(
        "blend: both models have delta (specular) lobes; a direction both sample discretely would need the "
        "probabilities of both, so at most one of the two may have delta lobes");
  const bool firstTransmits = isTransmissive(*first_), secondTransmits = isTransmissive(*second_);
  if (firstTransmits && secondTransmits && first_->interiorIndex() != second_->interiorIndex())
    throw std::invalid_argument("blend: the two models transmit into different media (interior indices " +
                                std::to_string(first_->interiorIndex()) + " and " +
                                std::to_string(second_->interiorIndex()) +
                                "); there is one medium below a surface");
  interiorIndex_ =
      firstTransmits ? first_->interiorIndex() : (secondTransmits ? second_->interiorIndex() : 1.0);
}

bool BlendBsdf::isLossless() const {
  return first_->isLossless() && second_->isLossless() && isTransmissive(*first_) == isTransmissive(*second_);
}

double BlendBsdf::losslessAccuracy() const {
  return std::max(first_->losslessAccuracy(), second_->losslessAccuracy());
}

Rgb BlendBsdf::eval(const Vec3d& wi, const Vec3d& wo, TransportMode mode) const {
  Rgb f(0.0);
  // A component of weight 0 in every channel is not evaluated: its value could not show.
  if (weight_ != Rgb(0.0)) f += weight_ * first_->eval(wi, wo, mode);
  if (weight_ != Rgb(1.0)) f += (Rgb(1.0) - weight_) * second_->eval(wi, wo, mode);
  return f;
}

double BlendBsdf::pdf(const Vec3d& wi, const Vec3d& wo, TransportMode mode) const {
  double density = 0.0;
  if (firstProbability_ > 0.0) density += firstProbability_ * first_->pdf(wi, wo, mode);
  if (firstProbability_ < 1.0) density += (1.0 - firstProbability_) * second_->pdf(wi, wo, mode);
  return density;
}

std::optional<BsdfSample> BlendBsdf::sample(const Vec3d& wi, double uLobe, const Vec2d& u,
                                            TransportMode mode) const {
  const LobeChoice choice = chooseLobe(uLobe, firstProbability_);
  const bool chooseFirst = choice.lobe == 0;
  const double probability = chooseFirst ? firstProbability_ : 1.0 - firstProbability_;
  std::optional<BsdfSample> s = (chooseFirst ? first_ : second_)->sample(wi, choice.u, u, mode);
  if (!s) return s;
  if (s->isDelta()) {
    // Coefficient w c over discrete probability wbar P: the component's weight times w / wbar.
    s->weight *= (chooseFirst ? weight_ : Rgb(1.0) - weight_) / probability;
    s->pdf *= probability;
    return s;
  }
  // The mixture's density and value at wo, exactly as pdf() and eval() compute them.
  s->pdf = pdf(wi, s->wo, mode);
  if (!(s->pdf > 0.0)) return std::nullopt;
  s->weight = eval(wi, s->wo, mode) * (std::abs(s->wo.z) / s->pdf);
  return s;
}

// ---------------------------------------------------------------------------------------
// The material registry's "blend" model (materials/registry/model_list.h): the
// parameter spec and the function that builds it.

namespace {

using nlohmann::json;

std::unique_ptr<BsdfModel> buildBlend(const MaterialParameters& p) {
  const std::vector<json>& materials = p.materials("materials");
  std::unique_ptr<BsdfModel> models[2];
  for (size_t i = 0; i < 2; ++i) {
    try {
      models[i] = makeBsdf(materials[i]);
    } catch (const MaterialError& error) {
      throw nestedMaterialError(error, "materials[" + std::to_string(i) + "]");
    }
  }
  try {
    return std::make_unique<BlendBsdf>(std::move(models[0]), std::move(models[1]), p.rgb("weight"));
  } catch (const std::invalid_argument& error) {
    throwMaterialKeyError(
        "materials", json(materials), std::string("cannot be blended (") + error.what() + ")",
        "two materials of which at most one has delta lobes, and transmissive ones with the same index");
  }
}

}  // namespace

MaterialModel blendModel() {
  return {
      .type = "blend",
      .description =
          "Mixture of two materials, f = w fA + (1 - w) fB per channel, sampled as the mixture (exact "
          "pdf with the channel mean of w)",
      .citation = "pbrt-v3 MixMaterial; Mitsuba 0.6 blendbsdf (mixture sampling by a lobe choice)",
      .parameters = {{.name = "weight",
                      .kind = ParameterKind::Rgb,
                      .range = ValueRange::closed(0.0, 1.0),
                      .defaultValue = 0.5,
                      .description =
                          "how much of the first material per linear-RGB channel (the second gets 1 - "
                          "weight); the first is sampled with the channel mean"},
                     {.name = "materials",
                      .kind = ParameterKind::Materials,
                      .defaultValue =
                          json::array({json{{"type", "lambertian"}}, json{{"type", "conductor"}}}),
                      .description = "the two materials [first, second]; at most one with delta lobes, "
                                     "transmissive ones with the same index",
                      .materialCount = 2}},
      .alternatives = {},
      .build = buildBlend,
      .losslessExamples = {{{"type", "blend"},
                            {"weight", 0.4},
                            {"materials",
                             {{{"type", "lambertian"}, {"albedo", 1.0}},
                              {{"type", "conductor"},
                               {"alpha", 0.3},
                               {"multiscatter", "kulla-conty"},
                               {"eta", {1, 1, 1}},
                               {"k", {1e8, 1e8, 1e8}}}}}}},
  };
}

}  // namespace scatterlab
