// Adaptors from a BSDF model (anything with eval/pdf/sample per bsdf.h; templated so the
// concrete `final` models are called without virtual dispatch) to the chi-square kit.
#pragma once

#include <optional>

#include "materials/bsdf/bsdf.h"
#include "materials/core/rng.h"
#include "validation/chi_square.h"

namespace scatterlab {

// One draw of the model's sampler with the kit's random numbers: uLobe first, then u.
// Both the histogram pass and the consistency pass use this, so sample i is the same in both.
template <typename Model>
std::optional<BsdfSample> drawBsdfSample(const Model& model, const Vec3d& wi, CounterRng& rng,
                                         TransportMode mode = TransportMode::Radiance) {
  const double uLobe = rng.uniform();
  const Vec2d u = rng.uniform2D();
  return model.sample(wi, uLobe, u, mode);
}

inline bool isValidWeight(const Rgb& w) { return isFinite(w) && w.x >= 0 && w.y >= 0 && w.z >= 0; }

template <typename Model>
auto bsdfDirectionSampler(const Model& model, const Vec3d& wi, TransportMode mode = TransportMode::Radiance) {
  return [&model, wi, mode](CounterRng& rng) -> std::optional<DirectionSample> {
    const std::optional<BsdfSample> s = drawBsdfSample(model, wi, rng, mode);
    if (!s) return std::nullopt;
    DirectionSample d{s->wo, s->pdf, s->isDelta(), s->weight};
    if (!isValidWeight(s->weight)) d.invalid = "sample weight is negative or not finite";
    return d;
  };
}

// The chi-square test of one model at one incident direction.
template <typename Model> ChiSquareResult bsdfChiSquareTest(const Model& model, const Vec3d& wi,
                                                            const ChiSquareOptions& options,
                                                            TransportMode mode = TransportMode::Radiance) {
  return sphericalChiSquareTest(
      bsdfDirectionSampler(model, wi, mode), [&](const Vec3d& wo) { return model.pdf(wi, wo, mode); },
      options);
}

}  // namespace scatterlab
