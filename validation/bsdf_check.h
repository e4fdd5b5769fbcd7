// The whole kit run on one BSDF model over a set of incident angles (docs/validation.md 1-4):
// chi-square of sample() against pdf(), per-sample consistency, pdf normalisation,
// directional albedo <= 1 (quadrature and Monte Carlo), white furnace for lossless models,
// and reciprocity. Used by `scatterlab check` and by the model tests.
//
// Models with transmission (flags() has Transmission) also get: incident directions from
// inside the medium (180 - theta), energy rows in importance transport (bsdf_sampling.h
// energyTransportMode), consistency in both transport modes and the relation between them
// ("transport modes", transport_modes.h), and the generalised reciprocity in both modes plus
// the adjoint relation (reciprocity.h).
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "materials/bsdf/bsdf.h"
#include "validation/check_report.h"
#include "validation/negative_controls.h"

namespace scatterlab {

struct BsdfCheckOptions {
  std::vector<double> wiThetaDeg{0, 30, 60, 85, 89};
  double wiPhiDeg = 30.0;  // off the tangent axes, so anisotropy bugs show
  size_t samples = 1'000'000;
  int thetaBins = 64;  // cos(theta) cells over [-1, 1]
  int phiBins = 128;   // phi cells over [-pi, pi]
  uint64_t seed = 1;
  double alpha = 0.01;         // family-wise significance before the Sidak correction
  int chiSquareTestCount = 0;  // tests in the whole suite for the Sidak correction; 0: this run's count
  std::optional<std::filesystem::path> imageDir;  // write observed/expected/residual PNGs here
  bool imagesOnFailureOnly = false;
  int reciprocityPairs = 10000;
  // Models with transmission are also checked from inside the medium: each angle theta < 90
  // of wiThetaDeg is repeated as 180 - theta (wi.z < 0), and the rows show that angle.
  // Angles above 90 may also be listed directly.
  bool transmissionFromBelow = true;
};

// stage: what is running ("chi2 wi=60"), fraction in [0, 1] of this material's checks.
using ProgressCallback = std::function<void(const std::string& stage, double fraction)>;

// Runs every check on `model`; rows are labelled with `label`.
CheckReport runBsdfChecks(const BsdfModel& model, const std::string& label, const BsdfCheckOptions& options,
                          const ProgressCallback& progress = {});

// The negative controls (negative_controls.h) of `model`, each run through the chi-square
// test at every incident angle (incidentAngles(): with transmission, from below too); a row
// PASSES when the kit REJECTS the broken sampler.
// `alteredSampler` (the same material 10% rougher, materials/registry/spec_validation.h
// withMismatchedRoughness) enables RoughnessMismatch; without it that control is reported as not applicable
// (a row with passed = true and a note).
CheckReport runNegativeControls(const BsdfModel& model, const BsdfModel* alteredSampler,
                                const std::string& label, const BsdfCheckOptions& options,
                                const ProgressCallback& progress = {});

// The units runBsdfChecks and runNegativeControls are made of, for callers that run them one at a
// time to bound what they hold at once (the Python kit's replay of a Python object,
// docs/python.md): the rows of incident angle incidentAngles(options, model)[angleIndex]
// (its seed and Sidak threshold as in the whole run), the reciprocity rows, and one negative
// control at one angle (one not-applicable row, whatever angleIndex, for RoughnessMismatch
// without `alteredSampler`). Concatenated in runBsdfChecks' order they are its report.
CheckReport runBsdfChecksAtAngle(const BsdfModel& model, const std::string& label,
                                 const BsdfCheckOptions& options, size_t angleIndex);
CheckReport runReciprocityChecks(const BsdfModel& model, const std::string& label,
                                 const BsdfCheckOptions& options);
CheckReport runNegativeControl(const BsdfModel& model, const BsdfModel* alteredSampler,
                               const std::string& label, const BsdfCheckOptions& options,
                               NegativeControl control, size_t angleIndex);

// Number of chi-square tests runBsdfChecks will perform with these options (for the
// Sidak correction when several materials are checked together): the listed angles for a
// model without transmission...
int chiSquareTestCount(const BsdfCheckOptions& options);
// ...and for `model`, whose transmission adds the angles from below.
int chiSquareTestCount(const BsdfCheckOptions& options, const BsdfModel& model);

// The incident polar angles runBsdfChecks and runNegativeControls use for `model`, in order.
std::vector<double> incidentAngles(const BsdfCheckOptions& options, const BsdfModel& model);

}  // namespace scatterlab
