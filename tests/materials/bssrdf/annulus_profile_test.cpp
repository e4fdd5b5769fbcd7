// Profiles on annuli (annulus_profile.h): exact averages, the r-weighted relative error that
// compares a profile with the walk, the coarser groups it is measured on, and its noise floor.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "materials/bssrdf/annulus_profile.h"
#include "materials/bssrdf/burley.h"
#include "materials/bssrdf/half_space_walk.h"

namespace scatterlab {
namespace annulus_profile_test {

TEST(AnnulusProfile, AveragesCarryTheProfilesPower) {
  const BurleyProfile profile(Rgb(0.3, 0.6, 0.9), Rgb(0.5, 1.0, 2.0));
  const std::vector<double> edges = logRadiusEdges(1e-3, 10.0, 20);
  const std::vector<double> areas = annulusAreas(edges);
  for (int c = 0; c < 3; ++c) {
    const std::vector<double> means = annulusMeans(profile, c, edges);
    double power = 0.0;
    for (size_t k = 0; k < means.size(); ++k) power += means[k] * areas[k];
    EXPECT_NEAR(power, profile.totalReflectance()[c] * profile.radiusCdf(c, edges.back()), 1e-14);
  }
}

TEST(AnnulusProfile, RelativeErrorIsTheL1DistanceOfThePower) {
  const std::vector<double> edges{0.0, 1.0, 2.0, 3.0};
  const std::vector<double> areas = annulusAreas(edges);  // pi, 3 pi, 5 pi
  const std::vector<double> reference{1.0, 0.5, 0.1}, twice{2.0, 1.0, 0.2}, disjoint{0.0, 0.0, 0.0};
  EXPECT_DOUBLE_EQ(radialRelativeError(edges, reference, reference), 0.0);
  EXPECT_NEAR(radialRelativeError(edges, twice, reference), 1.0, 1e-15);
  // Nothing in the annuli, all of the model's power beyond them: the distance is both totals.
  const double total = reference[0] * areas[0] + reference[1] * areas[1] + reference[2] * areas[2];
  EXPECT_NEAR(radialRelativeError(edges, disjoint, reference, total, 0.0), 2.0, 1e-15);
  // The power beyond the edges counts as one more bin of the reference too.
  EXPECT_NEAR(radialRelativeError(edges, reference, reference, 0.0, total), 1.0 / 2.0, 1e-15);
  EXPECT_THROW(radialRelativeError(edges, std::vector<double>{1.0}, reference), std::invalid_argument);
}

TEST(AnnulusProfile, GroupsAreWholeAnnuliAndKeepThePower) {
  const std::vector<double> edges = linearRadiusEdges(20.0, 1000);
  std::vector<double> means;
  for (size_t k = 0; k + 1 < edges.size(); ++k) means.push_back(std::exp(-edges[k]));
  const std::vector<size_t> groups = logAnnulusGroups(edges, 16);
  ASSERT_GE(groups.size(), 3u);
  EXPECT_EQ(groups.front(), 0u);
  EXPECT_EQ(groups.back(), edges.size() - 1);
  for (size_t g = 1; g < groups.size(); ++g) EXPECT_GT(groups[g], groups[g - 1]);
  const std::vector<double> coarse = groupedEdges(edges, groups);
  const std::vector<double> merged = groupedMeans(edges, means, groups);
  const std::vector<double> fineAreas = annulusAreas(edges), coarseAreas = annulusAreas(coarse);
  double fine = 0.0, grouped = 0.0;
  for (size_t k = 0; k < means.size(); ++k) fine += means[k] * fineAreas[k];
  for (size_t k = 0; k < merged.size(); ++k) grouped += merged[k] * coarseAreas[k];
  EXPECT_NEAR(grouped, fine, 1e-12 * fine);
}

TEST(AnnulusProfile, NoiseFloorOfOneAnnulus) {
  // One annulus holding p = 0.2 of n paths: E|error| = sqrt(2 / pi) sqrt(p (1 - p) / n), relative to p.
  const std::vector<double> edges{0.0, 1.0};
  const double n = 1e4, p = 0.2;
  EXPECT_NEAR(radialNoiseFloor(edges, std::vector<double>{p / Pi}, n),
              std::sqrt(2.0 / Pi) * std::sqrt(p * (1 - p) / n) / p, 1e-15);
}

}  // namespace annulus_profile_test
}  // namespace scatterlab
