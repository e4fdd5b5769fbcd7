// The lab's fit families are identifiable, and a fit that is not (rank deficient) is never
// GOOD. Fitted to a noise-free table of a published Lambert + Cook-Torrance line
// (data/published-fits), on one cell per (theta_h, theta_d) stratum.
#include <gtest/gtest.h>

#include <string>

#include "app/fit_verdict.h"
#include "app/lab/lab_settings.h"
#include "fitting/fitting_test_support.h"
#include "fitting/material_writer.h"

namespace scatterlab {
namespace lab_fit_families_test {

using namespace fitting;
using namespace fitting::test;

FitResult fitSpec(const std::string& spec) {
  static const BrdfSamples samples =
      cellSamples(GroundTruth(publishedFit("alum-bronze", "ngan_cooktorrance.fit")), 1);
  const FitModel model(parseModelSpec(spec), false);
  return fitBrdf(model, samples, quickOptions(Metric::Ngan));
}

// Every family with a fixed index is identifiable on this table. The conductor whose index is
// fitted (f0 and edge tint per channel) needs data near grazing to fix its edge tint, which
// one cell per stratum of this table need not hold: there it may be rank deficient, and then
// its verdict must be POOR (its identifiability on conductor data is FitCli's copper test).
TEST(LabFitFamilies, AreIdentifiable) {
  for (const auto& [name, spec] : LabSettings::quickMode(1).fitFamilies) {
    const FitResult result = fitSpec(spec);
    if (spec != "conductor") {
      EXPECT_FALSE(result.rankDeficient) << name << " (" << spec << "): " << result.unidentified.size()
                                         << " directions the data cannot determine";
      continue;
    }
    if (!result.rankDeficient) continue;
    const FitModel model(parseModelSpec(spec), false);
    EXPECT_FALSE(judgeFit(result, writeMaterial(model.fittedParts(result.x.data())), 10.0).good)
        << name << " is rank deficient here and must not be GOOD";
  }
}

// The control: a Lambertian beside Blinn-Phong's own diffuse kd is a direction along which the
// data cannot tell the two apart. The fit says so, and the verdict is POOR whatever its error.
TEST(LabFitFamilies, LambertianBesideBlinnPhongIsRankDeficientAndPoor) {
  const FitResult result = fitSpec("lambertian+blinn-phong");
  ASSERT_TRUE(result.rankDeficient);
  ASSERT_FALSE(result.unidentified.empty());
  EXPECT_NE(result.unidentified[0].find("lambertian.albedo"), std::string::npos) << result.unidentified[0];
  EXPECT_NE(result.unidentified[0].find("blinn-phong.kd"), std::string::npos) << result.unidentified[0];
  const FitModel model(parseModelSpec("lambertian+blinn-phong"), false);
  const FitVerdict verdict = judgeFit(result, writeMaterial(model.fittedParts(result.x.data())), 10.0);
  EXPECT_FALSE(verdict.good);
  bool named = false;
  for (const std::string& problem : verdict.problems) named = named || problem.find("rank deficient") == 0;
  EXPECT_TRUE(named) << "no rank-deficiency problem among " << verdict.problems.size();
}

}  // namespace lab_fit_families_test
}  // namespace scatterlab
