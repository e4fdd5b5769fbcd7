// The statistics behind the chi-square test, on hand-made tables with known answers.
#include <gtest/gtest.h>

#include "validation/chi_square.h"

namespace scatterlab {
namespace {

Table2D row(std::initializer_list<double> v) {
  Table2D t(1, int(v.size()));
  t.values.assign(v);
  return t;
}

TEST(ChiSquareStatistics, StatisticDofAndPValueOfSimpleTable) {
  // Two cells, O = (60, 40), E = (50, 50): chi2 = 100/50 + 100/50 = 4, dof = 1,
  // p = Q(1/2, 2) = erfc(sqrt(2)) = 0.0455003.
  const ChiSquareResult r = chiSquareFromTables(row({60, 40}), row({50, 50}), 100, 0.01);
  EXPECT_DOUBLE_EQ(r.statistic, 4.0);
  EXPECT_EQ(r.dof, 1);
  EXPECT_NEAR(r.pValue, std::erfc(std::sqrt(2.0)), 1e-12);
  EXPECT_TRUE(r.passed);
}

TEST(ChiSquareStatistics, TwoDegreesOfFreedomHaveExponentialTail) {
  // For dof = 2, Q(1, x/2) = exp(-x/2).
  const ChiSquareResult r = chiSquareFromTables(row({70, 40, 40}), row({50, 50, 50}), 150, 0.01);
  EXPECT_EQ(r.dof, 2);
  EXPECT_NEAR(r.pValue, std::exp(-r.statistic / 2), 1e-12);
}

TEST(ChiSquareStatistics, SmallCellsArePooledIntoOneScoredCell) {
  // Cells with E < 5 (1, 2, 3) pool into one cell with E = 6, O = 6: it contributes 0.
  const ChiSquareResult r = chiSquareFromTables(row({1, 1, 4, 50, 50}), row({1, 2, 3, 50, 50}), 106, 0.01);
  EXPECT_EQ(r.pooledCells, 3);
  EXPECT_EQ(r.dof, 2);  // pool + two cells - 1
  EXPECT_DOUBLE_EQ(r.statistic, 0.0);
}

TEST(ChiSquareStatistics, PoolBelowMinimumMergesIntoNextCell) {
  // Pool E = 1 + 2 = 3 < 5: merged with the E = 10 cell -> one cell E = 13, O = 3 + 10.
  const ChiSquareResult r = chiSquareFromTables(row({2, 1, 10, 40}), row({1, 2, 10, 40}), 53, 0.01);
  EXPECT_EQ(r.dof, 1);
  EXPECT_DOUBLE_EQ(r.statistic, 0.0);
}

TEST(ChiSquareStatistics, SamplesWherePdfIsZeroRejectAtOnce) {
  // 20 samples in a cell of expectation 0 with N = 1000: more than 1e-5 N.
  const ChiSquareResult r = chiSquareFromTables(row({20, 490, 490}), row({0, 500, 500}), 1000, 0.01);
  EXPECT_FALSE(r.passed);
  EXPECT_NE(r.failure.find("support"), std::string::npos) << r.failure;
}

TEST(ChiSquareStatistics, GrossMismatchIsRejected) {
  const ChiSquareResult r = chiSquareFromTables(row({700, 300}), row({500, 500}), 1000, 0.01);
  EXPECT_FALSE(r.passed);
  EXPECT_LT(r.pValue, 1e-20);
}

TEST(ChiSquareStatistics, SidakCorrection) {
  EXPECT_DOUBLE_EQ(sidakSignificance(0.01, 1), 0.01);
  // 1 - 0.99^(1/10) = 0.00100453...
  EXPECT_NEAR(sidakSignificance(0.01, 10), 1.0 - std::pow(0.99, 0.1), 1e-15);
  // For large m it approaches alpha / m from above.
  EXPECT_GT(sidakSignificance(0.01, 1000), 0.01 / 1000);
  EXPECT_NEAR(sidakSignificance(0.01, 1000), 0.01 / 1000, 1e-7);
}

}  // namespace
}  // namespace scatterlab
