// The alias table: probabilities, sampling frequencies by a chi-square test (with a negative
// control), zero-weight cells never drawn, and a uniform leftover within the chosen cell.
#include <gtest/gtest.h>

#include "materials/core/alias_table.h"
#include "materials/core/rng.h"
#include "validation/chi_square.h"

namespace scatterlab {
namespace alias_table_test {

// 2 tests at family-wise 1%.
const double Threshold = sidakSignificance(0.01, 2);

std::vector<double> skewedWeights() {
  std::vector<double> w(37);
  for (size_t i = 0; i < w.size(); ++i)
    w[i] = (i % 5 == 0) ? 0.0 : std::pow(1.3, double(i % 11)) + 1e-3 * double(i);
  w[7] = 500.0;  // one dominant cell
  return w;
}

Table2D histogram(const AliasTable& table, size_t n, size_t leftoverBins, Table2D* leftovers) {
  Table2D counts(1, int(table.size()));
  CounterRng rng(21, 0);
  for (size_t k = 0; k < n; ++k) {
    const auto s = table.sample(rng.uniform());
    EXPECT_GE(s.remapped, 0.0);
    EXPECT_LT(s.remapped, 1.0);
    counts(0, int(s.cell)) += 1;
    if (leftovers && s.cell == 7)
      (*leftovers)(0, std::min(int(s.remapped * leftoverBins), int(leftoverBins) - 1)) += 1;
  }
  return counts;
}

TEST(AliasTable, DrawsCellsWithTheirProbabilities) {
  const std::vector<double> w = skewedWeights();
  const AliasTable table(w);
  double total = 0;
  for (const double x : w) total += x;
  EXPECT_DOUBLE_EQ(table.total(), total);
  const size_t n = 400'000;
  Table2D leftovers(1, 10);
  const Table2D observed = histogram(table, n, 10, &leftovers);
  Table2D expected(1, int(w.size()));
  for (size_t i = 0; i < w.size(); ++i) {
    EXPECT_NEAR(table.probability(i), w[i] / total, 1e-15);
    expected(0, int(i)) = n * table.probability(i);
    if (w[i] == 0) {
      EXPECT_EQ(observed(0, int(i)), 0.0) << "zero-weight cell " << i << " drawn";
    }
  }
  const auto r = chiSquareFromTables(observed, expected, n, Threshold);
  EXPECT_TRUE(r.passed) << "chi2 " << r.statistic << " dof " << r.dof << " p " << r.pValue;
  // The leftover within the dominant cell is uniform.
  const double drawn = leftovers.sum();
  const auto uniform = chiSquareFromTables(leftovers, Table2D(1, 10, drawn / 10), size_t(drawn), Threshold);
  EXPECT_TRUE(uniform.passed) << "chi2 " << uniform.statistic << " p " << uniform.pValue;
}

TEST(AliasTable, RejectsOtherProbabilities) {
  std::vector<double> w = skewedWeights();
  const AliasTable table(w);
  const size_t n = 400'000;
  const Table2D observed = histogram(table, n, 1, nullptr);
  w[3] *= 1.5;  // one cell of 0.4% probability claimed 50% more likely
  const AliasTable other(w);
  Table2D expected(1, int(w.size()));
  for (size_t i = 0; i < w.size(); ++i) expected(0, int(i)) = n * other.probability(i);
  EXPECT_FALSE(chiSquareFromTables(observed, expected, n, Threshold).passed);
}

TEST(AliasTable, EmptyAndInvalid) {
  const std::vector<double> zeros(4, 0.0);
  EXPECT_EQ(AliasTable(zeros).total(), 0.0);
  const std::vector<double> bad{1.0, -1.0};
  EXPECT_THROW(AliasTable{bad}, std::invalid_argument);
}

}  // namespace alias_table_test
}  // namespace scatterlab
