// The test kit as GoogleTest assertions (docs/own-bsdf.md): a user's test of their own BSDF is
//
//     #include "validation/gtest_check.h"
//     TEST(MyBsdf, PassesTheKit) { EXPECT_TRUE(scatterlab::passesBsdfCheck(MyBsdf(0.3))); }
//
// and a deliberately broken variant of it (a pdf that does not match the sampler) is shown to be
// caught with EXPECT_TRUE(scatterlab::failsBsdfCheck(broken)). On failure the message is the whole
// verdict table, as `scatterlab check` prints it. Header-only: include it from a test linked to
// scatterlab::validation and GTest::gtest.
#pragma once

#include <gtest/gtest.h>

#include "validation/check_bsdf.h"

namespace scatterlab {

// Success when the kit passes `model` (every row, negative controls included when asked).
inline ::testing::AssertionResult passesBsdfCheck(const BsdfModel& model,
                                                  const CheckBsdfOptions& options = {}) {
  const CheckReport report = checkBsdf(model, options);
  if (report.passed()) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "the kit rejects " << options.label << ":\n"
                                       << formatVerdict(report);
}

// Success when the kit REJECTS `model`: for a deliberately broken variant, which shows that the
// kit, at these options, has the power to catch the mistake it contains.
inline ::testing::AssertionResult failsBsdfCheck(const BsdfModel& model,
                                                 const CheckBsdfOptions& options = {}) {
  const CheckReport report = checkBsdf(model, options);
  if (!report.passed()) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << "the kit passes " << options.label << ", which should have been rejected:\n"
         << formatVerdict(report);
}

}  // namespace scatterlab
