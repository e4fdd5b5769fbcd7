// The least-squares problem: the hand-assembled residual rows (scales, tied and per-channel
// shapes, metric transforms) against numeric derivatives, the compressed block against the
// full problem, and independence from the thread count.
#include <gtest/gtest.h>

#include <ceres/dynamic_cost_function.h>
#include <ceres/gradient_checker.h>
#include <ceres/manifold.h>

#include "fitting/least_squares.h"
#include "fitting_test_support.h"

namespace scatterlab::fitting::test {
namespace least_squares_test {

// The raw residuals of a few samples as a Ceres cost function, for the gradient checker. As in
// kernel_gradient_test.cpp, positive parameters enter as their logarithms (x = exp(u), so
// dr/du = x dr/dx), which keeps Ridders' numeric steps relative to them.
class SampleResiduals final : public ceres::DynamicCostFunction {
 public:
  SampleResiduals(const BrdfLeastSquares& problem, size_t begin, size_t end, std::vector<double>& x)
      : problem_(problem), begin_(begin), end_(end), logarithm_(x.size()) {
    AddParameterBlock(int(problem.parameterCount()));
    SetNumResiduals(int((end - begin) * 3 * size_t(problem.samples().orderings())));
    for (size_t k = 0; k < x.size(); ++k) {
      logarithm_[k] = x[k] > 0;
      if (logarithm_[k]) x[k] = std::log(x[k]);
    }
  }
  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
    std::vector<double> x(parameters[0], parameters[0] + logarithm_.size());
    for (size_t k = 0; k < x.size(); ++k)
      if (logarithm_[k]) x[k] = std::exp(x[k]);
    std::vector<double> r;
    Eigen::MatrixXd j;
    problem_.residuals(x.data(), begin_, end_, r, jacobians && jacobians[0] ? &j : nullptr);
    std::copy(r.begin(), r.end(), residuals);
    if (jacobians && jacobians[0])
      for (Eigen::Index row = 0; row < j.rows(); ++row)
        for (Eigen::Index col = 0; col < j.cols(); ++col)
          jacobians[0][row * j.cols() + col] = j(row, col) * (logarithm_[size_t(col)] ? x[size_t(col)] : 1.0);
    return true;
  }

 private:
  const BrdfLeastSquares& problem_;
  size_t begin_, end_;
  std::vector<bool> logarithm_;
};

// Parameters inside their bounds and away from the starts, so every derivative is exercised.
std::vector<double> probePoint(const FitModel& model) {
  std::vector<double> x = model.startValues();
  for (size_t j = 0; j < x.size(); ++j) {
    const FitParameter& p = model.parameters()[j];
    const double span = std::min(p.upper, 1e4) - p.lower;
    x[j] = p.lower + (0.3 + 0.05 * double(j % 7)) * span;
    if (p.key == "roughness" || p.key == "alpha") x[j] = 0.05 + 0.01 * double(j % 5);
  }
  return x;
}

void expectRowsMatchNumericDerivatives(const std::string& spec, bool perChannel, Metric metric, int lobes = 1,
                                       double tolerance = 1e-4) {
  const FitModel model(parseModelSpec(spec, lobes), perChannel);
  const BrdfSamples samples =
      cellSamples(GroundTruth(publishedFit("gold-metallic-paint", "ngan_cooktorrance.fit")), 1);
  const MetricSamples prepared(samples, metric);
  const BrdfLeastSquares problem(model, prepared, nullptr, 1);
  // Samples spread over the table: the first theta_h rows (highlight) and the rest.
  for (const size_t begin : {size_t(0), size_t(40), samples.size() / 2, samples.size() - 30}) {
    std::vector<double> x = probePoint(model);
    SampleResiduals cost(problem, begin, begin + 20, x);
    ceres::NumericDiffOptions numeric;  // Ridders from a relative step of 1e-3 (kernel_gradient_test.cpp)
    numeric.ridders_relative_initial_step_size = 1e-3;
    const ceres::GradientChecker checker(
        &cost, static_cast<const std::vector<const ceres::Manifold*>*>(nullptr), numeric);
    ceres::GradientChecker::ProbeResults results;
    double* blocks[] = {x.data()};
    // 1e-4: a row mixes O(1) derivatives with a lobe's tail whose derivatives are 1e-10 of the
    // residual, which numeric differences resolve only to ~eps |r| / (h |dr/dx|) ~ 1e-5
    // relative; a wrong chain-rule factor is still an O(1) error.
    EXPECT_TRUE(checker.Probe(blocks, tolerance, &results))
        << spec << (perChannel ? " per channel" : "") << ", metric " << toString(metric) << ", samples from "
        << begin << ": " << results.error_log;
  }
}

TEST(ResidualRows, MatchNumericDerivativesForEveryMetric) {
  for (const std::string& metric : metricNames())
    expectRowsMatchNumericDerivatives("lambertian+ngan-cook-torrance", false, *parseMetric(metric));
}

TEST(ResidualRows, MatchWithPerChannelTiedAndRepeatedShapes) {
  expectRowsMatchNumericDerivatives("lambertian+ngan-cook-torrance", true, Metric::LowLog);
  expectRowsMatchNumericDerivatives("lafortune", false, Metric::Ngan);  // cy tied to cx
  expectRowsMatchNumericDerivatives(R"({"type":"blinn-phong","kd":0.1})", true, Metric::CubeRoot);  // kd held
  expectRowsMatchNumericDerivatives(std::string("lambertian+") + WhiteConductorSpec, false, Metric::LowL2,
                                    2);  // two lobes
  // A fitted index (f0 and edge tint per channel: three-slot shapes, one parameter each). The
  // edge tint moves the Fresnel factor near grazing only, so in some rows its derivative is
  // 1e-10 of the residual, which numeric differences resolve to eps |r| / (h |dr/dx|) ~ 1e-3
  // relative; a miswired parameter is still an O(1) error.
  expectRowsMatchNumericDerivatives("conductor", false, Metric::Ngan, 1, 2e-3);
}

// The compressed block reproduces the full problem's cost, gradient and J^T J.
TEST(CompressedBlock, ReproducesCostGradientAndGaussNewtonMatrix) {
  const FitModel model(parseModelSpec("lambertian+ngan-cook-torrance"), false);
  const BrdfSamples samples = cellSamples(GroundTruth(publishedFit("nickel", "ngan_cooktorrance.fit")), 1);
  for (const bool robust : {false, true}) {
    const MetricSamples prepared(samples, Metric::LowLog);
    const auto loss = robust ? makeLossFunction(RobustLoss::Cauchy, 0.01) : nullptr;
    const BrdfLeastSquares problem(model, prepared, loss.get(), 2);
    const std::vector<double> x = probePoint(model);
    const size_t p = model.parameterCount();

    // The full problem, sample by sample, with the robust loss applied as Ceres does.
    std::vector<double> r;
    Eigen::MatrixXd j;
    problem.residuals(x.data(), 0, samples.size(), r, &j);
    double cost = 0;
    for (size_t k = 0; k < r.size(); ++k) {
      double rho[3] = {r[k] * r[k], 1.0, 0.0};
      if (loss) loss->Evaluate(r[k] * r[k], rho);
      cost += rho[0];
      j.row(Eigen::Index(k)) *= std::sqrt(rho[1]);
      r[k] *= std::sqrt(rho[1]);
    }
    const Eigen::VectorXd residual = Eigen::Map<const Eigen::VectorXd>(r.data(), Eigen::Index(r.size()));
    const Eigen::VectorXd gradient = j.transpose() * residual;
    const Eigen::MatrixXd hessian = j.transpose() * j;

    CompressedCostFunction compressed(problem);
    std::vector<double> f(p + 1), jf((p + 1) * p);
    const double* parameters[] = {x.data()};
    double* jacobians[] = {jf.data()};
    ASSERT_TRUE(compressed.Evaluate(parameters, f.data(), jacobians));
    const Eigen::Map<const Eigen::VectorXd> fv(f.data(), Eigen::Index(p + 1));
    const Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> jm(
        jf.data(), Eigen::Index(p + 1), Eigen::Index(p));
    // Sums of ~1e5 terms in another order: agreement to ~1e-12 relative.
    EXPECT_NEAR(fv.squaredNorm(), cost, 1e-10 * cost) << "robust " << robust;
    EXPECT_LE((jm.transpose() * fv - gradient).norm(), 1e-9 * gradient.norm()) << "robust " << robust;
    EXPECT_LE((jm.transpose() * jm - hessian).norm(), 1e-9 * hessian.norm()) << "robust " << robust;

    // Without Jacobians: only the cost, in the last residual.
    std::vector<double> costOnly(p + 1);
    ASSERT_TRUE(compressed.Evaluate(parameters, costOnly.data(), nullptr));
    EXPECT_NEAR(costOnly[p] * costOnly[p], cost, 1e-10 * cost);
    for (size_t k = 0; k < p; ++k) EXPECT_EQ(costOnly[k], 0.0);
  }
}

// A rank-deficient J^T J: directions without curvature get no residual, and the gradient is
// still reproduced.
TEST(CompressedBlock, HandlesRankDeficientNormalEquations) {
  NormalEquations equations;
  Eigen::MatrixXd j(4, 3);
  j << 1, 2, 3, 2, 4, 6, 0, 1, 1, 1, 0, 1;  // column 3 = column 1 + column 2
  const Eigen::Vector4d r(0.5, -1.0, 2.0, 0.25);
  equations.hessian = j.transpose() * j;
  equations.gradient = j.transpose() * r;
  equations.cost = r.squaredNorm();
  std::vector<double> f(4), jf(12);
  compressNormalEquations(equations, f.data(), jf.data());
  const Eigen::Map<const Eigen::Vector4d> fv(f.data());
  const Eigen::Map<const Eigen::Matrix<double, 4, 3, Eigen::RowMajor>> jm(jf.data());
  EXPECT_NEAR(fv.squaredNorm(), equations.cost, 1e-12);
  EXPECT_LE((jm.transpose() * fv - equations.gradient).norm(), 1e-12);
  EXPECT_LE((jm.transpose() * jm - equations.hessian).norm(), 1e-11);
}

TEST(BrdfLeastSquares, SameBitsForAnyThreadCount) {
  const FitModel model(parseModelSpec(std::string("lambertian+") + WhiteConductorSpec), false);
  const BrdfSamples samples = cellSamples(GroundTruth(publishedFit("chrome", "ngan_cooktorrance.fit")), 1);
  const MetricSamples prepared(samples, Metric::Ngan);
  const std::vector<double> x = probePoint(model);
  const BrdfLeastSquares one(model, prepared, nullptr, 1), two(model, prepared, nullptr, 2);
  EXPECT_EQ(one.cost(x.data()), two.cost(x.data()));
  const NormalEquations a = one.normalEquations(x.data()), b = two.normalEquations(x.data());
  EXPECT_EQ(a.cost, b.cost);
  EXPECT_TRUE(a.hessian == b.hessian);
  EXPECT_TRUE(a.gradient == b.gradient);
  // The cost-only path evaluates the kernels in double, the derivative path in Jets, whose
  // value parts round a division differently (f * (1/g)): equal to round-off.
  EXPECT_NEAR(one.cost(x.data()), a.cost, 1e-13 * a.cost);
}

}  // namespace least_squares_test
}  // namespace scatterlab::fitting::test
