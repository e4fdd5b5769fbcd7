// The catalog's chi-square suites (docs/validation.md section 1). Each kit test file declares
// its suite with the number of chi-square tests of correct samplers it runs, and every kit run
// of the file uses the Sidak-corrected significance alpha' = 1 - (1 - alpha)^(1/m) with m that
// count: the file's family of tests is false-rejected with probability alpha at most. The count
// is written next to the grid it counts, and the kit tests assert it where the kit itself
// could count differently (models with transmission are also checked from below).
//
// Also here: the negative-control assertion every model file uses, and names for
// parameterised tests. Instantiations are named "Grid/..." (parameter grids) and
// "Controls/..." (negative controls); CI runs both in the release build only (.ci/run).
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "materials/registry/spec_validation.h"
#include "validation/bsdf_check.h"
#include "validation/chi_square.h"
#include "validation/negative_controls.h"

namespace scatterlab::catalog_suite {

inline const std::vector<double>& incidentAngles() {
  static const std::vector<double> angles{0, 30, 60, 85, 89.9};
  return angles;
}

// One family of chi-square tests of correct samplers: `name` (failure images go to a
// directory of that name under the test output directory) and `testCount`, the m of its Sidak
// correction at family-wise level alpha = 0.01.
class ChiSquareSuite {
 public:
  ChiSquareSuite(std::string name, int testCount) : name_(std::move(name)), testCount_(testCount) {
    if (testCount_ < 1) throw std::invalid_argument("a chi-square suite runs at least one test");
  }
  const std::string& name() const { return name_; }
  int testCount() const { return testCount_; }
  static constexpr double Alpha = 0.01;
  // alpha' of each test of the suite.
  double threshold() const { return sidakSignificance(Alpha, testCount_); }

  // The kit's options for this suite: 1e6 samples, 64 x 128 cells, incidentAngles(), m =
  // testCount(), failure images only on failure.
  BsdfCheckOptions options(uint64_t seed = 2024) const {
    BsdfCheckOptions o;
    o.wiThetaDeg = incidentAngles();
    o.samples = 1'000'000;
    o.thetaBins = 64;
    o.phiBins = 128;
    o.seed = seed;
    o.alpha = Alpha;
    o.chiSquareTestCount = testCount_;
    o.reciprocityPairs = 20000;
    o.imageDir = std::filesystem::path(SCATTERLAB_TEST_OUTPUT_DIR) / name_;
    o.imagesOnFailureOnly = true;
    return o;
  }

 private:
  std::string name_;
  int testCount_;
};

// 0.05 -> "0p05", for test names.
inline std::string number(double x) {
  std::string s = std::to_string(x);
  s.erase(s.find_last_not_of('0') + 1);
  if (!s.empty() && s.back() == '.') s.pop_back();
  for (char& ch : s) ch = ch == '.' ? 'p' : (ch == '-' ? 'm' : ch);
  return s;
}

inline void expectPasses(const BsdfModel& model, const std::string& label, const BsdfCheckOptions& o) {
  const CheckReport report = runBsdfChecks(model, label, o);
  EXPECT_TRUE(report.passed()) << formatTable(report);
}

// The negative controls of a registry material at one incident angle, with the suite's
// options: every control must be REJECTED, except that the kit may report a control as not
// applicable where its probe found that the control changes nothing for this model (a pdf
// symmetric in wi and wo; a sampler that does not depend on the roughness, such as Oren-
// Nayar's cosine sampling). The +5% control can never be a no-op and must be rejected, so the
// assertion can fail for every model. A model with transmission is checked from the angle's
// own side only (above 90 degrees: from inside). `thetaBins` x `phiBins`: coarser cells hold
// more samples each and lose no power against these errors, at a quarter of the quadrature.
// The controls are tested at the significance of `suite`, the one a real error of the same
// model would face.
inline void expectControlsRejected(const ChiSquareSuite& suite, const nlohmann::json& material,
                                   double wiThetaDeg, int thetaBins = 64, int phiBins = 128) {
  const auto model = makeBsdf(material);
  const auto mismatched = withMismatchedRoughness(material, 1.1);
  const auto sampler = mismatched ? makeBsdf(*mismatched) : nullptr;
  BsdfCheckOptions o = suite.options();
  o.wiThetaDeg = {wiThetaDeg};
  o.transmissionFromBelow = false;
  o.thetaBins = thetaBins;
  o.phiBins = phiBins;
  o.imageDir.reset();
  const CheckReport report = runNegativeControls(*model, sampler.get(), material.dump(), o);
  ASSERT_EQ(report.rows.size(), allNegativeControls().size());
  for (size_t i = 0; i < report.rows.size(); ++i) {
    const CheckRow& row = report.rows[i];
    const NegativeControl control = allNegativeControls()[i];
    EXPECT_TRUE(row.passed) << row.test << ": " << row.note;
    const bool mustReject = control == NegativeControl::PdfHighOnHalf;
    const bool rejected = row.note.rfind("rejected", 0) == 0;
    if (mustReject)
      EXPECT_TRUE(rejected) << row.test << ": " << row.note;
    else
      EXPECT_TRUE(rejected || row.note.rfind("not applicable", 0) == 0) << row.test << ": " << row.note;
  }
}

}  // namespace scatterlab::catalog_suite
