// The statistics behind the chi-square test, on hand-made tables with known answers.
#include <gtest/gtest.h>

#include <cmath>

#include "validation/chi_square.h"

namespace scatterlab {
namespace chi_square_statistics_test {

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
  // 20 samples in a cell of expectation 0.
  const ChiSquareResult r = chiSquareFromTables(row({20, 490, 490}), row({0, 500, 500}), 1000, 0.01);
  EXPECT_FALSE(r.passed);
  EXPECT_NE(r.failure.find("support"), std::string::npos) << r.failure;
}

// However few: 3 samples of 1e6 where the pdf integrates to 0 would once have been pooled
// (below the old allowance of 1e-5 N = 10), into a pool whose expectation is 0, where no
// statistic can score them.
TEST(ChiSquareStatistics, EvenAFewSamplesWherePdfIsZeroReject) {
  const ChiSquareResult r =
      chiSquareFromTables(row({3, 0, 499997, 500000}), row({0, 0, 500000, 500000}), 1000000, 0.01);
  EXPECT_FALSE(r.passed);
  EXPECT_NE(r.failure.find("3 of 1000000 samples"), std::string::npos) << r.failure;
  // The control: the same table without them passes.
  EXPECT_TRUE(
      chiSquareFromTables(row({0, 0, 500000, 500000}), row({0, 0, 500000, 500000}), 1000000, 0.01).passed);
}

// One scored cell: 0 degrees of freedom, so no p-value is made up; the count is tested
// instead, |O - E| / sqrt(E) <= CountSigmas.
TEST(ChiSquareStatistics, NoDegreesOfFreedomMeansNoPValue) {
  // E = 10000 (sd 100): O = 10300 is 3 sd away, O = 10600 is 6.
  const ChiSquareResult close = chiSquareFromTables(row({10300, 0}), row({10000, 0}), 10300, 0.01);
  EXPECT_EQ(close.dof, 0);
  EXPECT_FALSE(close.hasPValue());
  EXPECT_TRUE(std::isnan(close.pValue));
  EXPECT_DOUBLE_EQ(close.countZ, 3.0);
  EXPECT_TRUE(close.passed);
  const ChiSquareResult far = chiSquareFromTables(row({10600, 0}), row({10000, 0}), 10600, 0.01);
  EXPECT_FALSE(far.passed);
  EXPECT_NE(far.failure.find("no degrees of freedom"), std::string::npos) << far.failure;
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

}  // namespace chi_square_statistics_test
}  // namespace scatterlab
