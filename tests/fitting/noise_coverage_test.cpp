// Error bars: with noise whose variances are the metric's inverse weights (up to one common
// factor, which the fit estimates as sigma^2 = S / (N - p)), the recovered parameters fall
// within the reported covariance at the expected rate over independent seeds.
//
// The test statistic is the Mahalanobis distance d^2 = (x - x_true)^T C^-1 (x - x_true) of
// each seed's fit; if C is right, d^2 ~ chi^2_p, and the sum over S seeds ~ chi^2_(pS). The
// sum must lie in the central 99.9% of that distribution (Wilson-Hilferty quantiles), which
// rejects error bars that are off by a factor 1.5 either way with high probability. The
// per-parameter rates of |x - x_true| <= 1 and 2 standard deviations are checked loosely too
// (68% and 95% expected; the parameters of one fit are correlated, so their counts are
// wider than binomial).
#include <gtest/gtest.h>

#include "fitting/least_squares.h"
#include "fitting_test_support.h"
#include "materials/measured/measurement_synthesis.h"

namespace scatterlab::fitting::test {
namespace noise_coverage_test {

// The chi-square quantile by Wilson & Hilferty 1931: k (1 - 2/(9k) + z sqrt(2/(9k)))^3.
double chiSquareQuantile(double k, double z) {
  return k * std::pow(1.0 - 2.0 / (9.0 * k) + z * std::sqrt(2.0 / (9.0 * k)), 3.0);
}

const std::vector<json>& truth() {
  static const std::vector<json> t{
      json{{"type", "lambertian"}, {"albedo", {0.2, 0.3, 0.4}}},
      json{{"type", "ngan-cook-torrance"}, {"albedo", {0.2, 0.15, 0.1}}, {"eta", 0.4}, {"roughness", 0.15}}};
  return t;
}

struct Coverage {
  double mahalanobis = 0;
  int within1 = 0, within2 = 0, total = 0;
};

// Noise of standard deviation sigma0 / sqrt(relative metric weight): the metric's weights are
// then the inverse variances.
Coverage coverage(Metric metric, double sigma0, int seeds) {
  const FitModel model(parseModelSpec("lambertian+ngan-cook-torrance"), false);
  const BrdfSamples clean = cellSamples(GroundTruth(truth()), 1);
  const MetricSamples weights(clean, metric);
  double meanWeight = 0;
  for (size_t i = 0; i < clean.size(); ++i) meanWeight += sqr(weights.sqrtWeight(i, 0));
  meanWeight /= double(clean.size());
  std::vector<double> expected;
  for (const FitParameter& p : model.parameters()) {
    const json v = truth()[p.component][p.key];
    expected.push_back(v.is_array() ? v[size_t(p.channel)].get<double>() : v.get<double>());
  }
  Coverage out;
  for (int seed = 1; seed <= seeds; ++seed) {
    BrdfSamples noisy = clean;
    for (size_t i = 0; i < noisy.size(); ++i) {
      CounterRng rng(uint64_t(seed), i);
      const double sigma = sigma0 / std::sqrt(sqr(weights.sqrtWeight(i, 0)) / meanWeight);
      for (int c = 0; c < 3; ++c) {
        const double u0 = rng.uniform();
        noisy.value[i][c] += sigma * standardNormal(u0, rng.uniform());
      }
    }
    const FitResult result = fitBrdf(model, noisy, quickOptions(metric));
    EXPECT_TRUE(result.final.converged) << "seed " << seed;
    EXPECT_TRUE(result.covarianceAvailable) << "seed " << seed;
    if (!result.covarianceAvailable) continue;
    const Eigen::Map<const Eigen::VectorXd> x(result.x.data(), Eigen::Index(result.x.size()));
    const Eigen::Map<const Eigen::VectorXd> t(expected.data(), Eigen::Index(expected.size()));
    const Eigen::VectorXd delta = x - t;
    out.mahalanobis += delta.dot(result.covariance.ldlt().solve(delta));
    for (size_t j = 0; j < expected.size(); ++j) {
      const double z = std::abs(delta[Eigen::Index(j)]) / result.parameters[j].standardDeviation;
      out.within1 += z <= 1.0;
      out.within2 += z <= 2.0;
      ++out.total;
    }
  }
  return out;
}

void expectCalibrated(Metric metric, double sigma0) {
  constexpr int Seeds = 10;
  const Coverage c = coverage(metric, sigma0, Seeds);
  const double dof = 8.0 * Seeds;
  EXPECT_GT(c.mahalanobis, chiSquareQuantile(dof, -3.29)) << "error bars too large";
  EXPECT_LT(c.mahalanobis, chiSquareQuantile(dof, 3.29)) << "error bars too small";
  const double rate1 = double(c.within1) / c.total, rate2 = double(c.within2) / c.total;
  EXPECT_GT(rate1, 0.45) << rate1;
  EXPECT_LT(rate1, 0.90) << rate1;
  EXPECT_GT(rate2, 0.85) << rate2;
  std::printf(
      "%s: sum of d^2 over %d seeds %.1f (chi^2_%g: mean %g), within 1 sd %.0f%%, within 2 sd %.0f%%\n",
      toString(metric).c_str(), Seeds, c.mahalanobis, dof, dof, 100 * rate1, 100 * rate2);
}

struct MetricCase {
  Metric metric;
};
void PrintTo(const MetricCase& c, std::ostream* os) { *os << toString(c.metric); }

class NoiseCoverage : public ::testing::TestWithParam<MetricCase> {};

TEST_P(NoiseCoverage, RecoveredParametersFallWithinTheErrorBarsAtTheExpectedRate) {
  expectCalibrated(GetParam().metric, 0.02);
}

INSTANTIATE_TEST_SUITE_P(Grid, NoiseCoverage,
                         ::testing::Values(MetricCase{Metric::L2}, MetricCase{Metric::Ngan}),
                         [](const auto& info) { return toString(info.param.metric); });

}  // namespace noise_coverage_test
}  // namespace scatterlab::fitting::test
