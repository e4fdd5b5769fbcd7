#include "validation/negative_controls.h"

#include <stdexcept>
#include <vector>

#include "materials/core/rng.h"
#include "validation/bulk_evaluated_bsdf.h"

namespace scatterlab {
namespace {

// "Half the sphere" for the pdf +5% control: the half must hold about half of the lobe's
// mass, or the control is too weak to prove anything (a fixed half such as wo.y > 0 can miss
// a lobe entirely). Among four planes through the lobe's mean direction, take the one that
// splits the model's own samples most evenly.
Vec3d balancedSplitNormal(const BsdfModel& model, const Vec3d& wi) {
  constexpr int Probes = 4096;
  std::vector<Vec3d> samples;
  Vec3d mean(0.0);
  for (uint64_t i = 0; i < Probes; ++i) {
    CounterRng rng(0xba1a, i);
    const double uLobe = rng.uniform();
    const Vec2d u = rng.uniform2D();
    if (const auto s = model.sample(wi, uLobe, u, TransportMode::Radiance)) {
      samples.push_back(s->wo);
      mean += s->wo;
    }
  }
  if (samples.empty() || glm::length(mean) < 1e-9) return {0, 1, 0};
  const Framed frame = Framed::fromNormal(glm::normalize(mean));
  Vec3d best(0, 1, 0);
  double bestImbalance = 2.0;
  for (int k = 0; k < 4; ++k) {
    const double angle = k * PiOver4;
    const Vec3d n = std::cos(angle) * frame.s + std::sin(angle) * frame.t;
    size_t positive = 0;
    for (const Vec3d& w : samples) positive += glm::dot(w, n) > 0 ? 1 : 0;
    const double imbalance = std::abs(double(positive) / double(samples.size()) - 0.5);
    if (imbalance < bestImbalance) {
      bestImbalance = imbalance;
      best = n;
    }
  }
  return best;
}

// A deliberately broken model: eval from `model`, samples drawn by `sampler`, and a pdf()
// that differs from the sampler's true density. sample() reports the broken pdf and the
// weight that goes with it, so the result is self-consistent and only the chi-square
// test can tell that the samples do not follow pdf().
class BrokenSampler : public BsdfModel {
 public:
  BrokenSampler(NegativeControl control, const BsdfModel& model, const BsdfModel& sampler, const Vec3d& wi)
      : control_(control),
        model_(model),
        sampler_(sampler),
        splitNormal_(control == NegativeControl::PdfHighOnHalf ? balancedSplitNormal(model, wi)
                                                               : Vec3d(0, 1, 0)) {}

  Rgb eval(const Vec3d& wi, const Vec3d& wo, TransportMode mode) const override {
    return model_.eval(wi, wo, mode);
  }

  double pdf(const Vec3d& wi, const Vec3d& wo, TransportMode mode) const override {
    return control_ == NegativeControl::SwappedDirections ? brokenPdf(wi, wo, model_.pdf(wo, wi, mode))
                                                          : brokenPdf(wi, wo, model_.pdf(wi, wo, mode));
  }

  std::optional<BsdfSample> sample(const Vec3d& wi, double uLobe, const Vec2d& u,
                                   TransportMode mode) const override {
    std::optional<BsdfSample> s = sampler_.sample(wi, uLobe, u, mode);
    if (!s || s->isDelta()) return s;
    s->pdf = pdf(wi, s->wo, mode);
    if (!(s->pdf > 0)) return std::nullopt;
    s->weight = eval(wi, s->wo, mode) * std::abs(s->wo.z) / s->pdf;
    return s;
  }

  LobeFlags flags() const override { return model_.flags(); }

 protected:
  // The broken pdf at (wi, wo), given the model's pdf where the control reads it: at (wo, wi) for
  // the swapped control, at (wi, wo) for the others.
  double brokenPdf(const Vec3d& wi, const Vec3d& wo, double modelPdf) const {
    switch (control_) {
      case NegativeControl::PdfHighOnHalf: return modelPdf * (glm::dot(wo, splitNormal_) > 0 ? 1.05 : 1.0);
      case NegativeControl::MissingJacobian: {
        // The microfacet half-vector density without its Jacobian dwh/dwo = 1 / (4 |wo.h|).
        const Vec3d h = wi + wo;
        const double len = glm::length(h);
        return len > 0 ? modelPdf * 4.0 * std::abs(glm::dot(wo, h / len)) : 0.0;
      }
      case NegativeControl::SwappedDirections:
      case NegativeControl::RoughnessMismatch: return modelPdf;
    }
    return 0.0;
  }

  NegativeControl control_;
  const BsdfModel& model_;
  const BsdfModel& sampler_;
  Vec3d splitNormal_;  // the boosted half is dot(wo, splitNormal_) > 0
};

// The broken model of a model that answers in bulk (a BSDF written in Python): it answers in bulk
// too, with the same values, so that the kit's quadrature of its pdf asks the model a level at a
// time (energy.h integratePdfCells).
class BulkBrokenSampler final : public BrokenSampler, public BulkEvaluatedBsdf {
 public:
  BulkBrokenSampler(NegativeControl control, const BsdfModel& model, const BulkEvaluatedBsdf& bulk,
                    const BsdfModel& sampler, const Vec3d& wi)
      : BrokenSampler(control, model, sampler, wi), bulk_(bulk) {}

  void evalAndPdf(std::span<const Vec3d> wi, std::span<const Vec3d> wo, TransportMode mode, std::span<Rgb> f,
                  std::span<double> pdf) const override {
    bulk_.evalAndPdf(wi, wo, mode, f, pdf);
    if (control_ == NegativeControl::SwappedDirections) {
      std::vector<Rgb> swappedF(wo.size());
      bulk_.evalAndPdf(wo, wi, mode, swappedF, pdf);
    }
    for (size_t k = 0; k < wo.size(); ++k) pdf[k] = brokenPdf(wi[k], wo[k], pdf[k]);
  }

 private:
  const BulkEvaluatedBsdf& bulk_;
};

std::unique_ptr<BsdfModel> makeBrokenSampler(NegativeControl control, const BsdfModel& model,
                                             const BsdfModel& sampler, const Vec3d& wi) {
  if (const auto* bulk = dynamic_cast<const BulkEvaluatedBsdf*>(&model))
    return std::make_unique<BulkBrokenSampler>(control, model, *bulk, sampler, wi);
  return std::make_unique<BrokenSampler>(control, model, sampler, wi);
}

}  // namespace

std::optional<std::string> negativeControlIsNoOp(NegativeControl control, const BsdfModel& model,
                                                 const BsdfModel& broken, const Vec3d& wi) {
  // Probe with the correct model's own samples: that is where the chi-square test has its
  // power, and where a change must show.
  constexpr int Probes = 4096;
  for (uint64_t i = 0; i < Probes; ++i) {
    CounterRng rng(0x5eed, i);
    const double uLobe = rng.uniform();
    const Vec2d u = rng.uniform2D();
    const std::optional<BsdfSample> s = model.sample(wi, uLobe, u, TransportMode::Radiance);
    if (!s || s->isDelta()) continue;
    if (control == NegativeControl::RoughnessMismatch) {
      const std::optional<BsdfSample> b = broken.sample(wi, uLobe, u, TransportMode::Radiance);
      if (!b || glm::length(b->wo - s->wo) > 1e-12) return std::nullopt;
    } else if (relativeDifference(broken.pdf(wi, s->wo, TransportMode::Radiance),
                                  model.pdf(wi, s->wo, TransportMode::Radiance)) > 1e-12) {
      return std::nullopt;
    }
  }
  switch (control) {
    case NegativeControl::SwappedDirections:
      return "not applicable: this pdf is symmetric in wi and wo, so the swap changes nothing";
    case NegativeControl::RoughnessMismatch:
      return "not applicable: the altered sampler draws the same directions (roughness at its range limit?)";
    default: return "not applicable: the broken pdf equals the model's where the model samples";
  }
}

std::string toString(NegativeControl control) {
  switch (control) {
    case NegativeControl::PdfHighOnHalf: return "pdf +5% on half the sphere";
    case NegativeControl::MissingJacobian: return "missing half-vector Jacobian";
    case NegativeControl::SwappedDirections: return "wi/wo swapped in pdf";
    case NegativeControl::RoughnessMismatch: return "sampler lobe width 10% off";
  }
  return "unknown";
}

std::vector<NegativeControl> allNegativeControls() {
  return {NegativeControl::PdfHighOnHalf, NegativeControl::MissingJacobian,
          NegativeControl::SwappedDirections, NegativeControl::RoughnessMismatch};
}

std::unique_ptr<BsdfModel> makeNegativeControl(NegativeControl control, const BsdfModel& model,
                                               const Vec3d& wi, const BsdfModel* alteredSampler) {
  if (control == NegativeControl::RoughnessMismatch) {
    if (!alteredSampler)
      throw std::invalid_argument("the roughness-mismatch control needs the altered sampler model");
    return makeBrokenSampler(control, model, *alteredSampler, wi);
  }
  return makeBrokenSampler(control, model, model, wi);
}

}  // namespace scatterlab
