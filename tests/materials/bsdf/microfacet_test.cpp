#include "materials/bsdf/microfacet.h"

#include <vector>

#include <ceres/jet.h>
#include <gtest/gtest.h>

#include "materials/core/quadrature.h"

namespace scatterlab {
namespace microfacet_test {

struct Roughness {
  double x, y;
};
// The corners the test kit covers: near-specular, moderate, very rough, strongly anisotropic.
constexpr Roughness Roughnesses[] = {{0.001, 0.001}, {0.01, 0.01}, {0.3, 0.3},
                                     {1.0, 1.0},     {0.05, 0.8},  {0.8, 0.05}};

// Incident directions from normal to 89.9 degrees, at azimuths that mix the two roughnesses.
std::vector<Vec3d> incidentDirections() {
  return {directionFromDegrees(0, 0),   directionFromDegrees(30, 20),  directionFromDegrees(60, 90),
          directionFromDegrees(85, 37), directionFromDegrees(89.9, 0), directionFromDegrees(89.9, 63)};
}

template <typename Distribution> Distribution makeDistribution(const Roughness& r) {
  return Distribution(r.x, r.y);
}

std::string describe(const Roughness& r, const Vec3d& w = Vec3d(0, 0, 1)) {
  return "alpha (" + std::to_string(r.x) + ", " + std::to_string(r.y) + "), w theta " +
         std::to_string(degrees(sphericalTheta(w))) + " phi " + std::to_string(degrees(sphericalPhi(w)));
}

// Integral of g(m) over the hemisphere of normals, in the distribution's stretched slope
// plane: m = normalize(-ax r cos psi, -ay r sin psi, 1) with solid angle
// d omega = ax ay r cos^3 theta_m dr dpsi (slopes: d omega = cos^3 theta_m dx dy), and
// r = t / (1 - t) over t in [0, 1). An exact change of variables that gives every roughness
// a lobe of width ~1, so the adaptive quadrature resolves alpha = 0.001 as well as alpha = 1.
template <typename Distribution, typename F> double integrateOverNormals(const Distribution& d, const F& g) {
  const double ax = d.alphaX(), ay = d.alphaY();
  const auto integrand = [&](double t, double psi) {
    if (t >= 1.0) return 0.0;
    const double r = t / (1.0 - t);
    const double drdt = 1.0 / sqr(1.0 - t);
    const Vec3d slopeNormal(-ax * r * std::cos(psi), -ay * r * std::sin(psi), 1.0);
    const double length = glm::length(slopeNormal);
    const double cos3 = 1.0 / (length * length * length);
    return g(slopeNormal / length) * ax * ay * r * cos3 * drdt;
  };
  QuadratureOptions options;
  options.relativeTolerance = 1e-9;
  options.absoluteTolerance = 1e-13;
  options.minDepth = 4;
  return adaptiveSimpson2D(integrand, 0.0, 1.0, 0.0, 2.0 * Pi, options);
}

// Sample points strictly inside [0, 1)^2, away from the edges where polar maps are singular.
std::vector<Vec2d> interiorGrid(int n) {
  std::vector<Vec2d> points;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) points.emplace_back((i + 0.5) / n, (j + 0.5) / n);
  return points;
}

// Distance on [0, 1) with 0 == 1 (the azimuth wraps).
double wrappedDistance(double a, double b) {
  const double d = std::abs(a - b);
  return std::min(d, 1.0 - d);
}

// |dm/du1 x dm/du2|: the solid angle a sampler maps one unit of [0,1)^2 area to, by central
// differences. A sampler draws density p exactly when p(m(u)) times this equals 1.
template <typename Map> double solidAnglePerUnitSquare(const Map& map, const Vec2d& u, double h) {
  const Vec3d d1 = (map(u + Vec2d(h, 0)) - map(u - Vec2d(h, 0))) / (2 * h);
  const Vec3d d2 = (map(u + Vec2d(0, h)) - map(u - Vec2d(0, h))) / (2 * h);
  return glm::length(glm::cross(d1, d2));
}

template <typename Distribution> class MicrofacetDistributionTest : public ::testing::Test {};
using Distributions = ::testing::Types<GgxDistribution<double>, BeckmannDistribution<double>>;
// No name generator: CTest then names each test by its type,
// "MicrofacetDistributionTest.ProjectedAreaIsNormalised<scatterlab::GgxDistribution<double>>"
// (CMake's GoogleTest discovery reads the type only after a numeric index).
TYPED_TEST_SUITE(MicrofacetDistributionTest, Distributions);

// integral D(m) cos theta_m dm = 1: the microsurface's projected area equals the macrosurface's.
TYPED_TEST(MicrofacetDistributionTest, ProjectedAreaIsNormalised) {
  for (const Roughness& r : Roughnesses) {
    const auto d = makeDistribution<TypeParam>(r);
    const double integral = integrateOverNormals(d, [&](const Vec3d& m) { return d.D(m) * m.z; });
    EXPECT_NEAR(integral, 1.0, 1e-7) << describe(r);
  }
}

// The same integral in plain spherical coordinates (cos theta, phi), for lobes wide enough to
// need no change of variables: checks the slope-plane Jacobian the other tests rely on.
TYPED_TEST(MicrofacetDistributionTest, ProjectedAreaIsNormalisedInSphericalCoordinates) {
  for (const Roughness& r : {Roughness{0.3, 0.3}, Roughness{1.0, 1.0}, Roughness{0.3, 0.8}}) {
    const auto d = makeDistribution<TypeParam>(r);
    const auto integrand = [&](double cosTheta, double phi) {
      return d.D(sphericalDirection(safeSqrt(1.0 - cosTheta * cosTheta), cosTheta, phi)) * cosTheta;
    };
    QuadratureOptions options;
    options.relativeTolerance = 1e-9;
    options.minDepth = 4;
    EXPECT_NEAR(adaptiveSimpson2D(integrand, 0.0, 1.0, -Pi, Pi, options), 1.0, 1e-6) << describe(r);
  }
}

// Heitz 2014 eq. 38: the visible normals' density integrates to 1 for every w.
TYPED_TEST(MicrofacetDistributionTest, VisibleNormalsAreNormalised) {
  for (const Roughness& r : Roughnesses) {
    const auto d = makeDistribution<TypeParam>(r);
    for (const Vec3d& w : incidentDirections()) {
      const double integral = integrateOverNormals(d, [&](const Vec3d& m) { return d.visibleD(w, m); });
      EXPECT_NEAR(integral, 1.0, 1e-6) << describe(r, w);
    }
  }
}

// integral D(m) max(0, w.m) dm = cos theta (1 + Lambda(w)): the projected area of the visible
// microsurface, which is what Smith's Lambda is defined by (Heitz 2014).
TYPED_TEST(MicrofacetDistributionTest, LambdaSatisfiesTheSmithProjectedAreaRelation) {
  for (const Roughness& r : Roughnesses) {
    const auto d = makeDistribution<TypeParam>(r);
    for (const Vec3d& w : incidentDirections()) {
      const double integral =
          integrateOverNormals(d, [&](const Vec3d& m) { return d.D(m) * std::max(0.0, glm::dot(w, m)); });
      const double expected = w.z * (1.0 + d.lambda(w));
      EXPECT_NEAR(integral / expected, 1.0, 1e-6) << describe(r, w);
    }
  }
}

TYPED_TEST(MicrofacetDistributionTest, VisibleSamplingInvertsExactly) {
  for (const Roughness& r : Roughnesses) {
    const auto d = makeDistribution<TypeParam>(r);
    for (const Vec3d& w : incidentDirections()) {
      for (const Vec2d& u : interiorGrid(16)) {
        const Vec2d back = d.invertVisible(w, d.sampleVisible(w, u));
        ASSERT_NEAR(back.x, u.x, 1e-9) << describe(r, w) << " u " << u.x << " " << u.y;
        ASSERT_LT(wrappedDistance(back.y, u.y), 1e-9) << describe(r, w) << " u " << u.x << " " << u.y;
      }
    }
  }
}

TYPED_TEST(MicrofacetDistributionTest, ClassicSamplingInvertsExactly) {
  for (const Roughness& r : Roughnesses) {
    const auto d = makeDistribution<TypeParam>(r);
    for (const Vec2d& u : interiorGrid(16)) {
      const Vec2d back = d.invertClassic(d.sampleClassic(u));
      ASSERT_NEAR(back.x, u.x, 1e-9) << describe(r) << " u " << u.x << " " << u.y;
      ASSERT_LT(wrappedDistance(back.y, u.y), 1e-9) << describe(r) << " u " << u.x << " " << u.y;
    }
  }
}

TYPED_TEST(MicrofacetDistributionTest, SampledNormalsHavePositiveDensity) {
  for (const Roughness& r : Roughnesses) {
    const auto d = makeDistribution<TypeParam>(r);
    for (const Vec2d& u : interiorGrid(32)) {
      const Vec3d classic = d.sampleClassic(u);
      ASSERT_NEAR(glm::length(classic), 1.0, 1e-12);
      ASSERT_GT(d.pdfClassic(classic), 0.0) << describe(r) << " u " << u.x << " " << u.y;
      for (const Vec3d& w : incidentDirections()) {
        const Vec3d visible = d.sampleVisible(w, u);
        ASSERT_NEAR(glm::length(visible), 1.0, 1e-12);
        ASSERT_GT(d.pdfVisible(w, visible), 0.0) << describe(r, w) << " u " << u.x << " " << u.y;
      }
    }
  }
}

// The sampler's own density, |d omega / d u|^-1 from its Jacobian, equals pdfVisible: a
// deterministic check that sampleVisible draws exactly the distribution of visible normals.
TYPED_TEST(MicrofacetDistributionTest, VisibleSamplerJacobianMatchesPdf) {
  for (const Roughness& r : Roughnesses) {
    const auto d = makeDistribution<TypeParam>(r);
    for (const Vec3d& w : incidentDirections()) {
      const auto map = [&](const Vec2d& u) { return d.sampleVisible(w, u); };
      for (const Vec2d& u : interiorGrid(8)) {
        const double product = d.pdfVisible(w, map(u)) * solidAnglePerUnitSquare(map, u, 1e-5);
        ASSERT_NEAR(product, 1.0, 1e-5) << describe(r, w) << " u " << u.x << " " << u.y;
      }
    }
  }
}

TYPED_TEST(MicrofacetDistributionTest, ClassicSamplerJacobianMatchesPdf) {
  for (const Roughness& r : Roughnesses) {
    const auto d = makeDistribution<TypeParam>(r);
    const auto map = [&](const Vec2d& u) { return d.sampleClassic(u); };
    for (const Vec2d& u : interiorGrid(8)) {
      const double product = d.pdfClassic(map(u)) * solidAnglePerUnitSquare(map, u, 1e-5);
      ASSERT_NEAR(product, 1.0, 1e-5) << describe(r) << " u " << u.x << " " << u.y;
    }
  }
}

// Height correlation makes masking and shadowing positively correlated:
// G1(wi) G1(wo) <= G2(wi, wo) <= min(G1(wi), G1(wo)), as 1 + Li + Lo <= (1 + Li)(1 + Lo).
TYPED_TEST(MicrofacetDistributionTest, HeightCorrelatedG2IsBoundedBySeparableForms) {
  for (const Roughness& r : Roughnesses) {
    const auto d = makeDistribution<TypeParam>(r);
    for (const Vec3d& wi : incidentDirections()) {
      for (const Vec3d& wo : incidentDirections()) {
        const double g2 = d.G2(wi, wo), g1i = d.G1(wi), g1o = d.G1(wo);
        EXPECT_LE(g2, std::min(g1i, g1o) * (1.0 + 1e-15)) << describe(r, wi);
        EXPECT_GE(g2, g1i * g1o * (1.0 - 1e-15)) << describe(r, wi);
        EXPECT_EQ(g2, d.G2(wo, wi));
      }
    }
  }
}

TYPED_TEST(MicrofacetDistributionTest, NoMaskingAtThePole) {
  for (const Roughness& r : Roughnesses) {
    const auto d = makeDistribution<TypeParam>(r);
    const Vec3d pole(0, 0, 1);
    EXPECT_EQ(d.lambda(pole), 0.0);
    EXPECT_EQ(d.G1(pole), 1.0);
    EXPECT_EQ(d.G2(pole, pole), 1.0);
  }
}

// At normal incidence D is the peak 1 / (pi ax ay) for both distributions.
TYPED_TEST(MicrofacetDistributionTest, PeakDensityAtTheNormal) {
  for (const Roughness& r : Roughnesses) {
    const auto d = makeDistribution<TypeParam>(r);
    EXPECT_NEAR(d.D(Vec3d(0, 0, 1)) * Pi * r.x * r.y, 1.0, 1e-15);
    EXPECT_EQ(d.D(Vec3d(0.6, 0, -0.8)), 0.0);
    EXPECT_EQ(d.D(Vec3d(1, 0, 0)), 0.0);
  }
}

TYPED_TEST(MicrofacetDistributionTest, FiniteAtGrazingIncidence) {
  for (const Roughness& r : Roughnesses) {
    const auto d = makeDistribution<TypeParam>(r);
    for (const double cosTheta : {1e-4, 1e-8, 1e-12, 0.0}) {
      const Vec3d w(std::sqrt(1.0 - cosTheta * cosTheta) * std::cos(0.3),
                    std::sqrt(1.0 - cosTheta * cosTheta) * std::sin(0.3), cosTheta);
      if (cosTheta > 0) {
        ASSERT_TRUE(std::isfinite(d.lambda(w))) << describe(r, w);
      } else {
        ASSERT_EQ(d.lambda(w), std::numeric_limits<double>::infinity());
      }
      ASSERT_TRUE(std::isfinite(d.G1(w)) && std::isfinite(d.G2(w, w)) && std::isfinite(d.projectedArea(w)));
      ASSERT_GE(d.G1(w), 0.0);
      for (const Vec2d& u : interiorGrid(8)) {
        const Vec3d m = d.sampleVisible(w, u);
        ASSERT_TRUE(isFinite(m)) << describe(r, w);
        ASSERT_TRUE(std::isfinite(d.pdfVisible(w, m))) << describe(r, w);
        ASSERT_TRUE(std::isfinite(d.D(m)));
        const Vec2d back = d.invertVisible(w, m);
        ASSERT_TRUE(std::isfinite(back.x) && std::isfinite(back.y));
      }
    }
  }
}

// Lambda against its textbook forms (Walter et al. 2007 eq. 27 and 34 with the anisotropic
// alpha of Heitz 2014), away from the points where those forms cancel or divide by zero.
TEST(MicrofacetLambda, MatchesTextbookForms) {
  for (const Roughness& r : Roughnesses) {
    for (const double thetaDeg : {10.0, 45.0, 80.0, 89.0}) {
      for (const double phiDeg : {0.0, 30.0, 90.0}) {
        const Vec3d w = directionFromDegrees(thetaDeg, phiDeg);
        const double phi = radians(phiDeg);
        const double alpha = std::sqrt(sqr(r.x * std::cos(phi)) + sqr(r.y * std::sin(phi)));
        const double alphaTan = alpha * std::tan(radians(thetaDeg));
        const double ggx = 0.5 * (std::sqrt(1.0 + alphaTan * alphaTan) - 1.0);
        const double a = 1.0 / alphaTan;
        const double beckmann = 0.5 * (std::erf(a) - 1.0) + std::exp(-a * a) / (2.0 * a * SqrtPi);
        EXPECT_NEAR(GgxDistribution<double>(r.x, r.y).lambda(w), ggx, 1e-12 * std::max(1.0, ggx));
        EXPECT_NEAR(BeckmannDistribution<double>(r.x, r.y).lambda(w), beckmann,
                    1e-12 * std::max(1.0, beckmann));
      }
    }
  }
}

// The evaluation kernels with T = ceres::Jet (the fitter's scalar), differentiated with
// respect to (alphaX, alphaY): same value as double; derivatives finite at the pole, on the
// horizon and at grazing angles, and equal to central differences where the functions are
// smooth.
template <template <typename> class Distribution> void checkJetDerivatives() {
  using Jet = ceres::Jet<double, 2>;
  const double h = 1e-7;
  for (const Roughness& r : Roughnesses) {
    const Distribution<Jet> dj(Jet(r.x, 0), Jet(r.y, 1));
    const Distribution<double> d(r.x, r.y);
    const Distribution<double> dxPlus(r.x + h, r.y), dxMinus(r.x - h, r.y);
    const auto toJet = [](const Vec3d& v) { return Vec3<Jet>(Jet(v.x), Jet(v.y), Jet(v.z)); };
    const Vec3d directions[] = {Vec3d(0, 0, 1), directionFromDegrees(40, 30), directionFromDegrees(89.99, 70),
                                Vec3d(std::cos(1.0), std::sin(1.0), 0.0)};
    const Vec3d m = glm::normalize(Vec3d(0.1 * r.x, -0.05 * r.y, 1.0));
    for (const Vec3d& w : directions) {
      const Jet values[] = {dj.D(toJet(w)), dj.G1(toJet(w)), dj.G2(toJet(w), toJet(directions[1])),
                            dj.visibleD(toJet(w), toJet(m)), dj.projectedArea(toJet(w))};
      const double expected[] = {d.D(w), d.G1(w), d.G2(w, directions[1]), d.visibleD(w, m),
                                 d.projectedArea(w)};
      const double plus[] = {dxPlus.D(w), dxPlus.G1(w), dxPlus.G2(w, directions[1]), dxPlus.visibleD(w, m),
                             dxPlus.projectedArea(w)};
      const double minus[] = {dxMinus.D(w), dxMinus.G1(w), dxMinus.G2(w, directions[1]),
                              dxMinus.visibleD(w, m), dxMinus.projectedArea(w)};
      for (int i = 0; i < 5; ++i) {
        ASSERT_TRUE(ceres::isfinite(values[i])) << "quantity " << i << " " << describe(r, w);
        EXPECT_NEAR(values[i].a, expected[i], 1e-14 * std::max(1.0, std::abs(expected[i])));
        const double finiteDifference = (plus[i] - minus[i]) / (2 * h);
        const double scale = std::max(1.0, std::abs(expected[i]) / r.x);
        if (r.x > 10 * h) {
          EXPECT_NEAR(values[i].v[0], finiteDifference, 1e-5 * scale)
              << "quantity " << i << " " << describe(r, w);
        }
      }
      if (w.z > 0) {
        const Jet lambda = dj.lambda(toJet(w));
        ASSERT_TRUE(ceres::isfinite(lambda));
        EXPECT_NEAR(lambda.a, d.lambda(w), 1e-14 * std::max(1.0, d.lambda(w)));
      }
    }
  }
}

TEST(MicrofacetJet, GgxDerivativesAreFiniteAndCorrect) { checkJetDerivatives<GgxDistribution>(); }
TEST(MicrofacetJet, BeckmannDerivativesAreFiniteAndCorrect) { checkJetDerivatives<BeckmannDistribution>(); }

}  // namespace microfacet_test
}  // namespace scatterlab
