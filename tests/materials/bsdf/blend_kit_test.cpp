// Blends through the whole test kit (docs/validation.md sections 1-4): a Lambertian with a rough
// conductor at w = 0.3, two conductors of very different roughness with a coloured weight, a
// white Lambertian with a smooth dielectric (delta reflection and refraction: the kit adds
// their discrete probabilities to the chi-square expectation), and a blend of two lossless
// models, which must pass the white furnace; plus the negative controls.
#include <gtest/gtest.h>

#include "catalog_suite.h"
#include "materials/bsdf/blend.h"
#include "materials/registry/spec_validation.h"

namespace scatterlab {
namespace blend_kit_test {

using nlohmann::json;

struct BlendCase {
  const char* name;
  json material;
  bool transmissive = false;  // the kit then also tests from below: twice the chi-square tests
};
void PrintTo(const BlendCase& c, std::ostream* os) { *os << c.name; }

json blendOf(json weight, json first, json second) {
  return {
      {"type", "blend"}, {"weight", std::move(weight)}, {"materials", {std::move(first), std::move(second)}}};
}

std::vector<BlendCase> grid() {
  return {
      {"LambertianGoldGgx_w0p3",
       blendOf(0.3, {{"type", "lambertian"}, {"albedo", 0.8}}, {{"type", "conductor"}, {"alpha", 0.3}})},
      {"SharpAndRoughConductors_coloured",
       blendOf({0.2, 0.5, 0.8}, {{"type", "conductor"}, {"alpha", 0.02}, {"metal", "Ag"}},
               {{"type", "conductor"}, {"alpha", {0.8, 0.3}}, {"metal", "Cu"}})},
      // Delta reflection and refraction into eta 1.5, seen from both sides.
      {"LambertianGlass",
       blendOf(0.5, {{"type", "lambertian"}, {"albedo", 1.0}}, {{"type", "dielectric"}, {"eta", 1.5}}), true},
  };
}

// Normal, oblique and grazing incidence (a kit case costs ~3 s of CPU per angle); the smoke
// test adds 30 degrees.
const std::vector<double> GridAngles{0, 60, 89.9};

int gridChiSquareTests() {
  int count = 0;
  for (const BlendCase& c : grid()) count += int(GridAngles.size()) * (c.transmissive ? 2 : 1);
  return count;
}
// The grid, and the smoke test below.
const catalog_suite::ChiSquareSuite Suite{"blend-kit", gridChiSquareTests() + 1};

class BlendKit : public ::testing::TestWithParam<BlendCase> {};

TEST_P(BlendKit, PassesEveryCheck) {
  const auto model = makeBsdf(GetParam().material);
  BsdfCheckOptions o = Suite.options();
  o.wiThetaDeg = GridAngles;
  ASSERT_EQ(chiSquareTestCount(o, *model), int(GridAngles.size()) * (GetParam().transmissive ? 2 : 1));
  catalog_suite::expectPasses(*model, GetParam().name, o);
}

INSTANTIATE_TEST_SUITE_P(Grid, BlendKit, ::testing::ValuesIn(grid()),
                         [](const ::testing::TestParamInfo<BlendCase>& info) {
                           return std::string(info.param.name);
                         });

// Outside the grid, so that the sanitizer pass runs a blend through the kit too: two lossless
// models (a white rough plastic and a white Lambertian), so the blend is lossless and the
// white furnace check runs; at 30 degrees, which the grid leaves out.
TEST(BlendKitSmoke, LosslessPairPassesTheFurnace) {
  const auto model =
      makeBsdf(blendOf({0.3, 0.6, 0.9}, {{"type", "rough-plastic"}, {"alpha", 0.05}, {"diffuse", 1.0}},
                       {{"type", "lambertian"}, {"albedo", 1.0}}));
  ASSERT_TRUE(model->isLossless());
  BsdfCheckOptions o = Suite.options();
  o.wiThetaDeg = {30};
  catalog_suite::expectPasses(*model, "smoke", o);
}

// The kit must reject deliberately broken samplers of blends (docs/validation.md, "Negative controls"). A
// blend has no single lobe width, so the roughness-mismatch control reports "not applicable".
struct ControlCase {
  const char* name;
  json material;
  double wiTheta;
};
void PrintTo(const ControlCase& c, std::ostream* os) { *os << c.name; }
class BlendNegativeControls : public ::testing::TestWithParam<ControlCase> {};
TEST_P(BlendNegativeControls, AreAllRejected) {
  catalog_suite::expectControlsRejected(Suite, GetParam().material, GetParam().wiTheta);
}
INSTANTIATE_TEST_SUITE_P(
    Controls, BlendNegativeControls,
    ::testing::Values(
        ControlCase{"LambertianGold_wi0",
                    blendOf(0.3, {{"type", "lambertian"}}, {{"type", "conductor"}, {"alpha", 0.3}}), 0.0},
        ControlCase{"TwoConductors_wi80",
                    blendOf(0.5, {{"type", "conductor"}, {"alpha", 0.05}},
                            {{"type", "conductor"}, {"alpha", 0.5}, {"distribution", "beckmann"}}),
                    80.0}),
    [](const ::testing::TestParamInfo<ControlCase>& info) { return std::string(info.param.name); });

}  // namespace blend_kit_test
}  // namespace scatterlab
