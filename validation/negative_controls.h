// Deliberately wrong samplers (docs/validation.md section 1, "Power"). Each wraps a correct model
// and is internally self-consistent (sample() reports the wrapper's own pdf and a weight
// that matches eval/pdf), so only the chi-square test can catch it. A kit that passes these
// proves nothing; the suites assert that they are REJECTED.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "materials/bsdf/bsdf.h"

namespace scatterlab {

enum class NegativeControl {
  PdfHighOnHalf,      // pdf() 5% too high on half the sphere: the half, through the lobe's mean
                      // direction, that holds about half of the samples at the given wi
  MissingJacobian,    // pdf() lacks the half-vector Jacobian 1/(4 |wo.h|)
  SwappedDirections,  // pdf() evaluated as pdf(wo, wi)
  RoughnessMismatch,  // sample() drawn from a model whose alpha is 10% off pdf()'s
};
std::string toString(NegativeControl control);
std::vector<NegativeControl> allNegativeControls();

// Some controls change nothing for some models (the classic microfacet pdf is symmetric in
// wi and wo; a roughness at its range limit cannot grow): then a rejection is impossible and
// the control proves nothing. Returns the reason when `broken` is indistinguishable from
// `model` at wi, nothing otherwise.
std::optional<std::string> negativeControlIsNoOp(NegativeControl control, const BsdfModel& model,
                                                 const BsdfModel& broken, const Vec3d& wi);

// The broken variant of `model`, to be tested at incident direction wi (PdfHighOnHalf picks
// its half from the samples there). RoughnessMismatch needs the model whose sampler is used
// (same material, alpha 10% different), built by the caller (the registry knows the
// parameters). `model` and `alteredSampler` must outlive the result.
std::unique_ptr<BsdfModel> makeNegativeControl(NegativeControl control, const BsdfModel& model,
                                               const Vec3d& wi, const BsdfModel* alteredSampler = nullptr);

}  // namespace scatterlab
