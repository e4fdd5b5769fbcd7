// The fitter's data: usable cells of a MERL table at their centres, missing cells excluded,
// and stratified subsets whose weights keep sums unbiased.
#include <gtest/gtest.h>

#include <map>
#include <set>

#include "fitting_test_support.h"
#include "materials/measured/measurement_synthesis.h"
#include "materials/measured/tabulated_brdf.h"

namespace scatterlab::fitting::test {
namespace brdf_samples_test {

// One full table (1,458,000 cells), shared by the tests of this file: 0.3-0.7 s to make.
const MerlTable& lambertianTable() {
  static const MerlTable table = [] {
    const auto model = makeBsdf(json{{"type", "lambertian"}, {"albedo", {0.2, 0.4, 0.6}}});
    MeasurementPerturbation missing;
    missing.missingAboveDeg = 80.0;
    return MeasurementSynthesizer({model.get()}, missing).synthesize();
  }();
  return table;
}

TEST(SamplesFromMerl, KeepsExactlyTheMeasuredReachableCellsAtTheirCentres) {
  const MerlTable& table = lambertianTable();
  MerlSampleCounts counts;
  const BrdfSamples samples = samplesFromMerl(table, &counts);
  size_t reachable = 0, reachableAndMeasured = 0;
  for (size_t cell = 0; cell < merl::CellCount; ++cell) {
    reachable += isReachableCell(cell);
    reachableAndMeasured += isReachableCell(cell) && !table.isMissing(cell);
  }
  EXPECT_EQ(counts.cells, merl::CellCount);
  EXPECT_EQ(counts.missing, table.missingCount());
  EXPECT_EQ(counts.usable, reachableAndMeasured);
  EXPECT_EQ(samples.size(), reachableAndMeasured);
  EXPECT_EQ(counts.missing + counts.unreachable + counts.usable, merl::CellCount);
  EXPECT_LT(reachableAndMeasured, reachable);  // the cut-off removed some
  for (size_t i = 0; i < samples.size(); i += 997) {
    EXPECT_GT(samples.wi[i].z, std::cos(radians(80.0)) - 1e-12);
    EXPECT_GT(samples.wo[i].z, std::cos(radians(80.0)) - 1e-12);
    // The table's value (stored as albedo/pi times the channel scale, round-tripped exactly).
    EXPECT_NEAR(samples.value[i].x, 0.2 / Pi, 1e-15);
    EXPECT_NEAR(samples.value[i].z, 0.6 / Pi, 1e-15);
    EXPECT_EQ(samples.weight[i], 1.0);
  }
}

TEST(SamplesFromMerl, TableWithNoMeasuredCellGivesNoSamples) {
  MerlTable table;
  for (size_t cell = 0; cell < merl::CellCount; ++cell) table.setMissing(cell);
  MerlSampleCounts counts;
  EXPECT_TRUE(samplesFromMerl(table, &counts).empty());
  EXPECT_EQ(counts.missing, merl::CellCount);
}

TEST(StratifiedSubset, WeightsSumToTheStratumSizesAndEveryStratumIsKept) {
  const BrdfSamples all = samplesFromMerl(lambertianTable());
  const BrdfSamples subset = stratifiedSubset(all, 50000, 7);
  std::map<uint32_t, size_t> allCount;
  std::map<uint32_t, double> subsetWeight;
  for (size_t i = 0; i < all.size(); ++i) ++allCount[all.stratum[i]];
  for (size_t i = 0; i < subset.size(); ++i) subsetWeight[subset.stratum[i]] += subset.weight[i];
  EXPECT_EQ(allCount.size(), subsetWeight.size());
  for (const auto& [stratum, n] : allCount)
    EXPECT_NEAR(subsetWeight[stratum], double(n), 1e-9 * double(n)) << stratum;
  // About the target: ceil per stratum adds at most one sample per stratum.
  EXPECT_GE(subset.size(), 50000u);
  EXPECT_LE(subset.size(), 50000u + allCount.size());
  EXPECT_NEAR(subset.totalWeight(), double(all.size()), 1e-6 * double(all.size()));
}

TEST(StratifiedSubset, SameSeedSameSubsetOtherSeedOtherSubset) {
  const BrdfSamples all = samplesFromMerl(lambertianTable());
  const BrdfSamples a = stratifiedSubset(all, 20000, 3), b = stratifiedSubset(all, 20000, 3),
                    c = stratifiedSubset(all, 20000, 4);
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) ASSERT_EQ(a.wi[i], b.wi[i]);
  size_t differ = 0;
  for (size_t i = 0; i < std::min(a.size(), c.size()); ++i) differ += a.wi[i] != c.wi[i];
  EXPECT_GT(differ, a.size() / 2);
  // No sample is chosen twice.
  std::set<std::tuple<double, double, double, double>> seen;
  for (size_t i = 0; i < a.size(); ++i)
    EXPECT_TRUE(seen.insert({a.wi[i].x, a.wi[i].z, a.wo[i].x, a.wo[i].y}).second);
}

TEST(StratifiedSubset, TargetZeroOrLargerThanTheSetKeepsEverything) {
  const BrdfSamples all = cellSamples(GroundTruth(std::vector<json>{json{{"type", "lambertian"}}}), 1);
  EXPECT_EQ(stratifiedSubset(all, 0, 1).size(), all.size());
  EXPECT_EQ(stratifiedSubset(all, all.size() + 10, 1).size(), all.size());
}

}  // namespace brdf_samples_test
}  // namespace scatterlab::fitting::test
