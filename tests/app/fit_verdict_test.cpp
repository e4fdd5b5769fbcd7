// The fit verdict (app/fit_verdict.h) on a result whose residuals are not finite at the fitted
// parameters (fitting/brdf_fit.h, finiteResiduals): POOR, and that reason comes first, whatever
// else the result says; the control, the same result with finite residuals, is GOOD.
#include <gtest/gtest.h>

#include <string>

#include <nlohmann/json.hpp>

#include "app/fit_verdict.h"
#include "fitting/material_writer.h"

namespace scatterlab {
namespace fit_verdict_test {

// A converged result with small errors, and a material the registry accepts.
fitting::FitResult soundResult() {
  fitting::FitResult result;
  result.final.converged = true;
  result.final.termination = "CONVERGENCE";
  result.relativeError = Rgb(0.01);
  return result;
}

const fitting::WrittenMaterial Written{nlohmann::json{{"type", "lambertian"}}, ""};

TEST(FitVerdict, ResidualsThatAreNotFiniteMakeTheFitPoorAndSaySoFirst) {
  ASSERT_TRUE(judgeFit(soundResult(), Written, DefaultMaxRelativeError).good);
  fitting::FitResult result = soundResult();
  result.finiteResiduals = false;
  const FitVerdict verdict = judgeFit(result, Written, DefaultMaxRelativeError);
  EXPECT_FALSE(verdict.good);
  ASSERT_FALSE(verdict.problems.empty());
  EXPECT_EQ(verdict.problems.front().rfind("the residuals at the fitted parameters are not finite", 0), 0u)
      << verdict.problems.front();
}

}  // namespace fit_verdict_test
}  // namespace scatterlab
