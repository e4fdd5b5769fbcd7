// Rough plastic through the whole test kit (docs/validation.md sections 1-4) over a grid with the
// hard corners: alpha 0.001 and 1, a black and a white base (white: lossless, so the furnace
// check runs), indices 1.1 to 2.4, GGX and Beckmann, incident angles up to 89.9 degrees; plus
// the negative controls, which the kit must reject for this model too.
#include <gtest/gtest.h>

#include "catalog_suite.h"
#include "materials/bsdf/rough_plastic.h"

namespace scatterlab {
namespace rough_plastic_kit_test {

struct PlasticCase {
  MicrofacetType type;
  double alpha;
  Rgb kd;
  double eta;
};

// Appended piece by piece: a chain of + here trips GCC 12's -Wrestrict (a false positive, GCC
// bug 105329; materials/registry/parameter_spec.cpp's inQuotes does the same).
std::string name(const PlasticCase& c) {
  const auto n = catalog_suite::number;
  std::string out = c.type == MicrofacetType::Ggx ? "Ggx" : "Beckmann";
  out += "_alpha";
  out += n(c.alpha);
  out += "_kd";
  out += n(c.kd.x);
  if (c.kd.x != c.kd.y || c.kd.y != c.kd.z) {
    out += "_";
    out += n(c.kd.y);
    out += "_";
    out += n(c.kd.z);
  }
  out += "_eta";
  out += n(c.eta);
  return out;
}
void PrintTo(const PlasticCase& c, std::ostream* os) { *os << name(c); }

// The corners, each once: alpha 0.001 and 1 of both distributions, a black and a white base
// (white: lossless, so the furnace check runs) with both distributions, indices 1.1 to 2.4.
// A kit case costs ~3 s of CPU per incident angle here, so the grid runs at normal, 60 degrees
// and grazing incidence; the smoke test below adds 85 degrees and a coloured base.
std::vector<PlasticCase> grid() {
  return {
      {MicrofacetType::Ggx, 0.001, Rgb(1.0), 1.5},       // near-mirror coating, lossless
      {MicrofacetType::Ggx, 1.0, Rgb(0.0), 1.1},         // roughest coating alone, lowest index
      {MicrofacetType::Beckmann, 0.001, Rgb(0.5), 2.4},  // near-mirror, high index
      {MicrofacetType::Beckmann, 1.0, Rgb(1.0), 1.5},    // roughest coating, lossless
  };
}
const std::vector<double> GridAngles{0, 60, 89.9};

// The grid, and the smoke test below.
const catalog_suite::ChiSquareSuite Suite{"rough-plastic-kit", int(grid().size() * GridAngles.size()) + 1};

class RoughPlasticKit : public ::testing::TestWithParam<PlasticCase> {};

TEST_P(RoughPlasticKit, PassesEveryCheck) {
  const PlasticCase& c = GetParam();
  const auto model = makeRoughPlastic(c.type, c.alpha, c.kd, c.eta);
  BsdfCheckOptions o = Suite.options();
  o.wiThetaDeg = GridAngles;
  catalog_suite::expectPasses(*model, name(c), o);
}

INSTANTIATE_TEST_SUITE_P(Grid, RoughPlasticKit, ::testing::ValuesIn(grid()),
                         [](const ::testing::TestParamInfo<PlasticCase>& info) { return name(info.param); });

// One kit case outside the grid, so that the sanitizer pass (which skips Grid/...) runs the
// model through the whole kit too: a coloured base under a high-index coating, at 85 degrees.
TEST(RoughPlasticKitSmoke, ColouredGgxPassesAt85Degrees) {
  const auto model = makeRoughPlastic(MicrofacetType::Ggx, 0.3, Rgb(0.8, 0.2, 0.05), 2.4);
  BsdfCheckOptions o = Suite.options();
  o.wiThetaDeg = {85};
  catalog_suite::expectPasses(*model, "smoke", o);
}

// The kit must reject deliberately broken samplers of this model (docs/validation.md, "Negative controls").
struct ControlCase {
  const char* name;
  nlohmann::json material;
  double wiTheta;
};
void PrintTo(const ControlCase& c, std::ostream* os) { *os << c.name; }
class RoughPlasticNegativeControls : public ::testing::TestWithParam<ControlCase> {};
TEST_P(RoughPlasticNegativeControls, AreAllRejected) {
  catalog_suite::expectControlsRejected(Suite, GetParam().material, GetParam().wiTheta);
}
INSTANTIATE_TEST_SUITE_P(
    Controls, RoughPlasticNegativeControls,
    ::testing::Values(
        ControlCase{"GgxDark_wi0", {{"type", "rough-plastic"}, {"alpha", 0.3}, {"diffuse", 0.1}}, 0.0},
        ControlCase{"GgxWhite_wi85",
                    {{"type", "rough-plastic"}, {"alpha", 0.05}, {"diffuse", 1.0}, {"eta", 2.0}},
                    85.0}),
    [](const ::testing::TestParamInfo<ControlCase>& info) { return std::string(info.param.name); });

}  // namespace rough_plastic_kit_test
}  // namespace scatterlab
