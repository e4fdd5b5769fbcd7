#include "fitting/brdf_fit.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <ceres/ceres.h>

#include "fitting/ceres_support.h"
#include "fitting/initialization.h"
#include "fitting/least_squares.h"

namespace scatterlab::fitting {

namespace {

using nlohmann::json;

// Reports Ceres's iterations as progress (the fraction of the iteration budget used).
class IterationProgress final : public ceres::IterationCallback {
 public:
  IterationProgress(const FitProgress& progress, std::string stage, int maxIterations)
      : progress_(progress), stage_(std::move(stage)), maxIterations_(maxIterations) {}
  ceres::CallbackReturnType operator()(const ceres::IterationSummary& summary) override {
    if (progress_)
      progress_(stage_ + " (iteration " + std::to_string(summary.iteration) + ")",
                double(summary.iteration) / double(std::max(maxIterations_, 1)));
    return ceres::SOLVER_CONTINUE;
  }

 private:
  const FitProgress& progress_;
  std::string stage_;
  int maxIterations_;
};

// Parameters on a bound whose gradient points out of the box (the cost would fall further
// past the bound): held for the next Ceres run.
std::vector<int> blockedByBounds(const FitModel& model, const std::vector<double>& x,
                                 const Eigen::VectorXd& gradient) {
  std::vector<int> blocked;
  for (size_t j = 0; j < x.size(); ++j) {
    const FitParameter& p = model.parameters()[j];
    const double g = gradient[Eigen::Index(j)];  // of S / 2; the cost falls along -g
    if ((x[j] <= p.lower && g > 0) || (x[j] >= p.upper && g < 0)) blocked.push_back(int(j));
  }
  return blocked;
}

// One Ceres run with `held` parameters constant.
SolveSummary solveOnce(CompressedCostFunction& cost, const FitModel& model, std::vector<double>& x,
                       const std::vector<int>& held, int maxIterations, const FitOptions& options,
                       const std::string& stage) {
  const auto& parameters = model.parameters();
  SolveSummary out;
  ceres::Problem::Options problemOptions;
  problemOptions.cost_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  ceres::Problem ceresProblem(problemOptions);
  ceresProblem.AddResidualBlock(&cost, nullptr, x.data());
  for (size_t j = 0; j < x.size(); ++j) {
    ceresProblem.SetParameterLowerBound(x.data(), int(j), parameters[j].lower);
    ceresProblem.SetParameterUpperBound(x.data(), int(j), parameters[j].upper);
  }
  if (!held.empty()) ceresProblem.SetManifold(x.data(), new ceres::SubsetManifold(int(x.size()), held));
  ceres::Solver::Options solverOptions = denseSolverOptions(
      maxIterations, options.functionTolerance, options.parameterTolerance, options.gradientTolerance);
  solverOptions.num_threads = 1;  // one residual block; the parallelism is inside it
  IterationProgress callback(options.progress, stage, maxIterations);
  solverOptions.callbacks.push_back(&callback);
  ceres::Solver::Summary summary;
  ceres::Solve(solverOptions, &ceresProblem, &summary);
  // Ceres leaves a cost it could not evaluate at -1: a sum of squares is never negative, so
  // that is NaN here (counted, never chosen as the best start: brdf_fit.h).
  const auto sumOfSquares = [](double ceresCost) {
    return ceresCost >= 0 ? 2.0 * ceresCost : std::numeric_limits<double>::quiet_NaN();
  };
  out.initialCost = sumOfSquares(summary.initial_cost);
  out.finalCost = sumOfSquares(summary.final_cost);
  out.iterations = int(summary.iterations.size()) - 1;
  out.termination = terminationName(summary.termination_type);
  out.message = summary.message;
  out.converged = summary.termination_type == ceres::CONVERGENCE;
  return out;
}

// Levenberg-Marquardt with the registry's bounds. Ceres projects a step onto the box, so a
// parameter that the data push past its bound (an albedo that would go negative) keeps
// shrinking the steps of all the others; such parameters are held (an active set: the ones
// on a bound whose gradient points outward), released again when their gradient turns
// inward, and the run repeated until the set no longer changes. The rounds share one budget
// of options.maxIterations.
// `equations` (optional) receives the normal equations at the solution.
SolveSummary solve(const BrdfLeastSquares& problem, std::vector<double> x, const FitOptions& options,
                   const std::string& stage, NormalEquations* equations = nullptr) {
  const FitModel& model = problem.model();
  const auto& parameters = model.parameters();
  for (size_t j = 0; j < x.size(); ++j) x[j] = std::clamp(x[j], parameters[j].lower, parameters[j].upper);
  SolveSummary out;
  out.initial = x;
  CompressedCostFunction cost(problem);
  std::vector<int> held = blockedByBounds(model, x, cost.normalEquationsAt(x).gradient);
  constexpr int MaxRounds = 5;
  for (int round = 0; round < MaxRounds; ++round) {
    SolveSummary run;
    if (held.size() == x.size()) {
      run.initialCost = run.finalCost = problem.cost(x.data());
      run.termination = "CONVERGENCE";
      run.message = "every parameter is held on a bound";
      run.converged = true;
    } else {
      run = solveOnce(cost, model, x, held, std::max(options.maxIterations - out.iterations, 1), options,
                      stage);
    }
    if (round == 0) out.initialCost = run.initialCost;
    out.finalCost = run.finalCost;
    out.iterations += run.iterations;
    out.termination = run.termination;
    out.message = run.message;
    out.converged = run.converged;
    if (!run.converged || out.iterations >= options.maxIterations) break;
    const std::vector<int> next = blockedByBounds(model, x, cost.normalEquationsAt(x).gradient);
    if (next == held) break;
    held = next;
  }
  out.final = x;
  if (equations) *equations = cost.normalEquationsAt(x);
  return out;
}

// The null space of the column-normalised J^T J: how many directions, and each as the
// parameters it involves.
struct NullSpace {
  int dimension = 0;
  std::vector<std::string> directions;
};

NullSpace nullSpaceOf(const Eigen::MatrixXd& hessian, const FitModel& model) {
  const Eigen::Index p = hessian.rows();
  NullSpace out;
  Eigen::VectorXd scale(p);
  for (Eigen::Index j = 0; j < p; ++j) {
    const double d = hessian(j, j);
    scale[j] = d > 0 ? 1.0 / std::sqrt(d) : 0.0;
    if (!(d > 0))
      out.directions.push_back(model.parameters()[size_t(j)].name + " (no influence on the data)");
  }
  const Eigen::MatrixXd normalised = scale.asDiagonal() * hessian * scale.asDiagonal();
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(normalised);
  // The normalised matrix has a unit diagonal (0 for parameters without influence); an
  // eigenvalue below this is a combination of columns of J that cancels to a reciprocal
  // condition number below 1e-6.
  constexpr double Threshold = 1e-12;
  for (Eigen::Index k = 0; k < p; ++k) {
    if (eigen.eigenvalues()[k] > Threshold) continue;
    ++out.dimension;
    const Eigen::VectorXd v = eigen.eigenvectors().col(k);
    std::string names;
    for (Eigen::Index j = 0; j < p; ++j)
      if (scale[j] > 0 && std::abs(v[j]) >= 0.1)
        names += (names.empty() ? "" : " + ") + model.parameters()[size_t(j)].name;
    if (!names.empty()) out.directions.push_back(names);
  }
  return out;
}

// The compressed block of fixed normal equations: what ceres::Covariance differentiates, so
// that the covariance costs no second pass over the samples.
class FixedNormalEquations final : public ceres::CostFunction {
 public:
  explicit FixedNormalEquations(const NormalEquations& equations) : equations_(equations) {
    const int p = int(equations.gradient.size());
    set_num_residuals(p + 1);
    mutable_parameter_block_sizes()->push_back(p);
  }
  bool Evaluate(double const* const*, double* residuals, double** jacobians) const override {
    const size_t p = size_t(equations_.gradient.size());
    std::vector<double> jacobian((p + 1) * p);
    compressNormalEquations(equations_, residuals, jacobian.data());
    if (jacobians && jacobians[0]) std::copy(jacobian.begin(), jacobian.end(), jacobians[0]);
    return true;
  }

 private:
  const NormalEquations& equations_;
};

// `equations`: the normal equations at result.x.
void computeCovariance(const FitModel& model, const NormalEquations& equations, FitResult& result) {
  const size_t p = model.parameterCount();
  std::vector<double> x = result.x;
  const NullSpace nullSpace = nullSpaceOf(equations.hessian, model);
  result.unidentified = nullSpace.directions;
  result.rankDeficient = nullSpace.dimension > 0;
  FixedNormalEquations cost(equations);
  ceres::Problem::Options problemOptions;
  problemOptions.cost_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  ceres::Problem ceresProblem(problemOptions);
  ceresProblem.AddResidualBlock(&cost, nullptr, x.data());
  ceres::Covariance::Options covarianceOptions;
  covarianceOptions.algorithm_type = ceres::DENSE_SVD;
  // Rank deficient: the pseudo-inverse, without the null space's smallest singular values.
  covarianceOptions.null_space_rank = nullSpace.dimension;
  covarianceOptions.num_threads = 1;
  ceres::Covariance covariance(covarianceOptions);
  const std::vector<std::pair<const double*, const double*>> blocks{{x.data(), x.data()}};
  result.covarianceAvailable = covariance.Compute(blocks, &ceresProblem);
  result.covariance = Eigen::MatrixXd();
  if (!result.covarianceAvailable) return;
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> c(p, p);
  covariance.GetCovarianceBlock(x.data(), x.data(), c.data());
  result.covariance = c * result.sigma2;
}

}  // namespace

FitResult fitBrdf(const FitModel& model, const BrdfSamples& samples, const FitOptions& options) {
  if (samples.empty()) throw std::invalid_argument("no valid samples to fit");
  quietCeresLogging();
  const auto begin = std::chrono::steady_clock::now();
  FitResult result;
  const size_t p = model.parameterCount();
  result.samples = samples.size();
  result.observations = 3 * samples.size();
  const auto report = [&](const std::string& stage, double fraction) {
    if (options.progress) options.progress(stage, fraction);
  };

  // 1. Grid.
  report("grid", 0.0);
  const BrdfSamples gridSet = stratifiedSubset(samples, options.gridSamples, options.seed);
  result.gridSamples = gridSet.size();
  const GridSearch search = searchGrid(model, gridSet, options.metric, options.gridBudget, options.threads);
  result.gridPoints = search.points.size() + search.nonFinitePoints;
  result.gridNonFinitePoints = search.nonFinitePoints;
  const std::vector<GridPoint> starts = distinctStarts(search, std::max(options.starts, 1));
  if (starts.empty())
    throw std::runtime_error("fit: none of the " + std::to_string(result.gridPoints) +
                             " points of the initial grid has a finite cost: the model's values are not "
                             "finite on the data");

  // 2. Multi-start on a subset.
  const BrdfSamples startSet = stratifiedSubset(samples, options.startSamples, options.seed);
  result.startSamples = startSet.size();
  const MetricSamples startMetric(startSet, options.metric);
  std::unique_ptr<ceres::LossFunction> loss;
  if (options.robust != RobustLoss::None) {
    double scale = options.robustScale.value_or(0.0);
    if (!options.robustScale) {
      const BrdfLeastSquares plain(model, startMetric, nullptr, options.threads);
      std::vector<double> r;
      plain.residuals(starts.front().x.data(), 0, startSet.size(), r, nullptr);
      for (double& v : r) v = std::abs(v);
      std::nth_element(r.begin(), r.begin() + std::ptrdiff_t(r.size() / 2), r.end());
      scale = 2.5 * 1.4826 * r[r.size() / 2];
      if (!(scale > 0)) scale = 1e-12;
    }
    result.robustScale = scale;
    loss = makeLossFunction(options.robust, scale);
  }
  const BrdfLeastSquares startProblem(model, startMetric, loss.get(), options.threads);
  for (size_t s = 0; s < starts.size(); ++s) {
    const std::string stage = "start " + std::to_string(s + 1) + "/" + std::to_string(starts.size());
    result.starts.push_back(solve(startProblem, starts[s].x, options, stage));
  }
  result.nonFiniteStarts =
      size_t(std::count_if(result.starts.begin(), result.starts.end(),
                           [](const SolveSummary& s) { return !std::isfinite(s.finalCost); }));
  const auto best =
      std::min_element(result.starts.begin(), result.starts.end(), [](const auto& a, const auto& b) {
        const double ca = std::isfinite(a.finalCost) ? a.finalCost : std::numeric_limits<double>::infinity();
        const double cb = std::isfinite(b.finalCost) ? b.finalCost : std::numeric_limits<double>::infinity();
        return ca < cb;
      });

  // 3. Refinement on every sample.
  const MetricSamples allMetric(samples, options.metric);
  const BrdfLeastSquares problem(model, allMetric, loss.get(), options.threads);
  NormalEquations equations;
  if (startSet.size() == samples.size()) {
    result.final = *best;
    equations = problem.normalEquations(best->final.data());
  } else {
    result.final = solve(problem, best->final, options, "refine", &equations);
  }
  result.x = result.final.final;

  // 4. Errors and error bars.
  report("covariance", 1.0);
  const BrdfLeastSquares::ChannelSums sums = problem.channelSums(result.x.data());
  for (int c = 0; c < 3; ++c) {
    result.rms[c] = std::sqrt(sums.squaredError[c] / std::max(sums.weight, 1e-300));
    result.relativeError[c] = std::sqrt(sums.squaredError[c] / std::max(sums.squaredData[c], 1e-300));
  }
  // Residuals that are not finite at the result fail the fit (brdf_fit.h): no cost, no error
  // bars (the normal equations hold NaN), and the verdict says why.
  result.finiteResiduals = std::isfinite(result.final.finalCost) && std::isfinite(sums.squaredError[0]) &&
                           std::isfinite(sums.squaredError[1]) && std::isfinite(sums.squaredError[2]);
  const double dof = double(result.observations) - double(p);
  result.sigma2 = dof > 0 && result.finiteResiduals ? result.final.finalCost / dof
                                                    : std::numeric_limits<double>::quiet_NaN();
  if (result.finiteResiduals) computeCovariance(model, equations, result);
  for (size_t j = 0; j < p; ++j) {
    const FitParameter& fp = model.parameters()[j];
    ParameterEstimate e;
    e.name = fp.name;
    e.value = result.x[j];
    e.lower = fp.lower;
    e.upper = fp.upper;
    const double tolerance = 1e-9 * std::max(1.0, std::min(fp.upper - fp.lower, 1e9));
    e.atBound = result.x[j] - fp.lower <= tolerance || fp.upper - result.x[j] <= tolerance;
    e.standardDeviation = result.covarianceAvailable
                              ? std::sqrt(std::max(0.0, result.covariance(Eigen::Index(j), Eigen::Index(j))))
                              : std::numeric_limits<double>::quiet_NaN();
    result.parameters.push_back(e);
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
  return result;
}

namespace {

json numberOrNull(double x) { return std::isfinite(x) ? json(x) : json(); }

json summaryJson(const SolveSummary& s, const FitModel& model) {
  json initial = json::object(), final = json::object();
  for (size_t j = 0; j < model.parameterCount(); ++j) {
    initial[model.parameters()[j].name] = s.initial[j];
    final[model.parameters()[j].name] = s.final[j];
  }
  return {{"initial_cost", numberOrNull(s.initialCost)},
          {"final_cost", numberOrNull(s.finalCost)},
          {"iterations", s.iterations},
          {"termination", s.termination},
          {"message", s.message},
          {"initial", initial},
          {"final", final}};
}

}  // namespace

nlohmann::json toJson(const FitResult& result, const FitModel& model, const FitOptions& options) {
  json parameters = json::array();
  for (const ParameterEstimate& e : result.parameters)
    parameters.push_back({{"name", e.name},
                          {"value", e.value},
                          {"std_dev", numberOrNull(e.standardDeviation)},
                          {"lower", e.lower},
                          {"upper", e.upper},
                          {"at_bound", e.atBound}});
  json starts = json::array();
  for (const SolveSummary& s : result.starts) starts.push_back(summaryJson(s, model));
  return {{"metric", toString(options.metric)},
          {"robust", toString(options.robust)},
          {"robust_scale", result.robustScale},
          {"parameters", parameters},
          {"cost", numberOrNull(result.final.finalCost)},
          {"iterations", result.final.iterations},
          {"termination", result.final.termination},
          {"message", result.final.message},
          {"converged", result.final.converged},
          {"rms", {result.rms.x, result.rms.y, result.rms.z}},
          {"relative_error", {result.relativeError.x, result.relativeError.y, result.relativeError.z}},
          {"samples", result.samples},
          {"observations", result.observations},
          {"parameter_count", model.parameterCount()},
          {"sigma2", numberOrNull(result.sigma2)},
          {"covariance_available", result.covarianceAvailable},
          {"rank_deficient", result.rankDeficient},
          {"unidentified", result.unidentified},
          {"finite_residuals", result.finiteResiduals},
          {"grid",
           {{"points", result.gridPoints},
            {"samples", result.gridSamples},
            {"non_finite_points", result.gridNonFinitePoints}}},
          {"starts", starts},
          {"non_finite_starts", result.nonFiniteStarts},
          {"start_samples", result.startSamples},
          {"seconds", result.seconds}};
}

}  // namespace scatterlab::fitting
