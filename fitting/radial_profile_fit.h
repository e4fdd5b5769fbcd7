// Fitting a radial profile R(r) (a BSSRDF's diffuse reflectance as a function of the distance
// between entry and exit points, in mm^-2 over r in mm) to tabulated values: the
// one-dimensional problem of the BSSRDF models (materials/bssrdf).
//
// Two kinds of data. Values at radii (fitRadialProfile): the profile is a functor with its
// parameter count and a value templated on the scalar type, so that Ceres differentiates it
// automatically (ceres::Jet):
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
// Averages over annuli [r_k, r_k+1] (fitRadialAnnuli), what a Monte Carlo tally measures: the
// functor gives the cumulative reflectance C(r) = integral_0^r 2 pi r' R(r') dr' instead,
//   template <typename T> T cumulative(const T* p, double r) const,
// and the model's annulus average is (C(r_k+1) - C(r_k)) / (pi (r_k+1^2 - r_k^2)): exact, and
// finite where R itself diverges (r = 0 for Burley's profile and the dipoles' limits).
//
// The profile must keep its value and derivative finite at every tabulated radius (guard
// r = 0 and sqrt/exp at the ends of the parameter range, as the BSDF kernels do).
//
// Residual per point i: w_i (R_i - R(r_i; p)), with w_i by `weighting` (for an annulus, r_i is
// its middle radius):
//   Plain    1
//   Area     sqrt(2 pi r_i): squared errors weighted by the area element 2 pi r dr, the
//            plane's L2 norm of R_i - R (the default)
//   Radius   r_i: errors in r R(r), the curve Christensen & Burley 2015 plot and fit (finite
//            at r = 0, where R diverges like 1 / r)
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
#include "materials/core/math.h"

namespace scatterlab::fitting {

enum class RadialWeighting { Plain, Area, Radius, Relative };

struct RadialFitOptions {
  std::vector<double> start;         // K values
  std::vector<double> lower, upper;  // K values each, or empty for no bounds
  RadialWeighting weighting = RadialWeighting::Area;
  std::vector<double> weights;  // per point, or empty for 1
  int maxIterations = 200;
  double functionTolerance = 1e-14, parameterTolerance = 1e-12, gradientTolerance = 1e-16;
};

struct RadialFitResult {
  std::vector<double> parameters;
  std::vector<double> standardDeviations;  // NaN when the covariance is not available
  double cost = 0;                         // S, the sum of squared weighted residuals
  double sigma2 = 0;                       // S / (N - K)
  int iterations = 0;
  std::string termination;  // CONVERGENCE, NO_CONVERGENCE, FAILURE
  std::string message;
  bool converged = false;
  bool covarianceAvailable = false;
};

template <typename Profile>
concept RadialProfile = requires(const Profile& profile, const double* p) {
  { Profile::ParameterCount } -> std::convertible_to<int>;
  { profile(p, 1.0) } -> std::convertible_to<double>;
};

template <typename Profile>
concept CumulativeRadialProfile = requires(const Profile& profile, const double* p) {
  { Profile::ParameterCount } -> std::convertible_to<int>;
  { profile.cumulative(p, 1.0) } -> std::convertible_to<double>;
};

namespace detail {

// One tabulated point: weight (value - R(r)).
template <typename Profile> struct RadialPointResidual {
  const Profile* profile;
  double r, value, weight;
  template <typename T> bool operator()(const T* p, T* residual) const {
    residual[0] = T(weight) * (T(value) - (*profile)(p, r));
    return true;
  }
};

// One annulus [r0, r1] of area pi (r1^2 - r0^2): weight (value - (C(r1) - C(r0)) / area).
template <typename Profile> struct RadialAnnulusResidual {
  const Profile* profile;
  double r0, r1, area, value, weight;
  template <typename T> bool operator()(const T* p, T* residual) const {
    residual[0] = T(weight) * (T(value) - (profile->cumulative(p, r1) - profile->cumulative(p, r0)) / area);
    return true;
  }
};

double radialWeight(RadialWeighting weighting, double r, double value);

// Throws std::invalid_argument naming what does not fit: `points` values for K parameters.
void checkRadialFitInput(size_t points, size_t values, int parameterCount, const RadialFitOptions& options);

// Bounds, the Levenberg-Marquardt solve and the covariance of the problem's one parameter
// block `parameters` (started at options.start) with `points` residuals.
RadialFitResult solveRadialFit(ceres::Problem& problem, std::vector<double>& parameters, size_t points,
                               const RadialFitOptions& options);

}  // namespace detail

template <RadialProfile Profile>
RadialFitResult fitRadialProfile(const Profile& profile, std::span<const double> radii,
                                 std::span<const double> values, const RadialFitOptions& options) {
  constexpr int K = Profile::ParameterCount;
  const size_t n = radii.size();
  detail::checkRadialFitInput(n, values.size(), K, options);
  quietCeresLogging();
  std::vector<double> parameters = options.start;
  ceres::Problem problem;
  for (size_t i = 0; i < n; ++i) {
    const double weight = detail::radialWeight(options.weighting, radii[i], values[i]) *
                          (options.weights.empty() ? 1.0 : options.weights[i]);
    using Residual = detail::RadialPointResidual<Profile>;
    problem.AddResidualBlock(
        new ceres::AutoDiffCostFunction<Residual, 1, K>(new Residual{&profile, radii[i], values[i], weight}),
        nullptr, parameters.data());
  }
  return detail::solveRadialFit(problem, parameters, n, options);
}

// `edges` are n + 1 increasing radii (mm) bounding n annuli; `means` the n averages of R over
// them (mm^-2).
template <CumulativeRadialProfile Profile>
RadialFitResult fitRadialAnnuli(const Profile& profile, std::span<const double> edges,
                                std::span<const double> means, const RadialFitOptions& options) {
  constexpr int K = Profile::ParameterCount;
  if (edges.size() != means.size() + 1)
    throw std::invalid_argument("fitRadialAnnuli: n + 1 edges are needed for n annulus means");
  const size_t n = means.size();
  detail::checkRadialFitInput(n, means.size(), K, options);
  for (size_t i = 0; i < n; ++i)
    if (!(edges[i] >= 0 && edges[i + 1] > edges[i]))
      throw std::invalid_argument("fitRadialAnnuli: edges must increase from >= 0");
  quietCeresLogging();
  std::vector<double> parameters = options.start;
  ceres::Problem problem;
  for (size_t i = 0; i < n; ++i) {
    const double r0 = edges[i], r1 = edges[i + 1];
    const double weight = detail::radialWeight(options.weighting, 0.5 * (r0 + r1), means[i]) *
                          (options.weights.empty() ? 1.0 : options.weights[i]);
    using Residual = detail::RadialAnnulusResidual<Profile>;
    const double area = Pi * (r1 * r1 - r0 * r0);
    problem.AddResidualBlock(new ceres::AutoDiffCostFunction<Residual, 1, K>(
                                 new Residual{&profile, r0, r1, area, means[i], weight}),
                             nullptr, parameters.data());
  }
  return detail::solveRadialFit(problem, parameters, n, options);
}

}  // namespace scatterlab::fitting
