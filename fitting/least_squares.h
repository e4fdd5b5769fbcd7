// The least-squares problem of a BRDF fit, shaped for millions of residuals and few
// parameters.
//
// Residuals: per sample, channel and metric ordering (metric.h),
//   r = sqrt(w) (g(f) - g(m(x))),   dr/dx = -sqrt(w) g'(m) dm/dx,
// with dm/dx from the model's kernels in ceres::Jet (fit_model.h). With a robust loss rho
// each residual and its row are scaled by sqrt(rho'(r^2)), as Ceres's own Corrector does for
// the robust losses (all of which have rho'' <= 0: Ceres's alpha = 0 case), and the cost is
// sum rho(r^2).
//
// Compression. For p parameters only H = J^T J (p x p), the gradient g = J^T r and the cost
// S = sum rho enter Levenberg-Marquardt's step, its model of the cost, Jacobi scaling and the
// covariance. So Ceres is given ONE residual block of p + 1 residuals,
//   f = [Lambda^(-1/2) V^T D^(-1/2) g ; e],  J_f = [Lambda^(1/2) V^T D^(1/2) ; 0],
//   D^(-1/2) H D^(-1/2) = V Lambda V^T (D = diag H),  e = sqrt(S - |f_(1..p)|^2),
// for which J_f^T J_f = H, J_f^T f = g and |f|^2 = S exactly (e^2 >= 0 since the unscaled
// part of S, sum (rho(s) - rho'(s) s), is >= 0 for concave rho with rho(0) = 0). The
// column normalisation keeps the rank test free of the parameters' units; directions with
// Lambda ~ 0 (rank deficiency) get f = 0: g has no component along them. When
// Ceres asks for the cost alone, f = [0, ..., 0, sqrt(S)] and no derivatives are computed.
//
// Work: the samples are cut into fixed chunks of ChunkSize; chunks are evaluated in parallel
// (TBB) and their sums (H, g, S) added in chunk order, so every number is the same for any
// thread count.
#pragma once

#include <cstddef>
#include <vector>

#include <ceres/cost_function.h>
#include <ceres/loss_function.h>
#include <Eigen/Dense>

#include "fitting/brdf_samples.h"
#include "fitting/fit_model.h"
#include "fitting/metric.h"

namespace scatterlab::fitting {

// Samples prepared for one metric: per sample and ordering, the transformed data g(f), the
// incident cosine and sqrt of the weight (sampling weight times metric weight). For linear
// metrics the orderings are merged into one residual on f itself (metric.h).
class MetricSamples {
 public:
  MetricSamples(const BrdfSamples& samples, Metric metric);

  const BrdfSamples& samples() const { return *samples_; }
  Metric metric() const { return metric_; }
  // The transform applied to the model value: the metric's own, or l2 for merged metrics.
  Metric evaluationMetric() const { return evaluationMetric_; }
  size_t size() const { return samples_->size(); }
  int orderings() const { return orderings_; }
  // Observations: samples x channels (the two orderings of a sample are one observation).
  size_t observations() const { return 3 * size(); }

  double sqrtWeight(size_t i, int o) const { return sqrtWeight_[i * size_t(orderings_) + size_t(o)]; }
  double cosIn(size_t i, int o) const { return cosIn_[i * size_t(orderings_) + size_t(o)]; }
  double target(size_t i, int o, int c) const {
    return target_[(i * size_t(orderings_) + size_t(o)) * 3 + size_t(c)];
  }

 private:
  const BrdfSamples* samples_;
  Metric metric_, evaluationMetric_;
  int orderings_ = 1;
  std::vector<double> sqrtWeight_, cosIn_, target_;
};

// The sums one evaluation of the problem gives.
struct NormalEquations {
  Eigen::MatrixXd hessian;   // J~^T J~ (p x p)
  Eigen::VectorXd gradient;  // J~^T r~ (the gradient of S / 2)
  double cost = 0;           // S = sum rho(r^2)
};

class BrdfLeastSquares {
 public:
  static constexpr size_t ChunkSize = 1024;

  // `loss` may be null (plain least squares); `threads` 0 means all cores. The model, the
  // samples and the loss must outlive this object.
  BrdfLeastSquares(const FitModel& model, const MetricSamples& samples, const ceres::LossFunction* loss,
                   int threads);

  const FitModel& model() const { return *model_; }
  const MetricSamples& samples() const { return *samples_; }
  size_t parameterCount() const { return model_->parameterCount(); }

  // S at x (no derivatives).
  double cost(const double* x) const;
  NormalEquations normalEquations(const double* x) const;

  // The raw residuals (without the robust loss) of samples [begin, end) and, if jacobian is
  // not null, their rows: what the gradient checks compare with numeric derivatives.
  void residuals(const double* x, size_t begin, size_t end, std::vector<double>& r,
                 Eigen::MatrixXd* jacobian) const;

  // Per channel, sum w (g(f) - g(m))^2, sum w g(f)^2 and sum w over every sample and
  // ordering (no robust loss): the RMS and relative errors a fit reports.
  struct ChannelSums {
    Rgb squaredError{0.0}, squaredData{0.0};
    double weight = 0;
  };
  ChannelSums channelSums(const double* x) const;

 private:
  template <typename ChunkResult, typename Evaluate>
  std::vector<ChunkResult> forEachChunk(Evaluate&& evaluate) const;

  const FitModel* model_;
  const MetricSamples* samples_;
  const ceres::LossFunction* loss_;
  int threads_;
};

// The compressed residual block Ceres sees (header comment): p + 1 residuals, one parameter
// block of size p. It keeps the normal equations of its last evaluation with derivatives:
// Ceres's last one is at the accepted solution, so the gradient and J^T J there (for the
// active bounds and the covariance) come without another pass over the samples.
class CompressedCostFunction final : public ceres::CostFunction {
 public:
  explicit CompressedCostFunction(const BrdfLeastSquares& problem);
  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override;

  // The normal equations at x: the kept ones if they were evaluated at exactly x.
  NormalEquations normalEquationsAt(const std::vector<double>& x) const;

 private:
  const BrdfLeastSquares* problem_;
  mutable std::vector<double> lastX_;
  mutable NormalEquations last_;
};

// The compressed form of (H, g, S): residual f (p + 1) and row-major Jacobian J_f
// ((p + 1) x p).
void compressNormalEquations(const NormalEquations& equations, double* residuals, double* jacobian);

}  // namespace scatterlab::fitting
