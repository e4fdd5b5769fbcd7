// Fitting a FitModel to BRDF samples: the whole procedure behind `scatterlab fit`.
//
//  1. Grid (initialization.h) on a stratified subset of gridSamples samples.
//  2. Multi-start: Ceres Levenberg-Marquardt (least_squares.h: one compressed residual
//     block, DENSE_QR on p + 1 rows, bounds from the registry) from each of the best
//     `starts` distinct grid points, on a stratified subset of startSamples samples; every
//     start's result is reported.
//  3. The best start is refined on all the samples (skipped when the start subset already is
//     all of them).
//  4. Error bars: ceres::Covariance of the compressed problem gives (J^T J)^-1 of the
//     (robustly weighted) residuals. The residuals' scale is not known, so it is estimated
//     from the fit: sigma^2 = S / (N - p), S the final sum of squared (or, with a robust
//     loss, rho-) residuals, N = 3 x samples observations, p parameters; the reported
//     covariance is sigma^2 (J^T J)^-1. This holds when the metric's weights are the inverse
//     variances of the noise up to one common factor (e.g. the l2 metric and additive noise
//     of one standard deviation); under other noise the error bars are indicative only.
//     Rank deficiency (a combination of parameters the data does not determine) is detected
//     on the column-normalised J^T J and reported with the parameters involved; the error
//     bars are then those of the pseudo-inverse and marked as such.
// Every random choice (the subsets) is keyed by `seed`, and every sum is taken in a fixed
// order: the same inputs give the same result for any thread count.
//
// Nothing fails silently (docs/reliability.md, "Messages"): grid points whose cost is not
// finite are left out and counted (initialization.h), so are starts whose run ends on a cost
// that is not finite (the best start is chosen among the others); and a result whose residuals
// are not finite is marked (finiteResiduals), without error bars, and judged a failed fit
// (app/fit_verdict.h). When no grid point has a finite cost, fitBrdf throws.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <nlohmann/json.hpp>

#include "fitting/brdf_samples.h"
#include "fitting/fit_model.h"
#include "fitting/metric.h"

namespace scatterlab::fitting {

// stage, fraction done.
using FitProgress = std::function<void(const std::string&, double)>;

struct FitOptions {
  Metric metric = Metric::Ngan;
  RobustLoss robust = RobustLoss::None;
  // The robust loss's scale in residual units; by default 2.5 x 1.4826 x the median absolute
  // residual at the best grid point (a robust estimate of 2.5 standard deviations).
  std::optional<double> robustScale;
  int gridBudget = 256;
  int starts = 3;
  size_t gridSamples = 20000;    // 0: all samples
  size_t startSamples = 100000;  // 0: all samples (no separate refinement)
  uint64_t seed = 1;
  int maxIterations = 100;  // per Ceres run (a start, the refinement)
  double functionTolerance = 1e-10;
  double parameterTolerance = 1e-10;
  double gradientTolerance = 1e-14;
  int threads = 0;  // 0: all cores
  FitProgress progress;
};

// One Ceres run.
struct SolveSummary {
  std::vector<double> initial, final;
  double initialCost = 0, finalCost = 0;  // S = 2 x Ceres's cost; NaN when Ceres could not evaluate it
  int iterations = 0;
  std::string termination;  // CONVERGENCE, NO_CONVERGENCE, FAILURE
  std::string message;      // Ceres's reason
  bool converged = false;
};

struct ParameterEstimate {
  std::string name;
  double value = 0;
  double standardDeviation = 0;  // NaN when the covariance is not available
  double lower = 0, upper = 0;
  bool atBound = false;
};

struct FitResult {
  std::vector<double> x;
  std::vector<ParameterEstimate> parameters;
  SolveSummary final;  // the refinement on all samples (or the best start)
  std::vector<SolveSummary> starts;
  size_t gridPoints = 0, gridSamples = 0, startSamples = 0, samples = 0;
  size_t gridNonFinitePoints = 0;    // of gridPoints, left out: cost not finite (expected 0)
  size_t nonFiniteStarts = 0;        // of starts, ended on a cost that is not finite (expected 0)
  bool finiteResiduals = true;       // false: the residuals at x are not finite, the fit failed
  size_t observations = 0;           // N
  double sigma2 = 0;                 // S / (N - p)
  double robustScale = 0;            // 0 without a robust loss
  Rgb rms{0.0}, relativeError{0.0};  // per channel, in the metric (header of least_squares.h)
  bool covarianceAvailable = false;
  bool rankDeficient = false;
  std::vector<std::string> unidentified;  // each: the parameters of one null-space direction
  Eigen::MatrixXd covariance;             // sigma^2 (J^T J)^-1, p x p (empty when not available)
  double seconds = 0;
};

// Throws std::invalid_argument when `samples` is empty, std::runtime_error when no grid point
// has a finite cost.
FitResult fitBrdf(const FitModel& model, const BrdfSamples& samples, const FitOptions& options);

// The result as JSON: parameters with error bars, cost, errors, iterations, starts.
nlohmann::json toJson(const FitResult& result, const FitModel& model, const FitOptions& options);

}  // namespace scatterlab::fitting
