#include "materials/bsdf/metals.h"

#include <algorithm>
#include <cstdio>
#include <sstream>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "materials/bsdf/fresnel.h"
#include "materials/bsdf/metal_reduction.h"
#include "materials/core/cie.h"

namespace scatterlab {
namespace metals_test {

struct MetalSpectra {
  Spectrum eta, k;
};

MetalSpectra readShippedSpectra(const std::string& name) {
  const std::string base = std::string(SCATTERLAB_DATA_DIR) + "/ior/" + name;
  return {readSpd(base + ".eta.spd"), readSpd(base + ".k.spd")};
}

// One line of the table in materials/bsdf/metals.cpp, ready to paste.
std::string tableLine(const MetalIor& metal) {
  char line[256];
  std::snprintf(line, sizeof line, "    {\"%s\", {%.10g, %.10g, %.10g}, {%.10g, %.10g, %.10g}},\n",
                metal.name, metal.eta.x, metal.eta.y, metal.eta.z, metal.k.x, metal.k.y, metal.k.z);
  return line;
}

const MetalIor& metal(const char* name) {
  const MetalIor* found = findMetal(name);
  if (!found) throw std::logic_error(std::string("metal missing from the table: ") + name);
  return *found;
}

Rgb normalIncidence(const MetalIor& m) { return fresnelConductor(1.0, m.eta, m.k); }

// The generator of the table: recompute every metal from data/ior and compare.
TEST(NamedMetals, TableMatchesTheReductionOfTheShippedSpectra) {
  std::string regenerated;
  bool matches = true;
  for (const MetalIor& stored : namedMetals()) {
    const MetalSpectra spectra = readShippedSpectra(stored.name);
    const MetalIor fresh = reduceMetalSpectra(stored.name, spectra.eta, spectra.k);
    regenerated += tableLine(fresh);
    for (int c = 0; c < 3; ++c) {
      matches = matches && relativeDifference(stored.eta[c], fresh.eta[c]) <= 1e-6 &&
                relativeDifference(stored.k[c], fresh.k[c]) <= 1e-6;
    }
  }
  EXPECT_TRUE(matches) << "materials/bsdf/metals.cpp is out of date; its table should read:\n" << regenerated;
}

// k_c is solved so that (eta_c, k_c) reproduces the spectra's RGB reflectance exactly at
// normal incidence; the table's 10 significant digits keep that to ~1e-10.
TEST(NamedMetals, TableReproducesTheSpectralRgbReflectance) {
  for (const MetalIor& stored : namedMetals()) {
    const MetalSpectra spectra = readShippedSpectra(stored.name);
    const Rgb expected = normalIncidenceReflectanceRgb(spectra.eta, spectra.k);
    const Rgb actual = normalIncidence(stored);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(actual[c], expected[c], 1e-9) << stored.name << " channel " << c;
  }
}

TEST(NamedMetals, LooksUpEveryShippedMetalBySymbol) {
  ASSERT_EQ(namedMetals().size(), 5u);
  for (const char* name : {"Au", "Ag", "Al", "Cu", "Cr"}) {
    const MetalIor* found = findMetal(name);
    ASSERT_NE(found, nullptr) << name;
    EXPECT_STREQ(found->name, name);
  }
  EXPECT_EQ(findMetal("Xx"), nullptr);
  EXPECT_EQ(findMetal("au"), nullptr);
  EXPECT_EQ(findMetal(""), nullptr);
}

// Gold and copper absorb blue and green (interband transitions), so they look yellow/red.
TEST(NamedMetals, GoldAndCopperReflectRedMoreThanGreenMoreThanBlue) {
  for (const char* name : {"Au", "Cu"}) {
    const Rgb r = normalIncidence(metal(name));
    EXPECT_GT(r.x, r.y) << name;
    EXPECT_GT(r.y, r.z) << name;
  }
}

// Silver and aluminium reflect nearly flat spectra above 85% across the visible range.
TEST(NamedMetals, SilverAndAluminiumAreBrightAndNearlyNeutral) {
  for (const char* name : {"Ag", "Al"}) {
    const Rgb r = normalIncidence(metal(name));
    for (int c = 0; c < 3; ++c) EXPECT_GT(r[c], 0.85) << name;
    EXPECT_LT(std::max({r.x, r.y, r.z}) / std::min({r.x, r.y, r.z}), 1.1) << name;
  }
}

// Every metal's reflectance goes to 1 at grazing incidence. It is NOT monotone over the
// last 20 degrees in general: the p-polarised reflectance has its principal-angle minimum
// there (the conductor's analogue of Brewster's angle), which pulls the unpolarised average
// down by up to ~0.07 (aluminium, minimum near 82 degrees) before it climbs to 1. So the test
// checks the shape physics gives: a single minimum (possibly at normal incidence), a
// monotone fall before it and a monotone rise from it to 89.9 degrees.
TEST(NamedMetals, ReflectanceRisesTowardOneAtGrazingIncidence) {
  for (const MetalIor& m : namedMetals()) {
    for (int c = 0; c < 3; ++c) {
      const auto reflectance = [&](int tenthsOfDegree) {
        return fresnelConductor(std::cos(radians(0.1 * tenthsOfDegree)), m.eta[c], m.k[c]);
      };
      constexpr int Grazing = 899;  // 89.9 degrees
      int minimum = 0;
      for (int t = 0; t <= Grazing; ++t) {
        if (reflectance(t) < reflectance(minimum)) minimum = t;
      }
      for (int t = 1; t <= minimum; ++t)
        ASSERT_LE(reflectance(t), reflectance(t - 1)) << m.name << " channel " << c << " at " << 0.1 * t;
      for (int t = minimum + 1; t <= Grazing; ++t)
        ASSERT_GT(reflectance(t), reflectance(t - 1)) << m.name << " channel " << c << " at " << 0.1 * t;
      EXPECT_GT(reflectance(Grazing), 0.95) << m.name << " channel " << c;
      EXPECT_GT(reflectance(Grazing), reflectance(0)) << m.name << " channel " << c;
    }
  }
}

// The CIE XYZ system is defined so that the equal-energy white has X = Y = Z; the analytic
// fit reproduces that to its fitting accuracy (~1%).
TEST(CieMatching, EqualEnergyWhiteHasEqualTristimulusValues) {
  Vec3d sum(0.0);
  for (int lambda = 360; lambda <= 830; ++lambda) sum += cieXyzMatching(lambda);
  EXPECT_NEAR(sum.x / sum.y, 1.0, 0.01);
  EXPECT_NEAR(sum.z / sum.y, 1.0, 0.01);
  // y-bar is the photopic luminous efficiency, 1 at its 555 nm peak.
  EXPECT_NEAR(cieXyzMatching(555.0).y, 1.0, 0.01);
}

// The matrix maps D65 to (1, 1, 1) and each Rec.709 primary onto its own axis.
TEST(CieMatching, Rec709MatrixMapsWhiteAndPrimaries) {
  const auto xyzOf = [](double x, double y) { return Vec3d(x / y, 1.0, (1.0 - x - y) / y); };
  const Rgb white = xyzToLinearRec709(xyzOf(0.3127, 0.3290));
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(white[c], 1.0, 1e-12);
  const Vec3d primaries[] = {xyzOf(0.64, 0.33), xyzOf(0.30, 0.60), xyzOf(0.15, 0.06)};
  for (int p = 0; p < 3; ++p) {
    const Rgb rgb = xyzToLinearRec709(primaries[p]);
    for (int c = 0; c < 3; ++c) {
      if (c == p) continue;
      EXPECT_NEAR(rgb[c] / rgb[p], 0.0, 1e-12) << "primary " << p;
    }
  }
}

TEST(SpdReader, SkipsCommentsAndInterpolatesLinearly) {
  std::istringstream in("# header\n# ; more\n\n400 1.0\n  500\t3.0  # trailing\n600 2.0\r\n");
  const Spectrum s = parseSpd(in, "test");
  ASSERT_EQ(s.wavelengths.size(), 3u);
  EXPECT_EQ(s.at(450.0), 2.0);
  EXPECT_EQ(s.at(575.0), 2.25);
  EXPECT_EQ(s.at(300.0), 1.0);  // held at the ends
  EXPECT_EQ(s.at(700.0), 2.0);
}

TEST(SpdReader, RejectsMalformedInput) {
  for (const char* text : {"400 1.0\n500\n", "400 1.0\n500 x\n", "400 1.0\n500 2.0 3.0\n",
                           "500 1.0\n400 2.0\n", "500 1.0\n500 2.0\n", "400 1.0\n", "# only a comment\n"}) {
    std::istringstream in(text);
    EXPECT_THROW(parseSpd(in, "test"), std::runtime_error) << text;
  }
  EXPECT_THROW(readSpd(std::string(SCATTERLAB_DATA_DIR) + "/ior/Xx.eta.spd"), std::runtime_error);
}

// A perfect reflector maps to RGB (1, 1, 1) by the per-channel normalisation, and a
// wavelength-independent (n, k) to its own normal-incidence reflectance in every channel.
TEST(MetalReduction, GreySpectraReduceToTheirOwnIndex) {
  const Spectrum n{{300.0, 900.0}, {0.5, 0.5}}, k{{300.0, 900.0}, {3.0, 3.0}};
  const MetalIor grey = reduceMetalSpectra("grey", n, k);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(grey.eta[c], 0.5, 1e-12);
    EXPECT_NEAR(grey.k[c], 3.0, 1e-12);
  }
}

TEST(MetalReduction, ChannelIndexReproducesTheReflectance) {
  for (const double eta : {0.2, 0.9, 1.5, 3.0}) {
    for (const double reflectance : {0.0, 0.01, 0.04, 0.3, 0.9, 0.999}) {
      const ComplexIndex index = indexWithNormalReflectance(eta, reflectance);
      EXPECT_NEAR(fresnelConductor(1.0, index.eta, index.k), reflectance, 1e-12);
      EXPECT_GE(index.k, 0.0);
      // Below the dielectric reflectance of eta no k >= 0 fits: k = 0 and eta moves toward 1,
      // staying on its side of 1. (At the boundary itself either branch is exact.)
      const double dielectric = sqr((eta - 1.0) / (eta + 1.0));
      if (reflectance < dielectric - 1e-12) {
        EXPECT_EQ(index.k, 0.0);
        EXPECT_GE((index.eta - 1.0) * (eta - 1.0), 0.0);
        EXPECT_LT(std::abs(index.eta - 1.0), std::abs(eta - 1.0));
      } else if (reflectance > dielectric + 1e-12) {
        EXPECT_EQ(index.eta, eta);
      }
    }
  }
  EXPECT_THROW(indexWithNormalReflectance(1.5, 1.0), std::domain_error);
  EXPECT_THROW(indexWithNormalReflectance(1.5, -0.1), std::domain_error);
}

}  // namespace metals_test
}  // namespace scatterlab
