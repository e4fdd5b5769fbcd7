#include <gtest/gtest.h>

#include <cmath>

#include "materials/core/root_finding.h"

namespace scatterlab {
namespace root_finding_test {

TEST(RootFinding, NewtonBisectionSolvesAMonotoneFunctionToTheTolerance) {
  // x^3 + x: a simple root for every target, Newton from a poor start.
  auto g = [](double x) { return ValueAndSlope{x * x * x + x, 3 * x * x + 1}; };
  for (const double target : {-5.0, 0.0, 0.3, 10.0, 1000.0}) {
    const double x = solveIncreasing(g, target, -20.0, 20.0, 19.0, 1e-14);
    EXPECT_NEAR(x * x * x + x, target, 1e-10 * std::max(1.0, std::abs(target))) << target;
  }
}

TEST(RootFinding, NewtonStepsThatLeaveTheBracketFallBackToBisection) {
  // atan has slopes that send Newton far out of the bracket from x = 5.
  auto g = [](double x) { return ValueAndSlope{std::atan(x), 1.0 / (1.0 + x * x)}; };
  const double x = solveIncreasing(g, 0.0, -10.0, 10.0, 5.0, 1e-15);
  EXPECT_NEAR(x, 0.0, 1e-14);
}

TEST(RootFinding, TargetsOutsideTheRangeClampToTheBracket) {
  auto g = [](double x) { return ValueAndSlope{x, 1.0}; };
  EXPECT_NEAR(solveIncreasing(g, 5.0, 0.0, 1.0, 0.5, 1e-14), 1.0, 1e-13);
  EXPECT_NEAR(solveIncreasing(g, -5.0, 0.0, 1.0, 0.5, 1e-14), 0.0, 1e-13);
  EXPECT_NEAR(bisectIncreasing([](double x) { return x; }, 5.0, 0.0, 1.0, 1e-14), 1.0, 1e-13);
}

TEST(RootFinding, BisectionFindsTheCrossingOfAStepFreeFunction) {
  const double x = bisectIncreasing([](double x) { return std::exp(x); }, 2.0, -5.0, 5.0, 1e-13);
  EXPECT_NEAR(x, std::log(2.0), 1e-12);
}

}  // namespace root_finding_test
}  // namespace scatterlab
