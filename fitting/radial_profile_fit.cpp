#include "fitting/radial_profile_fit.h"

#include <algorithm>

#include "materials/core/math.h"

namespace scatterlab::fitting::detail {

double radialWeight(RadialWeighting weighting, double r, double value) {
  switch (weighting) {
    case RadialWeighting::Plain: return 1.0;
    case RadialWeighting::Area: return std::sqrt(2.0 * Pi * std::max(r, 0.0));
    case RadialWeighting::Radius: return std::max(r, 0.0);
    case RadialWeighting::Relative: return std::abs(value) > 0 ? 1.0 / std::abs(value) : 0.0;
  }
  return 1.0;
}

void checkRadialFitInput(size_t points, size_t values, int parameterCount, const RadialFitOptions& options) {
  const size_t K = size_t(parameterCount);
  if (values != points) throw std::invalid_argument("fitRadialProfile: radii and values differ in length");
  if (points <= K) throw std::invalid_argument("fitRadialProfile: fewer points than parameters");
  if (options.start.size() != K)
    throw std::invalid_argument("fitRadialProfile: start needs ParameterCount values");
  if ((!options.lower.empty() && options.lower.size() != K) ||
      (!options.upper.empty() && options.upper.size() != K))
    throw std::invalid_argument("fitRadialProfile: bounds need ParameterCount values");
  if (!options.weights.empty() && options.weights.size() != points)
    throw std::invalid_argument("fitRadialProfile: weights need one value per point");
}

RadialFitResult solveRadialFit(ceres::Problem& problem, std::vector<double>& parameters, size_t points,
                               const RadialFitOptions& options) {
  const int K = int(parameters.size());
  double* p = parameters.data();
  for (int k = 0; k < K; ++k) {
    if (!options.lower.empty()) problem.SetParameterLowerBound(p, k, options.lower[size_t(k)]);
    if (!options.upper.empty()) problem.SetParameterUpperBound(p, k, options.upper[size_t(k)]);
  }
  const ceres::Solver::Options solverOptions =
      denseSolverOptions(options.maxIterations, options.functionTolerance, options.parameterTolerance,
                         options.gradientTolerance);
  ceres::Solver::Summary summary;
  ceres::Solve(solverOptions, &problem, &summary);

  RadialFitResult result;
  result.parameters = parameters;
  result.cost = 2.0 * summary.final_cost;
  result.sigma2 = result.cost / double(points - size_t(K));
  result.iterations = int(summary.iterations.size()) - 1;
  result.termination = terminationName(summary.termination_type);
  result.message = summary.message;
  result.converged = summary.termination_type == ceres::CONVERGENCE;

  ceres::Covariance::Options covarianceOptions;
  covarianceOptions.algorithm_type = ceres::DENSE_SVD;
  ceres::Covariance covariance(covarianceOptions);
  const std::vector<std::pair<const double*, const double*>> blocks{{p, p}};
  result.standardDeviations.assign(size_t(K), std::numeric_limits<double>::quiet_NaN());
  result.covarianceAvailable = covariance.Compute(blocks, &problem);
  if (result.covarianceAvailable) {
    std::vector<double> c(size_t(K * K));
    covariance.GetCovarianceBlock(p, p, c.data());
    for (int k = 0; k < K; ++k)
      result.standardDeviations[size_t(k)] = std::sqrt(std::max(0.0, result.sigma2 * c[size_t(k * K + k)]));
  }
  return result;
}

}  // namespace scatterlab::fitting::detail
