// The 2-D piecewise-constant distribution: cell probabilities, sampling frequencies by a
// chi-square test over the cells, zero cells never drawn, and the leftover within the cell.
#include <gtest/gtest.h>

#include "materials/core/piecewise_constant_2d.h"
#include "materials/core/rng.h"
#include "validation/chi_square.h"

namespace scatterlab {
namespace piecewise_constant_2d_test {

TEST(PiecewiseConstant2D, ProbabilitiesAreNormalisedWeights) {
  const std::vector<double> w{1, 2, 0, 3, 0, 0, 4, 5, 1};
  const PiecewiseConstant2D d(w, 3, 3);
  EXPECT_DOUBLE_EQ(d.total(), 16.0);
  double sum = 0;
  for (size_t r = 0; r < 3; ++r)
    for (size_t c = 0; c < 3; ++c) {
      EXPECT_NEAR(d.probability(r, c), w[r * 3 + c] / 16.0, 1e-15);
      sum += d.probability(r, c);
    }
  EXPECT_NEAR(sum, 1.0, 1e-15);
}

TEST(PiecewiseConstant2D, SamplesCellsWithTheirProbabilities) {
  const size_t rows = 7, columns = 11;
  std::vector<double> w(rows * columns);
  for (size_t i = 0; i < w.size(); ++i) w[i] = (i * 37 % 13) == 0 ? 0.0 : double(i * 37 % 13);
  const PiecewiseConstant2D d(w, rows, columns);
  const size_t n = 200'000;
  Table2D observed{static_cast<int>(rows), static_cast<int>(columns)};
  Table2D expected{static_cast<int>(rows), static_cast<int>(columns)};
  CounterRng rng(9, 0);
  for (size_t i = 0; i < n; ++i) {
    const auto s = d.sample(rng.uniform2D());
    ASSERT_GT(w[s.row * columns + s.column], 0.0);
    EXPECT_GE(s.remapped.x, 0.0);
    EXPECT_LT(s.remapped.x, 1.0);
    EXPECT_GE(s.remapped.y, 0.0);
    EXPECT_LT(s.remapped.y, 1.0);
    observed(int(s.row), int(s.column)) += 1;
  }
  for (size_t r = 0; r < rows; ++r)
    for (size_t c = 0; c < columns; ++c) expected(int(r), int(c)) = n * d.probability(r, c);
  const auto result = chiSquareFromTables(observed, expected, n, 0.01);
  EXPECT_TRUE(result.passed) << "chi2 " << result.statistic << " dof " << result.dof << " p "
                             << result.pValue;
}

TEST(PiecewiseConstant2D, RejectsBadShapes) {
  const std::vector<double> w{1, 2, 3};
  EXPECT_THROW(PiecewiseConstant2D(w, 2, 2), std::invalid_argument);
  const std::vector<double> negative{1, -2, 3, 4};
  EXPECT_THROW(PiecewiseConstant2D(negative, 2, 2), std::invalid_argument);
}

}  // namespace piecewise_constant_2d_test
}  // namespace scatterlab
