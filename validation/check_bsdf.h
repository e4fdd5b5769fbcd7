// The test kit as one library call (docs/own-bsdf.md): everything `scatterlab check` runs on a
// BSDF (docs/validation.md sections 1-4: chi-square of sample() against pdf() at each incident
// angle, per-sample consistency of weight, pdf and eval, pdf normalisation, albedo <= 1, the
// white furnace for lossless models, reciprocity) and, on request, the negative controls, for
// any model implementing BsdfModel (materials/bsdf/bsdf.h), wherever it is written. A model
// that lives in another renderer can be wrapped in FunctionBsdf (materials/bsdf/function_bsdf.h);
// validation/gtest_check.h makes either a GoogleTest assertion.
//
// The model must follow bsdf.h's conventions: local shading frame (z = normal), both directions
// pointing away from the surface (wi given, wo sampled), eval = f WITHOUT the cosine, pdf per
// unit solid angle of wo, sample() weight = f |cos wo| / pdf, never NaN.
//
//     scatterlab::CheckBsdfOptions options;
//     options.negativeControls = true;
//     const scatterlab::CheckReport report = scatterlab::checkBsdf(myModel, options);
//     std::cout << scatterlab::formatVerdict(report);   // the table `scatterlab check` prints
//     return report.passed() ? 0 : 1;
#pragma once

#include <string>

#include "materials/bsdf/bsdf.h"
#include "validation/bsdf_check.h"
#include "validation/check_report.h"

namespace scatterlab {

struct CheckBsdfOptions {
  // Incident angles, samples, chi-square grid, seed, significance, as `scatterlab check`'s
  // options; kit.imageDir: also write the observed, expected and residual PNG maps of every
  // chi-square test there (created when missing).
  BsdfCheckOptions kit{};
  // Also run the deliberately broken samplers of validation/negative_controls.h; their rows
  // pass when the kit REJECTS them (a kit that cannot reject them proves nothing).
  bool negativeControls = false;
  // For the roughness-mismatch control: the same model with its lobe 10% wider or narrower
  // (it outlives the call). Without it that control is reported as not applicable.
  const BsdfModel* roughnessMismatchSampler = nullptr;
  std::string label = "bsdf";  // names the rows and the image files
  ProgressCallback progress{};
};

// Runs the kit on `model` and returns its rows; report.passed() is the verdict.
CheckReport checkBsdf(const BsdfModel& model, const CheckBsdfOptions& options = {});

// The verdict table as `scatterlab check` prints it: every row, the counts, and
// "verdict: PASS" or "verdict: FAIL".
std::string formatVerdict(const CheckReport& report);

}  // namespace scatterlab
