// Robust losses: with a few gross outliers in the data (2% of the samples five times too
// bright, like dust or a glint), Huber, Cauchy and soft-L1 fits stay close to the truth while
// the plain least-squares fit is pulled away.
#include <gtest/gtest.h>

#include "fitting_test_support.h"

namespace scatterlab::fitting::test {
namespace robust_test {

const std::vector<json>& truth() {
  static const std::vector<json> t{
      json{{"type", "lambertian"}, {"albedo", {0.2, 0.3, 0.4}}},
      json{{"type", "ngan-cook-torrance"}, {"albedo", {0.2, 0.15, 0.1}}, {"eta", 0.3}, {"roughness", 0.1}}};
  return t;
}

// The largest relative error over the fitted parameters.
double worstRelativeError(const FitModel& model, const std::vector<double>& x) {
  double worst = 0;
  for (size_t j = 0; j < model.parameterCount(); ++j) {
    const FitParameter& p = model.parameters()[j];
    const json v = truth()[p.component][p.key];
    const double expected = v.is_array() ? v[size_t(p.channel)].get<double>() : v.get<double>();
    worst = std::max(worst, std::abs(x[j] - expected) / expected);
  }
  return worst;
}

TEST(RobustLoss, OutliersPullThePlainFitButNotTheRobustOnes) {
  BrdfSamples samples = cellSamples(GroundTruth(truth()), 2);
  for (size_t i = 0; i < samples.size(); i += 50) samples.value[i] *= 5.0;
  const FitModel model(parseModelSpec("lambertian+ngan-cook-torrance"), false);
  FitOptions options = quickOptions(Metric::Ngan);
  const double plain = worstRelativeError(model, fitBrdf(model, samples, options).x);
  std::printf("plain least squares: worst relative parameter error %.4f\n", plain);
  for (const std::string name : {"huber", "cauchy", "soft-l1"}) {
    options.robust = *parseRobustLoss(name);
    const FitResult result = fitBrdf(model, samples, options);
    const double robust = worstRelativeError(model, result.x);
    std::printf("%-8s (scale %.3g): worst relative parameter error %.4f\n", name.c_str(), result.robustScale,
                robust);
    EXPECT_TRUE(result.final.converged) << name;
    EXPECT_GT(result.robustScale, 0) << name;
    EXPECT_LT(robust, 0.1) << name;          // measured 0.017 to 0.048
    EXPECT_LT(robust, 0.2 * plain) << name;  // plain: 1.5
  }
}

}  // namespace robust_test
}  // namespace scatterlab::fitting::test
