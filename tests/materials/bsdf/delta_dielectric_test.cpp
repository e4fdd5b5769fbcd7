// The delta dielectrics: the smooth interface (smooth_dielectric.h) and the thin sheet
// (thin_dielectric.h). Formulas at fixed directions against expressions written out here
// (Fresnel in its angle form, Snell's law, the sheet's geometric series), total internal
// reflection, the transport modes, and the whole kit from both sides, where the white
// furnace (importance transport) must give 1.
//
// Negative controls: the kit's four generic controls change pdf(), which is 0 for every
// pair of a delta model, and pass delta samples through unchanged, so the kit must report
// them "not applicable" (asserted below). What can go wrong in a delta sampler, and what
// catches it:
//  - the probability sample() reports differs from the one it draws with: chi-square (the
//    expected count of a delta direction is N times the reported probability);
//  - the radiance scale 1/eta^2 missing, or applied in importance mode: "transport modes"
//    (and the furnace for the latter);
//  - a wrong direction or a wrong, but self-consistent, Fresnel term: nothing statistical
//    can see it (the expectation is placed where the samples land), so the formula tests
//    here are what checks it.
#include <gtest/gtest.h>

#include "catalog_suite.h"
#include "materials/bsdf/smooth_dielectric.h"
#include "materials/bsdf/thin_dielectric.h"
#include "materials/registry/material_file.h"
#include "materials/registry/spec_validation.h"

namespace scatterlab {
namespace delta_dielectric_test {

using nlohmann::json;

// Born & Wolf section 1.5.2: R_s = sin^2(ti - tt) / sin^2(ti + tt),
// R_p = tan^2(ti - tt) / tan^2(ti + tt), unpolarised R = (R_s + R_p) / 2, with Snell's law
// n_i sin ti = n_t sin tt; at normal incidence the limit ((n - 1) / (n + 1))^2.
double fresnelAngleForm(double thetaI, double etaRel) {
  if (thetaI == 0) return std::pow((etaRel - 1) / (etaRel + 1), 2);
  const double sinT = std::sin(thetaI) / etaRel;
  if (sinT >= 1) return 1.0;
  const double thetaT = std::asin(sinT);
  const double rs = std::pow(std::sin(thetaI - thetaT) / std::sin(thetaI + thetaT), 2);
  const double rp = std::pow(std::tan(thetaI - thetaT) / std::tan(thetaI + thetaT), 2);
  return (rs + rp) / 2;
}

// Incident directions from outside (theta < 90) and inside (theta > 90), off the axes.
std::vector<Vec3d> incidentDirections() {
  std::vector<Vec3d> out;
  for (const double theta : {0.0, 20.0, 45.0, 70.0, 89.0, 91.0, 110.0, 135.0, 160.0, 180.0})
    out.push_back(directionFromDegrees(theta, 37.0));
  return out;
}

// Reflection with uLobe -> 0, transmission with uLobe -> 1 (when it exists).
constexpr double FirstLobe = 0.0, LastLobe = 1.0 - 1e-12;

TEST(SmoothDielectric, ReflectanceIsTheFresnelEquations) {
  for (const double eta : {1.1, 1.5, 2.4}) {
    const SmoothDielectricBsdf model(eta);
    for (const Vec3d& wi : incidentDirections()) {
      const double theta = std::acos(std::abs(wi.z));
      const double expected = fresnelAngleForm(theta, wi.z > 0 ? eta : 1 / eta);
      const auto reflected = model.sample(wi, FirstLobe, {0.5, 0.5}, TransportMode::Importance);
      ASSERT_TRUE(reflected.has_value());
      EXPECT_NEAR(reflected->pdf, expected, 1e-13) << "eta " << eta << " wi.z " << wi.z;
      EXPECT_EQ(reflected->lobe, LobeFlags::SpecularReflection);
      EXPECT_EQ(reflected->wo, Vec3d(-wi.x, -wi.y, wi.z));
      EXPECT_EQ(reflected->weight, Rgb(1.0));
    }
  }
}

// Snell: sin(theta_t) = sin(theta_i) / etaRel in the plane of incidence, on the other side,
// azimuth turned by pi; BsdfSample::eta = n(wo) / n(wi).
TEST(SmoothDielectric, RefractionObeysSnellsLawFromBothSides) {
  for (const double eta : {1.1, 1.5, 2.4}) {
    const SmoothDielectricBsdf model(eta);
    for (const Vec3d& wi : incidentDirections()) {
      const double etaRel = wi.z > 0 ? eta : 1 / eta;
      const double sinI = std::sqrt(wi.x * wi.x + wi.y * wi.y);
      if (sinI / etaRel >= 1) continue;  // total internal reflection: the next test
      const auto t = model.sample(wi, LastLobe, {0.5, 0.5}, TransportMode::Importance);
      ASSERT_TRUE(t.has_value());
      ASSERT_EQ(t->lobe, LobeFlags::SpecularTransmission);
      EXPECT_NEAR(glm::length(t->wo), 1.0, 1e-14);
      EXPECT_LT(t->wo.z * wi.z, 0.0);
      EXPECT_NEAR(std::sqrt(t->wo.x * t->wo.x + t->wo.y * t->wo.y), sinI / etaRel, 1e-14);
      if (sinI > 1e-9) {
        EXPECT_NEAR(glm::dot(Vec2d(t->wo), Vec2d(wi)) / sinI, -sinI / etaRel, 1e-14);
      }
      EXPECT_NEAR(t->pdf, 1.0 - fresnelAngleForm(std::acos(std::abs(wi.z)), etaRel), 1e-13);
      EXPECT_DOUBLE_EQ(t->eta, etaRel);
    }
  }
}

// Inside, beyond the critical angle asin(1 / eta), every sample reflects; just before it,
// some refract, grazing.
TEST(SmoothDielectric, TotalInternalReflectionBeyondTheCriticalAngle) {
  const double eta = 1.5, critical = degrees(std::asin(1 / eta));  // 41.81 degrees
  const SmoothDielectricBsdf model(eta);
  const Vec3d beyond = directionFromDegrees(180 - (critical + 0.01), 10);
  EXPECT_EQ(model.reflectance(beyond.z), 1.0);
  for (const double uLobe : {0.0, 0.5, LastLobe}) {
    const auto s = model.sample(beyond, uLobe, {0.5, 0.5});
    ASSERT_TRUE(s.has_value());
    EXPECT_EQ(s->lobe, LobeFlags::SpecularReflection);
    EXPECT_EQ(s->pdf, 1.0);
  }
  const Vec3d before = directionFromDegrees(180 - (critical - 0.01), 10);
  const auto t = model.sample(before, LastLobe, {0.5, 0.5});
  ASSERT_TRUE(t.has_value());
  EXPECT_EQ(t->lobe, LobeFlags::SpecularTransmission);
  EXPECT_GT(t->wo.z, 0.0);
  EXPECT_LT(t->wo.z, 0.1);  // close to the horizon
}

// Veach 1997 section 5.2: importance weight T / T = 1, radiance weight 1 / etaRel^2 through a
// refraction; reflections 1 in both. Radiance "albedo" R + T / etaRel^2 is not 1, which is
// why the kit's energy checks use importance transport.
TEST(SmoothDielectric, RadianceThroughARefractionIsScaledByOneOverEtaSquared) {
  const double eta = 1.5;
  const SmoothDielectricBsdf model(eta);
  for (const double theta : {30.0, 150.0}) {
    const Vec3d wi = directionFromDegrees(theta, 0);
    const double etaRel = wi.z > 0 ? eta : 1 / eta;
    const auto importance = model.sample(wi, LastLobe, {0.5, 0.5}, TransportMode::Importance);
    const auto radiance = model.sample(wi, LastLobe, {0.5, 0.5}, TransportMode::Radiance);
    ASSERT_TRUE(importance && radiance);
    EXPECT_EQ(importance->weight, Rgb(1.0));
    EXPECT_NEAR(radiance->weight.x, 1 / (etaRel * etaRel), 1e-15);
    EXPECT_EQ(radiance->wo, importance->wo);
    const double r = model.reflectance(wi.z);
    const double radianceAlbedo = r + (1 - r) / (etaRel * etaRel);
    EXPECT_GT(std::abs(radianceAlbedo - 1), 0.2) << "radiance is not an energy";
    EXPECT_EQ(model.sample(wi, FirstLobe, {0.5, 0.5}, TransportMode::Radiance)->weight, Rgb(1.0));
  }
}

TEST(SmoothDielectric, DeltaConventionsAndFlags) {
  const SmoothDielectricBsdf model(1.5);
  const Vec3d wi = directionFromDegrees(30, 0);
  const Vec3d mirror(-wi.x, -wi.y, wi.z);
  const Vec3d refracted = model.sample(wi, LastLobe, {0.5, 0.5})->wo;
  for (const Vec3d& wo : {mirror, refracted, Vec3d(0, 0, 1), Vec3d(0, 0, -1)}) {
    EXPECT_EQ(model.eval(wi, wo), Rgb(0.0));
    EXPECT_EQ(model.pdf(wi, wo), 0.0);
  }
  EXPECT_EQ(model.flags(), LobeFlags::SpecularReflection | LobeFlags::SpecularTransmission);
  EXPECT_TRUE(model.isLossless());
  EXPECT_EQ(model.interiorIndex(), 1.5);
  EXPECT_FALSE(model.sample(Vec3d(1, 0, 0), 0.5, {0.5, 0.5}).has_value());  // on the horizon
}

// eta = 1 (which the registry rejects) is an invisible interface: R = 0 (up to rounding,
// 1e-32), straight through.
TEST(SmoothDielectric, IndexMatchedInterfacePassesEverythingStraightThrough) {
  const SmoothDielectricBsdf model(1.0);
  for (const Vec3d& wi : incidentDirections()) {
    if (std::abs(wi.z) < 0.1) continue;
    EXPECT_LT(model.reflectance(wi.z), 1e-30);
    const auto s = model.sample(wi, 1e-20, {0.5, 0.5}, TransportMode::Radiance);
    ASSERT_TRUE(s.has_value());
    EXPECT_EQ(s->lobe, LobeFlags::SpecularTransmission);
    EXPECT_EQ(s->pdf, 1.0);
    EXPECT_NEAR(glm::length(s->wo + wi), 0.0, 1e-15);
    EXPECT_EQ(s->weight, Rgb(1.0));
  }
}

// pbrt-v4's R' = R + T^2 R / (1 - R^2) against the series it sums: R, then T R T, T R^3 T, ...
// (each pass through the sheet's far side reflects R and crosses T), and against the closed
// form 2R / (1 + R) it simplifies to.
TEST(ThinDielectric, ReflectanceSumsTheInternalBounces) {
  for (const double eta : {1.1, 1.5, 2.4}) {
    const ThinDielectricBsdf model(eta);
    for (const double theta : {0.0, 30.0, 60.0, 85.0, 89.9}) {
      const double r = fresnelAngleForm(radians(theta), eta), t = 1 - r;
      double series = r;
      // Summed until the terms vanish (R = 0.995 at 89.9 degrees needs thousands).
      for (double term = t * t * r; term > 1e-18; term *= r * r) series += term;
      for (const double side : {1.0, -1.0}) {
        const Vec3d wi = directionFromDegrees(theta, 15) * Vec3d(1, 1, side);
        EXPECT_NEAR(model.reflectance(wi.z), series, 1e-12) << "eta " << eta << " theta " << theta;
        EXPECT_NEAR(model.reflectance(wi.z), 2 * r / (1 + r), 1e-12);
      }
    }
  }
}

TEST(ThinDielectric, MirrorOrStraightThroughWithWeightOneInBothModes) {
  const ThinDielectricBsdf model(1.5);
  for (const Vec3d& wi : incidentDirections()) {
    if (std::abs(wi.z) < 0.1) continue;
    for (const TransportMode mode : {TransportMode::Radiance, TransportMode::Importance}) {
      const auto r = model.sample(wi, FirstLobe, {0.5, 0.5}, mode);
      const auto t = model.sample(wi, LastLobe, {0.5, 0.5}, mode);
      ASSERT_TRUE(r && t);
      EXPECT_EQ(r->wo, Vec3d(-wi.x, -wi.y, wi.z));
      EXPECT_EQ(t->wo, -wi);
      EXPECT_EQ(r->weight, Rgb(1.0));
      EXPECT_EQ(t->weight, Rgb(1.0));  // the same medium on both sides: no radiance scaling
      EXPECT_EQ(t->eta, 1.0);
      EXPECT_DOUBLE_EQ(r->pdf + t->pdf, 1.0);
      EXPECT_EQ(r->pdf, model.reflectance(wi.z));
    }
  }
  EXPECT_EQ(model.interiorIndex(), 1.0);
  EXPECT_TRUE(model.isLossless());
  EXPECT_EQ(model.eval(directionFromDegrees(30, 0), directionFromDegrees(150, 180)), Rgb(0.0));
}

TEST(DeltaDielectrics, RegistryDefaultsBuildAndEtaOutsideItsRangeIsRejected) {
  for (const char* type : {"dielectric", "thin-dielectric"}) {
    SCOPED_TRACE(type);
    const auto model = makeBsdf({{"type", type}});
    EXPECT_EQ(model->flags(), LobeFlags::SpecularReflection | LobeFlags::SpecularTransmission);
    EXPECT_NO_THROW(makeBsdf({{"type", type}, {"eta", 4.0}}));
    EXPECT_NO_THROW(makeBsdf({{"type", type}, {"eta", 1.0001}}));
    for (const double eta : {1.0, 0.75, 4.5}) {
      try {
        makeBsdf({{"type", type}, {"eta", eta}});
        ADD_FAILURE() << "eta " << eta << " accepted";
      } catch (const MaterialError& error) {
        EXPECT_NE(std::string(error.what()).find("\"eta\""), std::string::npos) << error.what();
        EXPECT_NE(std::string(error.what()).find("in (1, 4]"), std::string::npos) << error.what();
      }
    }
    EXPECT_THROW(makeBsdf({{"type", type}, {"alpha", 0.1}}), MaterialError);
  }
  EXPECT_EQ(makeBsdf({{"type", "dielectric"}})->interiorIndex(), 1.5);
  EXPECT_EQ(makeBsdf({{"type", "thin-dielectric"}})->interiorIndex(), 1.0);
}

TEST(DeltaDielectrics, ExampleFilesBuild) {
  for (const char* file : {"glass-smooth.json", "window-pane-thin.json"}) {
    SCOPED_TRACE(file);
    const auto path = std::filesystem::path(SCATTERLAB_DATA_DIR) / "materials" / file;
    const auto model = makeBsdf(loadMaterialArgument(path.string()));
    EXPECT_TRUE(model->isLossless());
  }
}

// ---- The kit, from both sides ----

// The kit adds 180 - theta: 150 is a refraction from inside, 120 beyond the critical angle
// for every eta here, 90.1 grazing inside.
const std::vector<double> KitAngles{0, 30, 60, 89.9};

struct KitCase {
  const char* type;
  double eta;
};
const std::vector<KitCase> KitCases{{"dielectric", 1.1},
                                    {"dielectric", 1.5},
                                    {"dielectric", 2.4},
                                    {"thin-dielectric", 1.5},
                                    {"thin-dielectric", 2.4}};
std::string name(const KitCase& c) {
  return std::string(c.type == std::string("dielectric") ? "Smooth" : "Thin") + "_eta" +
         catalog_suite::number(c.eta);
}
void PrintTo(const KitCase& c, std::ostream* os) { *os << name(c); }

// The kit cases, plus the two chi-square tests of MissingRadianceScale, whose directions and
// probabilities are right.
const catalog_suite::ChiSquareSuite Suite{"delta-dielectric-kit",
                                          int(KitCases.size() * 2 * KitAngles.size()) + 2};

class DeltaDielectricKit : public ::testing::TestWithParam<KitCase> {};

// Besides every row passing: each angle from either side has a furnace row (importance
// transport; delta weights 1, so R + T = 1 up to the normalisation), and rows exist for
// 180 - theta.
TEST_P(DeltaDielectricKit, PassesEveryCheckAndTheFurnaceFromBothSides) {
  const auto model = makeBsdf({{"type", GetParam().type}, {"eta", GetParam().eta}});
  BsdfCheckOptions o = Suite.options();
  o.wiThetaDeg = KitAngles;
  // Two delta directions per angle: the test is of their two counts (dof 1), for which 2e5
  // samples resolve a probability to 1e-3; the cells only need to keep them apart.
  o.samples = 200'000;
  o.thetaBins = 32;
  o.phiBins = 64;
  const CheckReport report = runBsdfChecks(*model, name(GetParam()), o);
  EXPECT_TRUE(report.passed()) << formatTable(report);
  int furnaceRows = 0;
  for (const CheckRow& row : report.rows) {
    if (row.test != "furnace") continue;
    ++furnaceRows;
    EXPECT_LE(row.statistic, 0.005) << "wi " << *row.wiThetaDeg;
  }
  EXPECT_EQ(furnaceRows, int(2 * KitAngles.size()));
}

INSTANTIATE_TEST_SUITE_P(Grid, DeltaDielectricKit, ::testing::ValuesIn(KitCases),
                         [](const ::testing::TestParamInfo<KitCase>& info) { return name(info.param); });

// ---- Negative controls that apply to delta lobes ----

// Draws the reflection with probability R but reports 1.05 R (and 1 - 1.05 R for the
// refraction): self-consistent weights, normalised probabilities, only the counts are off.
class ClaimedProbabilityOff final : public BsdfModel {
 public:
  explicit ClaimedProbabilityOff(double eta) : model_(eta) {}
  Rgb eval(const Vec3d&, const Vec3d&, TransportMode) const override { return Rgb(0.0); }
  double pdf(const Vec3d&, const Vec3d&, TransportMode) const override { return 0.0; }
  std::optional<BsdfSample> sample(const Vec3d& wi, double uLobe, const Vec2d& u,
                                   TransportMode mode) const override {
    auto s = model_.sample(wi, uLobe, u, mode);
    if (!s) return s;
    const double claimedR = 1.05 * model_.reflectance(wi.z);
    s->pdf = s->lobe == LobeFlags::SpecularReflection ? claimedR : 1 - claimedR;
    return s;
  }
  LobeFlags flags() const override { return model_.flags(); }
  bool isLossless() const override { return true; }
  double interiorIndex() const override { return model_.interiorIndex(); }

 private:
  SmoothDielectricBsdf model_;
};

// The radiance weight without its 1 / etaRel^2.
class RadianceScaleMissing final : public BsdfModel {
 public:
  explicit RadianceScaleMissing(double eta) : model_(eta) {}
  Rgb eval(const Vec3d&, const Vec3d&, TransportMode) const override { return Rgb(0.0); }
  double pdf(const Vec3d&, const Vec3d&, TransportMode) const override { return 0.0; }
  std::optional<BsdfSample> sample(const Vec3d& wi, double uLobe, const Vec2d& u,
                                   TransportMode) const override {
    return model_.sample(wi, uLobe, u, TransportMode::Importance);
  }
  LobeFlags flags() const override { return model_.flags(); }
  bool isLossless() const override { return true; }
  double interiorIndex() const override { return model_.interiorIndex(); }

 private:
  SmoothDielectricBsdf model_;
};

// At normal incidence R = 0.04 (claimed 0.042: 10 sigma at 1e6 samples); from inside at 150
// degrees R = 0.044; at 120 degrees from inside (total internal reflection) the claimed
// probability exceeds 1, which is a hard failure.
TEST(DeltaDielectricControls, ClaimedProbabilityOffIsRejectedByChiSquare) {
  const ClaimedProbabilityOff broken(1.5);
  BsdfCheckOptions o = Suite.options();
  o.wiThetaDeg = {0, 150, 120};
  o.transmissionFromBelow = false;
  o.imageDir.reset();
  const CheckReport report = runBsdfChecks(broken, "claimed probability +5%", o);
  for (const double wi : o.wiThetaDeg) {
    const CheckRow* chi = report.find("chi2", wi);
    ASSERT_NE(chi, nullptr);
    EXPECT_FALSE(chi->passed) << "wi " << wi << ": " << chi->note;
  }
}

TEST(DeltaDielectricControls, MissingRadianceScaleIsCaughtByTheTransportModesRow) {
  const RadianceScaleMissing broken(1.5);
  BsdfCheckOptions o = Suite.options();
  o.wiThetaDeg = {30};
  o.samples = 100000;
  o.imageDir.reset();
  const CheckReport report = runBsdfChecks(broken, "radiance scale missing", o);
  for (const double wi : {30.0, 150.0}) {
    EXPECT_FALSE(report.find("transport modes", wi)->passed) << "wi " << wi;
    EXPECT_TRUE(report.find("chi2", wi)->passed) << "wi " << wi;
    EXPECT_TRUE(report.find("furnace", wi)->passed) << "wi " << wi;
  }
}

// The generic controls cannot apply (module comment): reported, never counted as rejections.
TEST(DeltaDielectricControls, GenericControlsAreReportedNotApplicable) {
  for (const char* type : {"dielectric", "thin-dielectric"}) {
    const json material{{"type", type}};
    const auto model = makeBsdf(material);
    BsdfCheckOptions o = Suite.options();
    o.wiThetaDeg = {45};
    o.samples = 100000;
    o.imageDir.reset();
    const CheckReport report = runNegativeControls(*model, nullptr, type, o);
    ASSERT_EQ(report.rows.size(), 1 + 3 * 2u);  // no lobe width: one row; others at 45 and 135
    for (const CheckRow& row : report.rows) {
      EXPECT_TRUE(row.passed) << row.test;
      EXPECT_EQ(row.note.rfind("not applicable", 0), 0u) << row.test << ": " << row.note;
    }
  }
}

}  // namespace delta_dielectric_test
}  // namespace scatterlab
