#include <gtest/gtest.h>

#include "bssrdf_test_support.h"
#include "materials/bssrdf/subsurface_registry.h"
#include "materials/registry/spec_validation.h"
#include "tests/test_names.h"

namespace scatterlab {
namespace subsurface_registry_test {

using nlohmann::json;

std::string errorOf(const json& material) {
  try {
    makeSubsurface(material);
  } catch (const MaterialError& error) {
    return error.what();
  }
  return "";
}

TEST(SubsurfaceRegistry, DefaultIsBurleyOnSkin1WithJensensReflectance) {
  const SubsurfaceMaterial m = makeSubsurface(json{{"type", "subsurface"}});
  EXPECT_EQ(m.model, ProfileModel::Burley);
  EXPECT_EQ(m.profile->name(), "burley");
  const Rgb total = m.profile->totalReflectance();
  EXPECT_NEAR(total.x, 0.436, 5e-4);
  EXPECT_NEAR(total.y, 0.227, 5e-4);
  EXPECT_NEAR(total.z, 0.131, 5e-4);
  EXPECT_DOUBLE_EQ(m.medium.eta, 1.3);
  EXPECT_EQ(completeMaterial(json{{"type", "subsurface"}}), (json{{"type", "subsurface"},
                                                                  {"profile", "burley"},
                                                                  {"medium", "Skin1"},
                                                                  {"eta", 1.3},
                                                                  {"g", 0.0},
                                                                  {"scale", 1.0},
                                                                  {"boundary", "smooth"},
                                                                  {"burley_fit", "searchlight"}}));
}

TEST(SubsurfaceRegistry, MediumSetsTheDefaultIndex) {
  EXPECT_EQ(completeMaterial(json{{"type", "subsurface"}, {"medium", "Marble"}})["eta"], 1.5);
  EXPECT_EQ(completeMaterial(json{{"type", "subsurface"}, {"medium", "Marble"}, {"eta", 1.2}})["eta"], 1.2);
  EXPECT_EQ(completeMaterial(json{{"type", "subsurface"}, {"sigma_s", 1.0}, {"sigma_a", 0.1}})["eta"], 1.3);
  EXPECT_DOUBLE_EQ(makeSubsurface(json{{"type", "subsurface"}, {"medium", "Marble"}}).medium.eta, 1.5);
}

TEST(SubsurfaceRegistry, EveryProfileBuildsFromEveryParameterisation) {
  for (const char* profile : {"dipole", "better-dipole", "beam-diffusion", "burley"}) {
    SCOPED_TRACE(profile);
    const json coefficients{
        {"type", "subsurface"}, {"profile", profile}, {"sigma_s", {1.0, 2.0, 3.0}}, {"sigma_a", 0.05}};
    const SubsurfaceMaterial m = makeSubsurface(coefficients);
    EXPECT_EQ(m.profile->name(), profile);
    EXPECT_EQ(m.medium.sigmaS, Rgb(1.0, 2.0, 3.0));
    // Diffuse colour and mean free path: the built profile reflects the colour (bisection 1e-12).
    const json colour{{"type", "subsurface"},
                      {"profile", profile},
                      {"reflectance", {0.7, 0.4, 0.1}},
                      {"mfp", {1.0, 0.5, 0.25}}};
    const SubsurfaceMaterial c = makeSubsurface(colour);
    const Rgb total = c.profile->totalReflectance();
    EXPECT_NEAR(total.x, 0.7, 1e-9);
    EXPECT_NEAR(total.y, 0.4, 1e-9);
    EXPECT_NEAR(total.z, 0.1, 1e-9);
    const Rgb sigmaT = c.medium.extinction();
    EXPECT_NEAR(sigmaT.x, 1.0, 1e-12);
    EXPECT_NEAR(sigmaT.z, 4.0, 1e-12);
  }
}

TEST(SubsurfaceRegistry, MeanFreePathIsOneOverSigmaTWithAnisotropy) {
  const SubsurfaceMaterial m = makeSubsurface(
      json{{"type", "subsurface"}, {"profile", "dipole"}, {"reflectance", 0.5}, {"mfp", 2.0}, {"g", 0.6}});
  EXPECT_NEAR(m.medium.extinction().x, 0.5, 1e-12);
  EXPECT_NEAR(m.profile->totalReflectance().x, 0.5, 1e-9);
}

TEST(SubsurfaceRegistry, ScaleMultipliesCoefficientsAndShrinksTheProfile) {
  const json base{{"type", "subsurface"}, {"profile", "dipole"}, {"medium", "Skin2"}};
  json scaled = base;
  scaled["scale"] = 10.0;
  const SubsurfaceMaterial a = makeSubsurface(base), b = makeSubsurface(scaled);
  EXPECT_NEAR(b.medium.sigmaA.y, 10 * a.medium.sigmaA.y, 1e-12);
  // R_scaled(r) = s^2 R(s r): the same reflectance over a 10x smaller area.
  EXPECT_NEAR(b.profile->eval(0.05).y, 100 * a.profile->eval(0.5).y, 1e-10 * b.profile->eval(0.05).y);
  EXPECT_NEAR(b.profile->totalReflectance().y, a.profile->totalReflectance().y, 1e-15);
}

TEST(SubsurfaceRegistry, RoughBoundaryGetsItsDefaultRoughness) {
  const json rough{{"type", "subsurface"}, {"boundary", "rough"}};
  EXPECT_EQ(completeMaterial(rough)["roughness"], 0.1);
  const SubsurfaceMaterial m =
      makeSubsurface(json{{"type", "subsurface"}, {"boundary", "rough"}, {"roughness", 0.3}});
  EXPECT_EQ(m.boundary, SubsurfaceBoundary::Rough);
  EXPECT_DOUBLE_EQ(m.roughness, 0.3);
}

struct BadSubsurface {
  const char* what;
  json material;
  std::vector<std::string> messageContains;
};
void PrintTo(const BadSubsurface& b, std::ostream* os) { *os << b.what; }

class BadSubsurfaceTest : public ::testing::TestWithParam<BadSubsurface> {};

TEST_P(BadSubsurfaceTest, IsRejectedNamingKeyValueAndAllowed) {
  const std::string message = errorOf(GetParam().material);
  ASSERT_FALSE(message.empty()) << GetParam().material.dump();
  for (const std::string& fragment : GetParam().messageContains)
    EXPECT_NE(message.find(fragment), std::string::npos)
        << "\"" << fragment << "\" missing from: " << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

INSTANTIATE_TEST_SUITE_P(
    SubsurfaceRegistry, BadSubsurfaceTest,
    ::testing::Values(
        BadSubsurface{"negative scattering",
                      {{"type", "subsurface"}, {"sigma_s", -1.0}, {"sigma_a", 0.1}},
                      {"\"sigma_s\"", "-1", "out of range", ">= 0"}},
        BadSubsurface{"negative absorption channel",
                      {{"type", "subsurface"}, {"sigma_s", 1.0}, {"sigma_a", {0.1, -0.2, 0.1}}},
                      {"\"sigma_a\"", "g = -0.2", ">= 0"}},
        BadSubsurface{"no extinction",
                      {{"type", "subsurface"}, {"sigma_s", {1.0, 0.0, 1.0}}, {"sigma_a", 0.0}},
                      {"\"sigma_a\"", "sigma_s + sigma_a > 0"}},
        BadSubsurface{"reflectance above 1",
                      {{"type", "subsurface"}, {"reflectance", 1.2}, {"mfp", 1.0}},
                      {"\"reflectance\"", "1.2", "[0, 1]"}},
        BadSubsurface{"reflectance below 0",
                      {{"type", "subsurface"}, {"reflectance", {0.5, -0.1, 0.5}}, {"mfp", 1.0}},
                      {"\"reflectance\"", "[0, 1]"}},
        BadSubsurface{"zero mean free path",
                      {{"type", "subsurface"}, {"reflectance", 0.5}, {"mfp", 0.0}},
                      {"\"mfp\"", "0", "> 0"}},
        BadSubsurface{"reflectance without mfp",
                      {{"type", "subsurface"}, {"reflectance", 0.5}},
                      {"\"reflectance\"", "needs \"mfp\""}},
        BadSubsurface{"two parameterisations",
                      {{"type", "subsurface"}, {"medium", "Skin1"}, {"sigma_s", 1.0}, {"sigma_a", 1.0}},
                      {"cannot be combined", "\"medium\""}},
        BadSubsurface{"zero eta", {{"type", "subsurface"}, {"eta", 0.0}}, {"\"eta\"", "0", "(0, 4]"}},
        BadSubsurface{"negative eta", {{"type", "subsurface"}, {"eta", -1.3}}, {"\"eta\"", "-1.3", "(0, 4]"}},
        BadSubsurface{"unknown medium",
                      {{"type", "subsurface"}, {"medium", "Skin3"}},
                      {"\"medium\"", "\"Skin3\"", "\"Skin1\"", "\"Marble\"", "\"Wholemilk\""}},
        BadSubsurface{"unknown profile",
                      {{"type", "subsurface"}, {"profile", "quantized"}},
                      {"\"profile\"", "\"quantized\"", "\"burley\"", "\"beam-diffusion\""}},
        BadSubsurface{"g of 1", {{"type", "subsurface"}, {"g", 1.0}}, {"\"g\"", "(-1, 1)"}},
        BadSubsurface{"zero scale", {{"type", "subsurface"}, {"scale", 0.0}}, {"\"scale\"", "> 0"}},
        BadSubsurface{"rough boundary below the rough dielectric's eta",
                      {{"type", "subsurface"}, {"boundary", "rough"}, {"eta", 1.01}},
                      {"\"eta\"", "1.01", "[1.02, 4]", "rough boundary"}},
        BadSubsurface{"rough boundary at eta 1 (index matched)",
                      {{"type", "subsurface"}, {"boundary", "rough"}, {"eta", 1.0}},
                      {"\"eta\"", "[1.02, 4]", "\"boundary\": \"smooth\""}},
        BadSubsurface{"roughness on a smooth boundary",
                      {{"type", "subsurface"}, {"roughness", 0.2}},
                      {"\"roughness\"", "0.2", "rough boundary only", "\"boundary\": \"rough\""}},
        BadSubsurface{"burley fit on a dipole",
                      {{"type", "subsurface"}, {"profile", "dipole"}, {"burley_fit", "diffuse"}},
                      {"\"burley_fit\"", "burley profile only"}},
        BadSubsurface{"dmfp fit without absorption",
                      {{"type", "subsurface"}, {"medium", "Spectralon"}, {"burley_fit", "searchlight-dmfp"}},
                      {"\"burley_fit\"", "absorption"}},
        BadSubsurface{"unknown key",
                      {{"type", "subsurface"}, {"albedo", 0.5}},
                      {"\"albedo\"", "\"reflectance\"", "\"mfp\""}},
        BadSubsurface{
            "a BSDF", {{"type", "lambertian"}}, {"\"type\"", "\"lambertian\"", "not a subsurface material"}}),
    [](const ::testing::TestParamInfo<BadSubsurface>& info) {
      return test_names::readableTestName(info.param.what);
    });

TEST(SubsurfaceRegistry, MakeBsdfRefusesASubsurfaceMaterial) {
  try {
    makeBsdf(json{{"type", "subsurface"}});
    FAIL() << "no MaterialError";
  } catch (const MaterialError& error) {
    EXPECT_NE(std::string(error.what()).find("subsurface material"), std::string::npos) << error.what();
  }
  EXPECT_TRUE(isSubsurfaceMaterial(json{{"type", "subsurface"}, {"medium", "nonsense"}}));
  EXPECT_FALSE(isSubsurfaceMaterial(json{{"type", "lambertian"}}));
  EXPECT_FALSE(isSubsurfaceMaterial(json::array()));
}

}  // namespace subsurface_registry_test
}  // namespace scatterlab
