#include "integrator/fault_injection.h"

#include <cstdlib>
#include <limits>
#include <string_view>
#include <utility>

namespace scatterlab {

namespace {

enum class Fault { None, NonFinite, Negative };

Fault requestedFault() {
  const char* value = std::getenv(TestFaultVariable);
  if (!value) return Fault::None;
  const std::string_view name(value);
  if (name == "non-finite") return Fault::NonFinite;
  if (name == "negative") return Fault::Negative;
  return Fault::None;
}

// The model with the fault in the weight of half of its samples; eval and pdf unchanged.
class FaultyBsdf final : public BsdfModel {
 public:
  FaultyBsdf(std::unique_ptr<BsdfModel> model, Fault fault) : model_(std::move(model)), fault_(fault) {}

  Rgb eval(const Vec3d& wi, const Vec3d& wo, TransportMode mode) const override {
    return model_->eval(wi, wo, mode);
  }
  double pdf(const Vec3d& wi, const Vec3d& wo, TransportMode mode) const override {
    return model_->pdf(wi, wo, mode);
  }
  std::optional<BsdfSample> sample(const Vec3d& wi, double uLobe, const Vec2d& u,
                                   TransportMode mode) const override {
    std::optional<BsdfSample> s = model_->sample(wi, uLobe, u, mode);
    if (s && uLobe < 0.5)
      s->weight = fault_ == Fault::NonFinite ? Rgb(std::numeric_limits<double>::quiet_NaN()) : Rgb(-1.0);
    return s;
  }
  LobeFlags flags() const override { return model_->flags(); }
  bool isLossless() const override { return false; }
  bool isReciprocal() const override { return model_->isReciprocal(); }
  double interiorIndex() const override { return model_->interiorIndex(); }

 private:
  std::unique_ptr<BsdfModel> model_;
  Fault fault_;
};

}  // namespace

std::unique_ptr<BsdfModel> withTestFault(std::unique_ptr<BsdfModel> model) {
  const Fault fault = requestedFault();
  if (fault == Fault::None) return model;
  return std::make_unique<FaultyBsdf>(std::move(model), fault);
}

}  // namespace scatterlab
