// A material is validated once on its way through `scatterlab check` (docs/design.md, "Material
// descriptions"): the command turns the description into a typed value where it reads it, and
// the BSDF, the completed description printed and the roughness-mismatch control's sampler
// are all made from that value.
#include <gtest/gtest.h>

#include <iostream>
#include <sstream>

#include "app/check_command.h"
#include "materials/registry/spec_validation.h"

namespace scatterlab {
namespace check_validation_count_test {

// Runs `check` in this process with a small kit (its verdict is not the point here) and
// returns how many validations it made.
uint64_t validationsOfCheck(const std::string& material, bool negativeControls) {
  CheckCommandOptions options;
  options.materials = {material};
  options.kit.wiThetaDeg = {30};
  options.kit.samples = 2000;
  options.kit.thetaBins = 8;
  options.kit.phiBins = 16;
  options.kit.reciprocityPairs = 100;
  options.negativeControls = negativeControls;
  std::ostringstream out;
  std::streambuf* saved = std::cout.rdbuf(out.rdbuf());
  const uint64_t before = materialValidationCount();
  runCheckCommand(options);
  const uint64_t after = materialValidationCount();
  std::cout.rdbuf(saved);
  return after - before;
}

TEST(CheckValidatesOnce, ABsdfMaterialWithItsNegativeControls) {
  EXPECT_EQ(validationsOfCheck(R"({"type": "conductor", "alpha": 0.3})", true), 1u);
}

TEST(CheckValidatesOnce, ASubsurfaceMaterial) {
  EXPECT_EQ(validationsOfCheck(R"({"type": "subsurface", "profile": "burley"})", false), 1u);
}

}  // namespace check_validation_count_test
}  // namespace scatterlab
