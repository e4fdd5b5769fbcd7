// A plugin's BSDF behind a guard (materials/registry/plugin.h): every call goes to the plugin's
// model, and an exception it throws becomes a PluginError that names the model, the library,
// the call and its arguments, so that a plugin bug is one message (exit 2), never a crash or an
// "internal error" of scatterlab. Values pass unchanged: a NaN is the checks' and the renderer's
// to count and report, as for every model.
#pragma once

#include <memory>

#include "materials/bsdf/bsdf.h"
#include "materials/registry/material_model.h"

namespace scatterlab {

// Builds a plugin model's BSDF from validated parameters, guarded. A MaterialError from the
// plugin (a combination of parameters it refuses) passes as it is; any other exception, or no
// model at all, throws PluginError.
std::unique_ptr<BsdfModel> buildPluginBsdf(const MaterialModel& model, const MaterialParameters& parameters);

class PluginBsdf final : public BsdfModel {
 public:
  // `entry` is the registry entry the model was built from (it outlives the model).
  PluginBsdf(std::unique_ptr<BsdfModel> model, const MaterialModel& entry);

  Rgb eval(const Vec3d& wi, const Vec3d& wo, TransportMode mode = TransportMode::Radiance) const override;
  double pdf(const Vec3d& wi, const Vec3d& wo, TransportMode mode = TransportMode::Radiance) const override;
  std::optional<BsdfSample> sample(const Vec3d& wi, double uLobe, const Vec2d& u,
                                   TransportMode mode = TransportMode::Radiance) const override;
  LobeFlags flags() const override;
  bool isLossless() const override;
  double losslessAccuracy() const override;
  bool isReciprocal() const override;
  double interiorIndex() const override;

  const BsdfModel& plugin() const { return *model_; }

 private:
  // Runs `call`, turning an exception into a PluginError about `what` ("eval(wi = ..., wo = ...)").
  template <typename Call, typename Describe> auto guarded(Call&& call, Describe&& what) const;

  std::unique_ptr<BsdfModel> model_;
  const MaterialModel* entry_;
};

}  // namespace scatterlab
