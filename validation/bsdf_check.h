// The whole kit run on one BSDF model over a set of incident angles (VALIDATION.md 1-4):
// chi-square of sample() against pdf(), per-sample consistency, pdf normalisation,
// directional albedo <= 1 (quadrature and Monte Carlo), white furnace for lossless models,
// and reciprocity. Used by `scatterlab check` and by the model tests.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "materials/bsdf/bsdf.h"
#include "validation/check_report.h"

namespace scatterlab {

struct BsdfCheckOptions {
  std::vector<double> wiThetaDeg{0, 30, 60, 85, 89};
  double wiPhiDeg = 30.0;         // off the tangent axes, so anisotropy bugs show
  size_t samples = 1'000'000;
  int thetaBins = 64;             // cos(theta) cells over [-1, 1]
  int phiBins = 128;              // phi cells over [-pi, pi]
  uint64_t seed = 1;
  double alpha = 0.01;            // family-wise significance before the Sidak correction
  int chiSquareTestCount = 0;     // tests in the whole suite for the Sidak correction; 0: this run's count
  std::optional<std::filesystem::path> imageDir;  // write observed/expected/residual PNGs here
  bool imagesOnFailureOnly = false;
  int reciprocityPairs = 10000;
};

// stage: what is running ("chi2 wi=60"), fraction in [0, 1] of this material's checks.
using ProgressCallback = std::function<void(const std::string& stage, double fraction)>;

// Runs every check on `model`; rows are labelled with `label`.
CheckReport runBsdfChecks(const BsdfModel& model, const std::string& label, const BsdfCheckOptions& options,
                          const ProgressCallback& progress = {});

// The negative controls (negative_controls.h) of `model`, each run through the chi-square
// test at every incident angle; a row PASSES when the kit REJECTS the broken sampler.
// `alteredSampler` (the same material with alpha x 1.1) enables RoughnessMismatch; without
// it that control is reported as not applicable (a row with passed = true and a note).
CheckReport runNegativeControls(const BsdfModel& model, const BsdfModel* alteredSampler, const std::string& label,
                                const BsdfCheckOptions& options, const ProgressCallback& progress = {});

// Number of chi-square tests runBsdfChecks will perform with these options (for the
// Sidak correction when several materials are checked together).
int chiSquareTestCount(const BsdfCheckOptions& options);

}  // namespace scatterlab
