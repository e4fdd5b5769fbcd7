// The statistical kit on every profile (docs/validation.md section 6): energy, 1-D radius
// chi-square, consistency and inverse round trip, the directional normalisation, and the 2-D
// probe chi-square on a plane with the sampler's frame aligned and tilted; then the negative
// controls, which the kit must reject, and a seed study of the radius test's size.
#include <gtest/gtest.h>

#include "bssrdf_test_support.h"
#include "tests/test_names.h"
#include "validation/subsurface_check.h"

namespace scatterlab {
namespace subsurface_kit_test {

using testing_support::measuredMedium;

// Chi-square tests in this file's suites (5 per material: 3 radius, 2 probe; 16 materials):
// the family-wise 1% is Sidak-corrected over all of them.
constexpr int SuiteChiSquareTests = 80;

SubsurfaceCheckOptions kitOptions() {
  SubsurfaceCheckOptions o;
  o.samples = 200000;  // 4000 per radius bin, ~780 per probe cell
  o.radiusBins = 50;
  o.probeRings = 16;
  o.probeSectors = 16;
  o.seed = 3;
  o.chiSquareTestCount = SuiteChiSquareTests;
  return o;
}

struct KitCase {
  ProfileModel model;
  std::string medium;
};
void PrintTo(const KitCase& c, std::ostream* os) { *os << toString(c.model) << " " << c.medium; }

std::string caseName(const ::testing::TestParamInfo<KitCase>& info) {
  return test_names::readableTestName(toString(info.param.model) + "_" + info.param.medium);
}

std::vector<KitCase> cases(std::vector<std::string> media) {
  std::vector<KitCase> out;
  for (const ProfileModel model :
       {ProfileModel::Dipole, ProfileModel::BetterDipole, ProfileModel::BeamDiffusion, ProfileModel::Burley})
    for (const std::string& medium : media) out.push_back({model, medium});
  return out;
}

class SubsurfaceKit : public ::testing::TestWithParam<KitCase> {
 protected:
  SubsurfaceMaterial material() const {
    SubsurfaceMaterial m;
    m.model = GetParam().model;
    m.medium = measuredMedium(GetParam().medium);
    m.profile = makeProfile(m.model, m.medium, BurleyFit::Searchlight);
    return m;
  }
};

TEST_P(SubsurfaceKit, EveryRowPasses) {
  const SubsurfaceMaterial m = material();
  const CheckReport report = runSubsurfaceChecks(m.bssrdf(), caseName({GetParam(), 0}), kitOptions());
  EXPECT_EQ(report.rows.size(), 3u * 4u + 1u + 4u);
  EXPECT_TRUE(report.passed()) << formatTable(report);
}

INSTANTIATE_TEST_SUITE_P(Profiles, SubsurfaceKit, ::testing::ValuesIn(cases({"Skin1"})), caseName);
INSTANTIATE_TEST_SUITE_P(Grid, SubsurfaceKit, ::testing::ValuesIn(cases({"Marble", "Ketchup", "Spectralon"})),
                         caseName);

class SubsurfaceKitControls : public SubsurfaceKit {};

// Each broken sampler must be rejected: a radius pdf 5% off on half the radii (every channel),
// probe channel weights 30% off, and the radial shortcut instead of the multi-axis pdf.
TEST_P(SubsurfaceKitControls, KitRejectsEveryBrokenSampler) {
  const SubsurfaceMaterial m = material();
  const CheckReport report =
      runSubsurfaceNegativeControls(*m.profile, caseName({GetParam(), 0}), kitOptions());
  EXPECT_EQ(report.rows.size(), 5u);
  EXPECT_TRUE(report.passed()) << formatTable(report);
  for (const CheckRow& row : report.rows)
    EXPECT_EQ(row.note.rfind("rejected", 0), 0u) << row.test << ": " << row.note;
}

INSTANTIATE_TEST_SUITE_P(Controls, SubsurfaceKitControls, ::testing::ValuesIn(cases({"Skin1"})), caseName);

TEST(SubsurfaceKitControls, WrongChannelWeightsAreNotApplicableToAGreyMaterial) {
  const BurleyProfile grey(Rgb(0.5), Rgb(1.0));
  const CheckReport report = runSubsurfaceNegativeControls(grey, "grey", kitOptions());
  bool found = false;
  for (const CheckRow& row : report.rows)
    if (row.test.find("channel weights") != std::string::npos) {
      found = true;
      EXPECT_TRUE(row.passed);
      EXPECT_EQ(row.note.rfind("not applicable", 0), 0u) << row.note;
    }
  EXPECT_TRUE(found);
}

// The size of the radius test, measured: a correct sampler at alpha = 5% over 200 seeds is
// rejected Binomial(200, 0.05) times, 10 +- 3.1; 4 standard deviations allow 0..22.
TEST(SubsurfaceKitSeedStudy, RadiusTestRejectsACorrectSamplerAtItsNominalRate) {
  const auto profile = makeProfile(ProfileModel::Dipole, measuredMedium("Skin2"), BurleyFit::Searchlight);
  int rejected = 0;
  for (uint64_t seed = 0; seed < 200; ++seed)
    rejected += radiusChiSquare(*profile, *profile, 1, 20, 10000, 1000 + seed, 0.05).passed ? 0 : 1;
  EXPECT_LE(rejected, 22);
  EXPECT_GE(rejected, 1);
}

}  // namespace subsurface_kit_test
}  // namespace scatterlab
