// What the kit tests of the glossy reflection models (Ward, Ashikhmin-Shirley, Ngan's
// Cook-Torrance) share: the suite's options (1e6 samples, 64 x 128 cells, incident angles up
// to 89.9 degrees, Sidak over every chi-square test of the file) and a case name.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "validation/bsdf_check.h"

namespace scatterlab::glossy_kit {

inline const std::vector<double>& incidentAngles() {
  static const std::vector<double> angles{0, 30, 60, 85, 89.9};
  return angles;
}

// `chiSquareTests`: every chi-square test of a correct sampler in the file (Sidak).
inline BsdfCheckOptions options(int chiSquareTests, const std::string& imageSubdir) {
  BsdfCheckOptions o;
  o.wiThetaDeg = incidentAngles();
  o.samples = 1'000'000;
  o.thetaBins = 64;
  o.phiBins = 128;
  o.seed = 2024;
  o.chiSquareTestCount = chiSquareTests;
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
  for (char& ch : s) ch = ch == '.' ? 'p' : ch;
  return s;
}

inline void expectPasses(const BsdfModel& model, const std::string& label, const BsdfCheckOptions& o) {
  const CheckReport report = runBsdfChecks(model, label, o);
  EXPECT_TRUE(report.passed()) << formatTable(report);
}

}  // namespace scatterlab::glossy_kit
