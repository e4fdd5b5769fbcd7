// Conductors whose complex index is fitted (fit_model.h: f0 and edge tint per channel,
// Gulbrandsen 2014, written back as eta and k): a copper table tabulated as `scatterlab synth`
// does is fitted back from the default starts (the grid and its best distinct points) without
// naming the metal, for GGX and Beckmann; Ngan's Cook-Torrance recovers its Schlick F0 the same
// way. The data are noise-free, so the least-squares optimum is the truth: the 1%
// bounds leave room only for a wrong basin or a degenerate parameterisation.
#include <gtest/gtest.h>

#include <cstdio>

#include "fitting/material_writer.h"
#include "fitting_test_support.h"
#include "materials/bsdf/edge_tint.h"
#include "materials/bsdf/metals.h"
#include "materials/measured/measurement_synthesis.h"

namespace scatterlab::fitting::test {
namespace conductor_index_test {

constexpr double Bound = 0.01;  // the issue's: alpha and normal-incidence reflectance within 1%

double normalReflectance(double eta, double k) { return reflectanceAndEdgeTintOf(eta, k).x; }

// A stratified subset of a MERL-layout table of `truth`, as `scatterlab synth` writes it.
BrdfSamples synthTableSamples(const json& truth, size_t count) {
  const auto model = makeBsdf(truth);
  const MerlTable table = MeasurementSynthesizer({model.get()}, MeasurementPerturbation{}).synthesize();
  return stratifiedSubset(samplesFromMerl(table), count, 5);
}

// Default starts: FitOptions' grid budget and number of starts; every sample of the subset.
FitOptions defaultStarts() {
  FitOptions options;
  options.gridSamples = 0;
  options.startSamples = 0;
  options.threads = 2;
  return options;
}

TEST(FittedConductorIndex, CopperTableRecoversAlphaAndReflectance) {
  const MetalIor& copper = *findMetal("Cu");
  for (const std::string distribution : {"ggx", "beckmann"}) {
    const json truth{{"type", "conductor"}, {"metal", "Cu"}, {"distribution", distribution}, {"alpha", 0.17}};
    const FitModel model(parseModelSpec(json{{"type", "conductor"}, {"distribution", distribution}}.dump()),
                         false);
    ASSERT_TRUE(model.components()[0].fittedIndex);
    const FitResult result = fitBrdf(model, synthTableSamples(truth, 30000), defaultStarts());
    EXPECT_TRUE(result.final.converged) << distribution << ": " << result.final.message;
    const double alpha = parameterValue(model, result.x, "conductor.alpha");
    std::printf("[ index ] %s copper: alpha %.5f (truth 0.17)", distribution.c_str(), alpha);
    EXPECT_NEAR(alpha, 0.17, Bound * 0.17) << distribution;
    const char* channels[] = {"r", "g", "b"};
    for (int c = 0; c < 3; ++c) {
      const double truthF0 = normalReflectance(copper.eta[c], copper.k[c]);
      const double f0 = parameterValue(model, result.x, std::string("conductor.f0.") + channels[c]);
      std::printf(", f0.%s %.5f (truth %.5f)", channels[c], f0, truthF0);
      EXPECT_NEAR(f0, truthF0, Bound * truthF0) << distribution << " channel " << c;
    }
    std::printf("\n");

    // The written material is a registry conductor with (eta, k) of that reflectance.
    const WrittenMaterial written = writeMaterial(model.fittedParts(result.x.data()));
    ASSERT_TRUE(written.material) << written.problem;
    const json& m = *written.material;
    EXPECT_EQ(m.at("type"), "conductor");
    EXPECT_FALSE(m.contains("f0"));
    for (int c = 0; c < 3; ++c) {
      const double f0 = parameterValue(model, result.x, std::string("conductor.f0.") + channels[c]);
      EXPECT_NEAR(normalReflectance(m.at("eta")[size_t(c)].get<double>(), m.at("k")[size_t(c)].get<double>()),
                  f0, 1e-12);
    }
  }
}

TEST(FittedConductorIndex, NganCookTorranceRecoversItsF0) {
  const json truth{
      {"type", "ngan-cook-torrance"}, {"albedo", {0.5, 0.4, 0.3}}, {"eta", 0.35}, {"roughness", 0.2}};
  const FitModel model(parseModelSpec("ngan-cook-torrance"), false);
  const FitResult result = fitBrdf(model, synthTableSamples(truth, 30000), defaultStarts());
  EXPECT_TRUE(result.final.converged) << result.final.message;
  const double f0 = parameterValue(model, result.x, "ngan-cook-torrance.eta");
  const double roughness = parameterValue(model, result.x, "ngan-cook-torrance.roughness");
  std::printf("[ index ] ngan-cook-torrance: F0 %.5f (truth 0.35), roughness %.5f (truth 0.2)\n", f0,
              roughness);
  EXPECT_NEAR(f0, 0.35, Bound * 0.35);
  EXPECT_NEAR(roughness, 0.2, Bound * 0.2);
}

// The parameterisation: every (f0, edge tint) gives an index with that normal-incidence
// reflectance, and a real metal's index maps back to itself.
TEST(EdgeTint, MapsToIndicesWithThatReflectanceAndBack) {
  for (double r : {0.001, 0.04, 0.5, 0.95, 0.999})
    for (double g : {0.0, 0.3, 1.0}) {
      const ComplexIndexT<double> index = indexFromReflectanceAndEdgeTint(r, g);
      EXPECT_NEAR(normalReflectance(index.eta, index.k), r, 1e-12 * std::max(r, 1.0)) << r << " " << g;
      const Vec2d back = reflectanceAndEdgeTintOf(index.eta, index.k);
      EXPECT_NEAR(back.y, g, 1e-7) << r << " " << g;
    }
  for (const MetalIor& metal : namedMetals())
    for (int c = 0; c < 3; ++c) {
      const Vec2d rg = reflectanceAndEdgeTintOf(metal.eta[c], metal.k[c]);
      const ComplexIndexT<double> index = indexFromReflectanceAndEdgeTint(rg.x, rg.y);
      EXPECT_NEAR(index.eta, metal.eta[c], 1e-9 * std::max(metal.eta[c], 1.0)) << metal.name << " " << c;
      EXPECT_NEAR(index.k, metal.k[c], 1e-9 * std::max(metal.k[c], 1.0)) << metal.name << " " << c;
    }
}

// Fitted alone: with another component the Fresnel factor and a weight could trade places.
TEST(FittedConductorIndex, IsFittedAlone) {
  try {
    FitModel(parseModelSpec("lambertian+conductor"), false);
    FAIL() << "no error";
  } catch (const MaterialError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("fitted alone"), std::string::npos) << message;
    EXPECT_NE(message.find(WhiteConductorSpec), std::string::npos) << message;
  }
  const FitModel model(parseModelSpec("conductor"), false);
  std::vector<std::string> names;
  for (const FitParameter& p : model.parameters()) names.push_back(p.name);
  EXPECT_EQ(names, (std::vector<std::string>{"conductor.alpha", "conductor.f0.r", "conductor.f0.g",
                                             "conductor.f0.b", "conductor.edge_tint.r",
                                             "conductor.edge_tint.g", "conductor.edge_tint.b"}));
}

}  // namespace conductor_index_test
}  // namespace scatterlab::fitting::test
