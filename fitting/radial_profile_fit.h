// Fitting a radial profile R(r) (a BSSRDF's diffuse reflectance as a function of the distance
// between entry and exit points, in mm^-2 over r in mm) to tabulated values: the
// one-dimensional problem of the BSSRDF models (materials/bssrdf).
//
// How a profile plugs in: a functor with its parameter count and a value templated on the
// scalar type, so that Ceres differentiates it automatically (ceres::Jet):
//
//   struct BurleyProfile {                       // R(r) = A (e^(-r/d) + e^(-r/(3d))) / (8 pi d r)
//     static constexpr int ParameterCount = 2;   // d, A
//     template <typename T> T operator()(const T* p, double r) const {
//       using std::exp;
//       return p[1] * (exp(-r / p[0]) + exp(-r / (3.0 * p[0]))) / (8.0 * Pi * p[0] * r);
//     }
//   };
//   RadialFitOptions options;
//   options.start = {1.0, 0.5};
//   options.lower = {1e-3, 0.0};
//   options.upper = {100.0, 1.0};
//   const RadialFitResult fit = fitRadialProfile(BurleyProfile{}, radii, values, options);
//
// The profile must keep its value and derivative finite at every tabulated radius (guard
// r = 0 and sqrt/exp at the ends of the parameter range, as the BSDF kernels do).
//
// Residual per point i: w_i (R_i - R(r_i; p)), with w_i by `weighting`:
//   Plain    1
//   Area     sqrt(2 pi r_i): errors in the radial integrand 2 pi r R(r), whose integral is the
//            total diffuse reflectance (the default: what a render sees)
//   Relative 1 / |R_i|: every radius counts alike, for profiles that span decades
// times the optional per-point weights. Error bars: ceres::Covariance, scaled by
// sigma^2 = S / (N - K) (S the final sum of squared residuals, N points, K parameters);
// valid when the weights are the inverse noise standard deviations up to one common factor.
#pragma once

#include <cmath>
#include <limits>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include <ceres/ceres.h>

#include "fitting/ceres_support.h"

namespace scatterlab::fitting {

enum class RadialWeighting { Plain, Area, Relative };

struct RadialFitOptions {
  std::vector<double> start;         // K values
  std::vector<double> lower, upper;  // K values each, or empty for no bounds
  RadialWeighting weighting = RadialWeighting::Area;
  std::vector<double> weights;       // per point, or empty for 1
  int maxIterations = 200;
  double functionTolerance = 1e-14, parameterTolerance = 1e-12, gradientTolerance = 1e-16;
};

struct RadialFitResult {
  std::vector<double> parameters;
  std::vector<double> standardDeviations;  // NaN when the covariance is not available
  double cost = 0;                         // S, the sum of squared weighted residuals
  double sigma2 = 0;                       // S / (N - K)
  int iterations = 0;
  std::string termination;                 // CONVERGENCE, NO_CONVERGENCE, FAILURE
  std::string message;
  bool converged = false;
  bool covarianceAvailable = false;
};

template <typename Profile>
concept RadialProfile = requires(const Profile& profile, const double* p) {
  { Profile::ParameterCount } -> std::convertible_to<int>;
  { profile(p, 1.0) } -> std::convertible_to<double>;
};

namespace detail {

// One tabulated point: residual weight (value - profile(r)).
template <typename Profile> struct RadialPointResidual {
  const Profile* profile;
  double r, value, weight;
  template <typename T> bool operator()(const T* p, T* residual) const {
    residual[0] = T(weight) * (T(value) - (*profile)(p, r));
    return true;
  }
};

double radialWeight(RadialWeighting weighting, double r, double value);

}  // namespace detail

template <RadialProfile Profile>
RadialFitResult fitRadialProfile(const Profile& profile, std::span<const double> radii, std::span<const double> values,
                                 const RadialFitOptions& options) {
  constexpr int K = Profile::ParameterCount;
  const size_t n = radii.size();
  if (values.size() != n) throw std::invalid_argument("fitRadialProfile: radii and values differ in length");
  if (n <= size_t(K)) throw std::invalid_argument("fitRadialProfile: fewer points than parameters");
  if (options.start.size() != size_t(K)) throw std::invalid_argument("fitRadialProfile: start needs ParameterCount values");
  if ((!options.lower.empty() && options.lower.size() != size_t(K)) ||
      (!options.upper.empty() && options.upper.size() != size_t(K)))
    throw std::invalid_argument("fitRadialProfile: bounds need ParameterCount values");
  if (!options.weights.empty() && options.weights.size() != n)
    throw std::invalid_argument("fitRadialProfile: weights need one value per point");

  quietCeresLogging();
  RadialFitResult result;
  result.parameters = options.start;
  double* p = result.parameters.data();
  ceres::Problem problem;
  for (size_t i = 0; i < n; ++i) {
    const double weight = detail::radialWeight(options.weighting, radii[i], values[i]) *
                          (options.weights.empty() ? 1.0 : options.weights[i]);
    using Residual = detail::RadialPointResidual<Profile>;
    problem.AddResidualBlock(new ceres::AutoDiffCostFunction<Residual, 1, K>(new Residual{&profile, radii[i], values[i], weight}),
                             nullptr, p);
  }
  for (int k = 0; k < K; ++k) {
    if (!options.lower.empty()) problem.SetParameterLowerBound(p, k, options.lower[size_t(k)]);
    if (!options.upper.empty()) problem.SetParameterUpperBound(p, k, options.upper[size_t(k)]);
  }
  const ceres::Solver::Options solverOptions = denseSolverOptions(
      options.maxIterations, options.functionTolerance, options.parameterTolerance, options.gradientTolerance);
  ceres::Solver::Summary summary;
  ceres::Solve(solverOptions, &problem, &summary);
  result.cost = 2.0 * summary.final_cost;
  result.sigma2 = result.cost / double(n - size_t(K));
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
    for (int k = 0; k < K; ++k) result.standardDeviations[size_t(k)] = std::sqrt(std::max(0.0, result.sigma2 * c[size_t(k * K + k)]));
  }
  return result;
}

}  // namespace scatterlab::fitting
