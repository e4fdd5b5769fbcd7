// `scatterlab check`: the statistical test kit (docs/validation.md sections 1-6) on materials given
// as inline JSON or files, or on the built-in showcase. Prints each completed material and
// the verdict table, or one JSON document with --json.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <CLI/CLI.hpp>

#include "materials/bsdf/bsdf.h"
#include "materials/registry/spec_validation.h"
#include "validation/bsdf_check.h"
#include "validation/subsurface_check.h"

namespace scatterlab {

struct CheckCommandOptions {
  std::vector<std::string> materials;  // inline JSON or file paths; none: the showcase
  BsdfCheckOptions kit;
  bool negativeControls = false;
  // With a value: also render each BSDF material by path tracing, light tracing and BDPT and
  // compare the renders (app/render_agreement.h); the value is the path tracer's samples per pixel.
  std::optional<int> renderAgreementSpp;
  bool json = false;
};

// Declares the subcommand on `app`, its options bound to `options`.
CLI::App* addCheckCommand(CLI::App& app, CheckCommandOptions& options);

// Validates every material and option before any work or output file, then runs the kit.
// Returns the exit code: 0 when every row passes, 1 otherwise. Bad input throws
// MaterialError or InputError.
int runCheckCommand(const CheckCommandOptions& options);

// The subsurface kit on the BSDF kit's options: --grid R x C gives R radius bins and R/2 x C/4
// probe cells (64 and 32 x 32 by default). Shared with the lab report.
SubsurfaceCheckOptions subsurfaceCheckOptions(const BsdfCheckOptions& kit);

// The sampler of the roughness-mismatch negative control (docs/validation.md, "Negative controls": a lobe
// width 10% off the one pdf() uses), or null for a model without a lobe-width parameter.
std::unique_ptr<BsdfModel> makeRoughnessMismatchSampler(const ValidatedMaterial& material);

}  // namespace scatterlab
