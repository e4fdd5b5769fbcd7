// The catalog's chi-square suite (docs/validation.md, "The Sidak correction"). Every kit test of a
// correct sampler in materials_tests belongs to ONE suite with ONE Sidak correction: each
// test file registers how many chi-square tests its grid runs (a namespace-scope
// initialiser, so the total is known before any test starts), and every kit run uses the
// significance alpha' = 1 - (1 - alpha)^(1/m) with m the whole catalog's count. Adding a model
// therefore tightens every test a little instead of spending a fresh alpha per file.
//
// Also here: the suite's options, the negative-control assertion every model file uses, and
// names for parameterised tests. Instantiations are named "Grid/..." (parameter grids) and
// "Controls/..." (negative controls); CI runs both in the release build only (.ci/run).
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "materials/registry/spec_validation.h"
#include "validation/bsdf_check.h"
#include "validation/negative_controls.h"

namespace scatterlab::catalog_suite {

inline int& registeredChiSquareTests() {
  static int count = 0;
  return count;
}

// Adds `count` chi-square tests of correct samplers to the suite; returns it (so that a file
// can keep it in a constant).
inline int registerChiSquareTests(int count) {
  registeredChiSquareTests() += count;
  return count;
}

// m of the Sidak correction: every registered test of the binary.
inline int chiSquareTests() { return registeredChiSquareTests(); }

inline const std::vector<double>& incidentAngles() {
  static const std::vector<double> angles{0, 30, 60, 85, 89.9};
  return angles;
}

// The suite's options: 1e6 samples, 64 x 128 cells, the catalog-wide Sidak count, failure
// images under the test output directory.
inline BsdfCheckOptions options(const std::string& imageSubdir, uint64_t seed = 2024) {
  BsdfCheckOptions o;
  o.wiThetaDeg = incidentAngles();
  o.samples = 1'000'000;
  o.thetaBins = 64;
  o.phiBins = 128;
  o.seed = seed;
  o.chiSquareTestCount = chiSquareTests();
  o.reciprocityPairs = 20000;
  o.imageDir = std::filesystem::path(SCATTERLAB_TEST_OUTPUT_DIR) / imageSubdir;
  o.imagesOnFailureOnly = true;
  return o;
}

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
inline void expectControlsRejected(const nlohmann::json& material, double wiThetaDeg, int thetaBins = 64,
                                   int phiBins = 128) {
  const auto model = makeBsdf(material);
  const auto mismatched = withMismatchedRoughness(material, 1.1);
  const auto sampler = mismatched ? makeBsdf(*mismatched) : nullptr;
  BsdfCheckOptions o = options("controls");
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
