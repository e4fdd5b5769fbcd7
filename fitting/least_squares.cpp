#include "fitting/least_squares.h"

#include <algorithm>
#include <cmath>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

namespace scatterlab::fitting {

namespace {

double sinOf(const Vec3d& w) { return std::sqrt(std::max(0.0, w.x * w.x + w.y * w.y)); }

// Residuals of sample i, r[o * 3 + c], and with Derivatives their rows (rows[k * p + j]),
// raw, before the robust loss. `modelRows` is scratch of 3 p. Returns the residual count.
template <bool Derivatives> int sampleResiduals(const FitModel& model, const MetricSamples& samples, size_t i,
                                                const double* x, double* r, double* rows, double* modelRows) {
  const BrdfSamples& s = samples.samples();
  const size_t p = model.parameterCount();
  double m[3];
  model.evaluate<Derivatives>(x, s.wi[i], s.wo[i], m, modelRows);
  const Metric metric = samples.evaluationMetric();
  int k = 0;
  for (int o = 0; o < samples.orderings(); ++o) {
    const double sqrtW = samples.sqrtWeight(i, o), cosIn = samples.cosIn(i, o);
    for (int c = 0; c < 3; ++c, ++k) {
      r[k] = sqrtW * (samples.target(i, o, c) - metricTransform(metric, m[c], cosIn));
      if constexpr (Derivatives) {
        const double factor = -sqrtW * metricSlope(metric, m[c], cosIn);
        const double* from = modelRows + size_t(c) * p;
        double* to = rows + size_t(k) * p;
        for (size_t j = 0; j < p; ++j) to[j] = factor * from[j];
      }
    }
  }
  return k;
}

// rho(s) and sqrt(rho'(s)); the identity without a loss.
struct Robust {
  double value, sqrtSlope;
};
Robust robust(const ceres::LossFunction* loss, double s) {
  if (!loss) return {s, 1.0};
  double rho[3];
  loss->Evaluate(s, rho);
  return {rho[0], std::sqrt(std::max(rho[1], 0.0))};
}

}  // namespace

MetricSamples::MetricSamples(const BrdfSamples& samples, Metric metric)
    : samples_(&samples),
      metric_(metric),
      evaluationMetric_(isLinear(metric) ? Metric::L2 : metric),
      orderings_(isLinear(metric) ? 1 : 2) {
  const size_t n = samples.size();
  sqrtWeight_.resize(n * size_t(orderings_));
  cosIn_.resize(n * size_t(orderings_));
  target_.resize(n * size_t(orderings_) * 3);
  for (size_t i = 0; i < n; ++i) {
    const Vec3d& wi = samples.wi[i];
    const Vec3d& wo = samples.wo[i];
    const double sinI = sinOf(wi), sinO = sinOf(wo);
    const double cosines[2] = {wi.z, wo.z};
    const double weights[2] = {metricWeight(metric, sinI, sinO), metricWeight(metric, sinO, sinI)};
    if (orderings_ == 1) {
      // g linear: the mean over both orderings of w (c f - c m)^2 is W (f - m)^2.
      const double gain2[2] = {metricTransform(metric, 1.0, cosines[0]),
                               metricTransform(metric, 1.0, cosines[1])};
      const double merged = 0.5 * (weights[0] * gain2[0] * gain2[0] + weights[1] * gain2[1] * gain2[1]);
      sqrtWeight_[i] = std::sqrt(samples.weight[i] * merged);
      cosIn_[i] = 1.0;
      for (int c = 0; c < 3; ++c) target_[i * 3 + size_t(c)] = samples.value[i][c];
      continue;
    }
    for (int o = 0; o < 2; ++o) {
      const size_t k = i * 2 + size_t(o);
      sqrtWeight_[k] = std::sqrt(0.5 * samples.weight[i] * weights[o]);
      cosIn_[k] = cosines[o];
      for (int c = 0; c < 3; ++c)
        target_[k * 3 + size_t(c)] = metricTransform(metric, samples.value[i][c], cosines[o]);
    }
  }
}

BrdfLeastSquares::BrdfLeastSquares(const FitModel& model, const MetricSamples& samples,
                                   const ceres::LossFunction* loss, int threads)
    : model_(&model), samples_(&samples), loss_(loss), threads_(threads) {}

template <typename ChunkResult, typename Evaluate>
std::vector<ChunkResult> BrdfLeastSquares::forEachChunk(Evaluate&& evaluate) const {
  const size_t n = samples_->size();
  const size_t chunks = (n + ChunkSize - 1) / ChunkSize;
  std::vector<ChunkResult> results(chunks);
  tbb::task_arena arena(threads_ > 0 ? threads_ : tbb::task_arena::automatic);
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<size_t>(0, chunks, 1), [&](const tbb::blocked_range<size_t>& range) {
      for (size_t chunk = range.begin(); chunk != range.end(); ++chunk)
        results[chunk] = evaluate(chunk * ChunkSize, std::min(n, (chunk + 1) * ChunkSize));
    });
  });
  return results;
}

double BrdfLeastSquares::cost(const double* x) const {
  const std::vector<double> sums = forEachChunk<double>([&](size_t begin, size_t end) {
    double r[6];
    double sum = 0;
    for (size_t i = begin; i < end; ++i) {
      const int count = sampleResiduals<false>(*model_, *samples_, i, x, r, nullptr, nullptr);
      for (int k = 0; k < count; ++k) sum += robust(loss_, r[k] * r[k]).value;
    }
    return sum;
  });
  double total = 0;
  for (const double s : sums) total += s;
  return total;
}

NormalEquations BrdfLeastSquares::normalEquations(const double* x) const {
  const size_t p = parameterCount();
  const int perSample = 3 * samples_->orderings();
  const std::vector<NormalEquations> parts = forEachChunk<NormalEquations>([&](size_t begin, size_t end) {
    const size_t rowsMax = (end - begin) * size_t(perSample);
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> jacobian(rowsMax, p);
    Eigen::VectorXd residual(rowsMax);
    std::vector<double> modelRows(3 * p);
    double r[6];
    NormalEquations part;
    size_t row = 0;
    for (size_t i = begin; i < end; ++i) {
      double* rows = jacobian.data() + row * p;
      const int count = sampleResiduals<true>(*model_, *samples_, i, x, r, rows, modelRows.data());
      for (int k = 0; k < count; ++k, ++row) {
        const Robust rho = robust(loss_, r[k] * r[k]);
        part.cost += rho.value;
        residual[Eigen::Index(row)] = rho.sqrtSlope * r[k];
        if (rho.sqrtSlope != 1.0) jacobian.row(Eigen::Index(row)) *= rho.sqrtSlope;
      }
    }
    part.hessian = Eigen::MatrixXd::Zero(Eigen::Index(p), Eigen::Index(p));
    part.hessian.selfadjointView<Eigen::Lower>().rankUpdate(jacobian.topRows(Eigen::Index(row)).transpose());
    part.gradient = jacobian.topRows(Eigen::Index(row)).transpose() * residual.head(Eigen::Index(row));
    return part;
  });
  NormalEquations total;
  total.hessian = Eigen::MatrixXd::Zero(Eigen::Index(p), Eigen::Index(p));
  total.gradient = Eigen::VectorXd::Zero(Eigen::Index(p));
  for (const NormalEquations& part : parts) {
    total.hessian += part.hessian;
    total.gradient += part.gradient;
    total.cost += part.cost;
  }
  total.hessian = total.hessian.selfadjointView<Eigen::Lower>();
  return total;
}

void BrdfLeastSquares::residuals(const double* x, size_t begin, size_t end, std::vector<double>& r,
                                 Eigen::MatrixXd* jacobian) const {
  const size_t p = parameterCount();
  const int perSample = 3 * samples_->orderings();
  r.assign((end - begin) * size_t(perSample), 0.0);
  std::vector<double> rows(size_t(perSample) * p), modelRows(3 * p);
  if (jacobian) jacobian->setZero(Eigen::Index(r.size()), Eigen::Index(p));
  for (size_t i = begin; i < end; ++i) {
    double* out = r.data() + (i - begin) * size_t(perSample);
    if (!jacobian) {
      sampleResiduals<false>(*model_, *samples_, i, x, out, nullptr, nullptr);
      continue;
    }
    sampleResiduals<true>(*model_, *samples_, i, x, out, rows.data(), modelRows.data());
    for (int k = 0; k < perSample; ++k)
      for (size_t j = 0; j < p; ++j)
        (*jacobian)(Eigen::Index((i - begin) * size_t(perSample) + size_t(k)), Eigen::Index(j)) =
            rows[size_t(k) * p + j];
  }
}

BrdfLeastSquares::ChannelSums BrdfLeastSquares::channelSums(const double* x) const {
  const std::vector<ChannelSums> parts = forEachChunk<ChannelSums>([&](size_t begin, size_t end) {
    ChannelSums sums;
    double r[6];
    for (size_t i = begin; i < end; ++i) {
      sampleResiduals<false>(*model_, *samples_, i, x, r, nullptr, nullptr);
      for (int o = 0; o < samples_->orderings(); ++o) {
        const double w = sqr(samples_->sqrtWeight(i, o));
        sums.weight += w;
        for (int c = 0; c < 3; ++c) {
          sums.squaredError[c] += sqr(r[o * 3 + c]);
          sums.squaredData[c] += w * sqr(samples_->target(i, o, c));
        }
      }
    }
    return sums;
  });
  ChannelSums total;
  for (const ChannelSums& part : parts) {
    total.squaredError += part.squaredError;
    total.squaredData += part.squaredData;
    total.weight += part.weight;
  }
  return total;
}

void compressNormalEquations(const NormalEquations& equations, double* residuals, double* jacobian) {
  const Eigen::Index p = equations.gradient.size();
  // Eigen-decompose the column-normalised matrix D^-1/2 H D^-1/2 = V Lambda V^T (D = diag H),
  // so that the rank test does not depend on the parameters' units (an exponent of 2e4 and an
  // albedo of 0.01 differ by 1e16 in their raw eigenvalues); then
  // J_f = Lambda^1/2 V^T D^1/2 and f = Lambda^-1/2 V^T D^-1/2 g.
  Eigen::VectorXd root(p);
  for (Eigen::Index j = 0; j < p; ++j) {
    const double d = equations.hessian(j, j);
    root[j] = d > 0 ? std::sqrt(d) : 1.0;
  }
  const Eigen::MatrixXd normalised =
      root.cwiseInverse().asDiagonal() * equations.hessian * root.cwiseInverse().asDiagonal();
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(normalised);
  const Eigen::VectorXd& lambda = eigen.eigenvalues();
  const Eigen::MatrixXd& v = eigen.eigenvectors();
  // The normalised matrix has a unit diagonal (its eigenvalues sum to at most p); below this an
  // eigenvalue is round-off of a rank-deficient H.
  const double threshold = 1e-14 * double(p);
  const Eigen::VectorXd projected = v.transpose() * root.cwiseInverse().asDiagonal() * equations.gradient;
  double explained = 0;
  Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> j(jacobian, p + 1, p);
  j.setZero();
  for (Eigen::Index k = 0; k < p; ++k) {
    const double l = lambda[k];
    if (l > threshold) {
      const double sqrtLambda = std::sqrt(l);
      residuals[k] = projected[k] / sqrtLambda;
      explained += residuals[k] * residuals[k];
      j.row(k) = sqrtLambda * v.col(k).transpose() * root.asDiagonal();
    } else {
      residuals[k] = 0.0;
    }
  }
  residuals[p] = std::sqrt(std::max(0.0, equations.cost - explained));
}

CompressedCostFunction::CompressedCostFunction(const BrdfLeastSquares& problem) : problem_(&problem) {
  const int p = int(problem.parameterCount());
  set_num_residuals(p + 1);
  mutable_parameter_block_sizes()->push_back(p);
}

bool CompressedCostFunction::Evaluate(double const* const* parameters, double* residuals,
                                      double** jacobians) const {
  const size_t p = problem_->parameterCount();
  const double* x = parameters[0];
  // Ceres evaluates a point more than once (with bounds, its projected line search asks for
  // the gradient at a candidate, then the cost and the Jacobian again once it is accepted):
  // a repeated point reuses the kept sums.
  const bool repeated = std::equal(x, x + p, lastX_.begin(), lastX_.end());
  if (!jacobians || !jacobians[0]) {
    const double cost = repeated ? last_.cost : problem_->cost(x);
    if (!std::isfinite(cost)) return false;
    std::fill(residuals, residuals + p, 0.0);
    residuals[p] = std::sqrt(cost);
    return true;
  }
  if (!repeated) {
    NormalEquations equations = problem_->normalEquations(x);
    if (!std::isfinite(equations.cost) || !equations.hessian.allFinite() || !equations.gradient.allFinite()) {
      lastX_.clear();
      return false;
    }
    lastX_.assign(x, x + p);
    last_ = std::move(equations);
  }
  compressNormalEquations(last_, residuals, jacobians[0]);
  return true;
}

NormalEquations CompressedCostFunction::normalEquationsAt(const std::vector<double>& x) const {
  if (x == lastX_) return last_;
  NormalEquations equations = problem_->normalEquations(x.data());
  lastX_ = x;
  last_ = equations;
  return equations;
}

}  // namespace scatterlab::fitting
