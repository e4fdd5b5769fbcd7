// The error metrics (docs/references.md, "Ngan et al. 2005 models and fitting metrics"): each residual
// against the formula written out, the merged orderings of the linear metrics, and the names.
#include <gtest/gtest.h>

#include "fitting/least_squares.h"
#include "fitting_test_support.h"

namespace scatterlab::fitting::test {
namespace metric_test {

// One sample: wi at 30 degrees, wo at 60 degrees, f = (0.5, 1, 2), sampling weight 2.
BrdfSamples oneSample() {
  BrdfSamples s;
  s.add(directionFromDegrees(30, 0), directionFromDegrees(60, 180), Rgb(0.5, 1.0, 2.0), 2.0, 0);
  return s;
}

// The model lambertian with albedo x, so m = x / pi per channel.
double metricSum(Metric metric, double albedo) {
  const BrdfSamples samples = oneSample();
  const MetricSamples prepared(samples, metric);
  const FitModel model(parseModelSpec("lambertian"), false);
  const BrdfLeastSquares problem(model, prepared, nullptr, 1);
  const std::vector<double> x(3, albedo);
  return problem.cost(x.data());
}

// The same sum written out from docs/references.md, "Ngan et al. 2005 models and fitting metrics",
// over both orderings of the pair, weight 1/2 each.
double expectedSum(Metric metric, double albedo) {
  const double ci = std::cos(radians(30.0)), co = std::cos(radians(60.0));
  const double si = std::sin(radians(30.0)), so = std::sin(radians(60.0));
  const double m = albedo / Pi;
  double sum = 0;
  for (const double f : {0.5, 1.0, 2.0}) {
    for (int o = 0; o < 2; ++o) {
      const double cIn = o == 0 ? ci : co, sIn = o == 0 ? si : so, sOut = o == 0 ? so : si;
      double term = 0;
      switch (metric) {
        case Metric::L2: term = sqr(f - m); break;
        case Metric::Ngan: term = sqr((f - m) * cIn) * sIn * sOut; break;
        case Metric::LowL2: term = sqr((f - m) * cIn) * sIn; break;
        case Metric::LowLog: term = sqr(std::log(1 + f * cIn) - std::log(1 + m * cIn)) * sIn; break;
        case Metric::CubeRoot:
          term = sqr(std::cbrt(f * cIn + CubeRootOffset) - std::cbrt(m * cIn + CubeRootOffset)) * sIn * sOut;
          break;
      }
      sum += 0.5 * 2.0 * term;  // ordering weight 1/2, sampling weight 2
    }
  }
  return sum;
}

TEST(Metric, EveryResidualIsTheFormulaOverBothOrderings) {
  for (const std::string& name : metricNames()) {
    const Metric metric = *parseMetric(name);
    for (const double albedo : {0.0, 0.3, 0.9})
      EXPECT_NEAR(metricSum(metric, albedo), expectedSum(metric, albedo), 1e-13 * expectedSum(metric, albedo))
          << name << " albedo " << albedo;
  }
}

TEST(Metric, LinearMetricsMergeTheirOrderings) {
  const BrdfSamples samples = oneSample();
  EXPECT_EQ(MetricSamples(samples, Metric::Ngan).orderings(), 1);
  EXPECT_EQ(MetricSamples(samples, Metric::LowL2).orderings(), 1);
  EXPECT_EQ(MetricSamples(samples, Metric::L2).orderings(), 1);
  EXPECT_EQ(MetricSamples(samples, Metric::LowLog).orderings(), 2);
  EXPECT_EQ(MetricSamples(samples, Metric::CubeRoot).orderings(), 2);
  EXPECT_EQ(linearAnalogue(Metric::LowLog), Metric::LowL2);
  EXPECT_EQ(linearAnalogue(Metric::CubeRoot), Metric::Ngan);
}

TEST(Metric, SlopeIsTheDerivativeOfTheTransform) {
  for (const std::string& name : metricNames()) {
    const Metric metric = *parseMetric(name);
    for (const double f : {1e-3, 0.2, 5.0}) {
      const double h = 1e-6 * f;
      const double numeric =
          (metricTransform(metric, f + h, 0.7) - metricTransform(metric, f - h, 0.7)) / (2 * h);
      EXPECT_NEAR(metricSlope(metric, f, 0.7), numeric, 1e-7 * std::abs(numeric) + 1e-12)
          << name << " f " << f;
    }
  }
}

TEST(Metric, NamesRoundTripAndUnknownNamesAreRejected) {
  for (const std::string& name : metricNames()) EXPECT_EQ(toString(*parseMetric(name)), name);
  for (const std::string& name : robustLossNames()) EXPECT_EQ(toString(*parseRobustLoss(name)), name);
  EXPECT_FALSE(parseMetric("l1"));
  EXPECT_FALSE(parseRobustLoss("tukey"));
  EXPECT_EQ(makeLossFunction(RobustLoss::None, 1.0), nullptr);
  // Ceres's losses are quadratic near 0: rho(s) ~ s.
  for (const RobustLoss loss : {RobustLoss::Huber, RobustLoss::Cauchy, RobustLoss::SoftL1}) {
    double rho[3];
    makeLossFunction(loss, 2.0)->Evaluate(1e-8, rho);
    EXPECT_NEAR(rho[0], 1e-8, 1e-15) << toString(loss);
    EXPECT_NEAR(rho[1], 1.0, 1e-8) << toString(loss);
  }
}

}  // namespace metric_test
}  // namespace scatterlab::fitting::test
