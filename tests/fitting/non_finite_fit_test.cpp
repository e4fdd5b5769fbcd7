// Nothing fails silently in the fitter (fitting/brdf_fit.h): grid points whose cost is not finite
// are counted, a grid without a finite point stops the fit with a message, and residuals that
// are not finite at the result mark the fit (finiteResiduals, the JSON's finite_residuals)
// instead of passing for a cost.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "fitting_test_support.h"

namespace scatterlab::fitting::test {
namespace non_finite_fit_test {

const double NaN = std::numeric_limits<double>::quiet_NaN();

const std::vector<json>& truth() {
  static const std::vector<json> t{
      json{{"type", "lambertian"}, {"albedo", {0.2, 0.3, 0.4}}},
      json{{"type", "ngan-cook-torrance"}, {"albedo", {0.2, 0.15, 0.1}}, {"eta", 0.3}, {"roughness", 0.1}}};
  return t;
}

bool hasNonFiniteValue(const BrdfSamples& samples) {
  for (const Rgb& v : samples.value)
    if (!isFinite(v)) return true;
  return false;
}

TEST(NonFiniteFit, ASoundFitCountsNothing) {
  const FitModel model(parseModelSpec("lambertian+ngan-cook-torrance"), false);
  const FitOptions options = quickOptions(Metric::Ngan);
  const FitResult result = fitBrdf(model, cellSamples(GroundTruth(truth()), 2), options);
  EXPECT_EQ(result.gridNonFinitePoints, 0u);
  EXPECT_EQ(result.nonFiniteStarts, 0u);
  EXPECT_TRUE(result.finiteResiduals);
  const json j = toJson(result, model, options);
  EXPECT_EQ(j["grid"]["non_finite_points"], 0);
  EXPECT_EQ(j["non_finite_starts"], 0);
  EXPECT_EQ(j["finite_residuals"], true);
}

// A sample the grid sees whose value is not finite makes every grid point's cost NaN: each is
// counted, none can start a fit, and the fit stops with a message that says so.
TEST(NonFiniteFit, AGridWithoutAFinitePointStopsTheFitWithAMessage) {
  const FitModel model(parseModelSpec("lambertian+ngan-cook-torrance"), false);
  BrdfSamples samples = cellSamples(GroundTruth(truth()), 2);
  samples.value[0] = Rgb(NaN);
  FitOptions options = quickOptions(Metric::Ngan);
  options.gridSamples = 0;  // the grid sees every sample, the NaN among them
  try {
    fitBrdf(model, samples, options);
    ADD_FAILURE() << "the fit did not stop";
  } catch (const std::runtime_error& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("points of the initial grid has a finite cost"), std::string::npos) << message;
  }
}

// A NaN value among the samples only the refinement on all of them sees: the grid and the starts
// are finite, the result's residuals are not, and the result says so rather than reporting a
// cost and error bars.
TEST(NonFiniteFit, ResidualsThatAreNotFiniteAtTheResultMarkTheFit) {
  const FitModel model(parseModelSpec("lambertian+ngan-cook-torrance"), false);
  const BrdfSamples clean = cellSamples(GroundTruth(truth()), 2);
  FitOptions options = quickOptions(Metric::Ngan);
  // One sample of each stratum of two (cellSamples), the same subset for the grid and the starts
  // (same size, same seed).
  options.gridSamples = options.startSamples = clean.size() / 2;
  BrdfSamples samples = clean;
  bool placed = false;
  for (size_t i = 0; i < samples.size() && !placed; ++i) {
    samples.value[i] = Rgb(NaN);
    placed = !hasNonFiniteValue(stratifiedSubset(samples, options.startSamples, options.seed));
    if (!placed) samples.value[i] = clean.value[i];
  }
  ASSERT_TRUE(placed) << "every sample is in the start subset";

  const FitResult result = fitBrdf(model, samples, options);
  EXPECT_EQ(result.gridNonFinitePoints, 0u);
  EXPECT_EQ(result.nonFiniteStarts, 0u);
  EXPECT_FALSE(result.finiteResiduals);
  EXPECT_FALSE(result.covarianceAvailable);
  EXPECT_TRUE(std::isnan(result.sigma2));
  const json j = toJson(result, model, options);
  EXPECT_EQ(j["finite_residuals"], false);
  EXPECT_TRUE(j["sigma2"].is_null());
}

}  // namespace non_finite_fit_test
}  // namespace scatterlab::fitting::test
