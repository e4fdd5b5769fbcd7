// The numbers behind the report's plots: lobes in the plane of incidence, the directional
// albedo curve, and slices of a MERL table, each against a closed form or the table itself.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "app/lab/albedo_curve.h"
#include "app/lab/lobe_curves.h"
#include "app/lab/measured_slice.h"
#include "cli_runner.h"
#include "materials/measured/merl_format.h"
#include "materials/measured/tabulated_brdf.h"
#include "materials/registry/spec_validation.h"

namespace scatterlab {
namespace lab_report_curves_test {

using nlohmann::json;

TEST(LobeCurves, LambertianIsFlatAtAlbedoOverPi) {
  const auto model = makeBsdf(json{{"type", "lambertian"}, {"albedo", 0.6}});
  const LobeCurve curve = lobeInPlaneOfIncidence(*model, 40.0, 30.0, 181);
  ASSERT_EQ(curve.thetaOutDeg.size(), 181u);
  EXPECT_DOUBLE_EQ(curve.thetaOutDeg.front(), -90.0);
  EXPECT_DOUBLE_EQ(curve.thetaOutDeg.back(), 90.0);
  // Both ends lie on the horizon, where f of a reflection is 0 or 0.6/pi: only the interior is checked.
  for (size_t k = 1; k + 1 < curve.value.size(); ++k) EXPECT_NEAR(curve.value[k].x, 0.6 / Pi, 1e-12) << k;
}

TEST(LobeCurves, ANarrowConductorPeaksAtTheMirrorDirection) {
  const auto model = makeBsdf(json{{"type", "conductor"}, {"alpha", 0.05}, {"metal", "Ag"}});
  // A 0.5 degree step: the peak is the sample nearest t = theta_i on the far side.
  const LobeCurve curve = lobeInPlaneOfIncidence(*model, 35.0, 30.0, 361);
  size_t peak = 0;
  for (size_t k = 0; k < curve.value.size(); ++k)
    if (rec709Luminance(curve.value[k]) > rec709Luminance(curve.value[peak])) peak = k;
  EXPECT_NEAR(curve.thetaOutDeg[peak], 35.0, 0.5);
}

TEST(LobeCurves, TransmissionCoversTheWholeCircle) {
  const auto model = makeBsdf(json{{"type", "rough-dielectric"}, {"alpha", 0.2}, {"eta", 1.5}});
  const LobeCurve curve = lobeInPlaneOfIncidence(*model, 30.0, 0.0, 361);
  EXPECT_DOUBLE_EQ(curve.thetaOutDeg.front(), -180.0);
  EXPECT_DOUBLE_EQ(curve.thetaOutDeg.back(), 180.0);
  // Refraction at eta 1.5: sin 30 = 1.5 sin t' puts the transmitted peak near 180 - 19.5 degrees.
  size_t peak = 0;
  for (size_t k = 0; k < curve.value.size(); ++k)
    if (std::abs(curve.thetaOutDeg[k]) > 90 &&
        rec709Luminance(curve.value[k]) > rec709Luminance(curve.value[peak]))
      peak = k;
  EXPECT_NEAR(curve.thetaOutDeg[peak], 180.0 - std::asin(0.5 / 1.5) * 180.0 / Pi, 2.0);
}

TEST(AlbedoCurve, LambertianReflectsItsAlbedoAtEveryAngle) {
  const auto model = makeBsdf(json{{"type", "lambertian"}, {"albedo", {0.2, 0.5, 0.8}}});
  const std::vector<AlbedoPoint> curve = directionalAlbedoCurve(*model, {0, 45, 89}, AlbedoCurveOptions{});
  ASSERT_EQ(curve.size(), 3u);
  // The quadrature's requested accuracy is 1e-4 relative per cell.
  for (const AlbedoPoint& p : curve) {
    EXPECT_NEAR(p.albedo.x, 0.2, 1e-4 * 0.2) << p.thetaDeg;
    EXPECT_NEAR(p.albedo.y, 0.5, 1e-4 * 0.5) << p.thetaDeg;
    EXPECT_NEAR(p.albedo.z, 0.8, 1e-4 * 0.8) << p.thetaDeg;
  }
}

TEST(AlbedoCurve, DeltaLobesCountTheirWeight) {
  // A perfect mirror (k huge: F = 1 to round-off) reflects everything along its delta lobe.
  const auto model = makeBsdf(json{{"type", "smooth-conductor"}, {"eta", 1.0}, {"k", 1e8}});
  for (const AlbedoPoint& p : directionalAlbedoCurve(*model, {0, 60}, AlbedoCurveOptions{}))
    EXPECT_NEAR(p.albedo.y, 1.0, 1e-6) << p.thetaDeg;
}

// A table whose cell values say where they are: f = 1 + theta_h cell + 0.01 theta_d cell.
MerlTable indexedTable() {
  MerlTable table;
  for (size_t cell = 0; cell < merl::CellCount; ++cell) {
    const auto c = merl::cellCoordinates(cell);
    table.setRgb(cell, Rgb(1.0 + c.thetaHalf + 0.01 * c.thetaDiff));
  }
  return table;
}

TEST(MeasuredSlice, HoldsTheTablesCellsAtTheChosenPhiDiff) {
  MerlTable table = indexedTable();
  table.setMissing(merl::cellIndex(3, 4, 90));
  const MeasuredSlice slice = sliceAtPhiDiff(table, 90.0);
  EXPECT_EQ(slice.phiDiffCell, 90);
  EXPECT_DOUBLE_EQ(slice.phiDiffDeg, 90.5);
  EXPECT_EQ(slice.stateAt(3, 4), CellState::Missing);
  EXPECT_EQ(slice.stateAt(10, 20), CellState::Measured);
  EXPECT_NEAR(slice.at(10, 20).x, 1.0 + 10 + 0.2, 1e-9);
  // Cells whose centre is no reflection above the surface are told apart from missing ones.
  for (int h = 0; h < merl::ThetaHalfCells; ++h) {
    for (int d = 0; d < merl::ThetaDiffCells; ++d) {
      if (h == 3 && d == 4) continue;
      EXPECT_EQ(slice.stateAt(h, d) == CellState::Unreachable, !isReachableCell(merl::cellIndex(h, d, 90)))
          << h << " " << d;
    }
  }
  EXPECT_EQ(slice.stateAt(10, 20), CellState::Measured);
  EXPECT_EQ(sliceAtPhiDiff(table, 0.0).stateAt(89, 89), CellState::Unreachable);
}

TEST(MeasuredSlice, CoverageCountsMissingCellsAmongTheReachable) {
  MerlTable table = indexedTable();
  const TableCoverage full = tableCoverage(table);
  EXPECT_EQ(full.missing, 0u);
  EXPECT_EQ(full.missingReachable, 0u);
  EXPECT_GT(full.reachable, merl::CellCount / 2);
  EXPECT_LT(full.reachable, merl::CellCount);
  for (size_t cell = 0; cell < merl::CellCount; ++cell)
    if (!isReachableCell(cell)) table.setMissing(cell);
  const TableCoverage cut = tableCoverage(table);
  EXPECT_EQ(cut.missing, merl::CellCount - full.reachable);
  EXPECT_EQ(cut.missingReachable, 0u);
}

TEST(MeasuredSlice, ImageHasCellPixelsPerCellAndTheBrightestCellsScale) {
  const MeasuredSlice slice = sliceAtPhiDiff(indexedTable(), 90.0);
  const auto path = cli_runner::uniquePath("slice") += ".png";
  const SliceImageScale scale = writeSliceImage(path, slice, 4.0, 2);
  // The brightest measured cell (grey, so its luminance is its value) sets the top of the scale.
  double brightest = 0;
  for (int h = 0; h < merl::ThetaHalfCells; ++h)
    for (int d = 0; d < merl::ThetaDiffCells; ++d)
      if (slice.stateAt(h, d) == CellState::Measured) brightest = std::max(brightest, slice.at(h, d).x);
  EXPECT_GT(brightest, 80.0);
  EXPECT_NEAR(scale.log10Max, std::log10(brightest), 1e-12);
  EXPECT_DOUBLE_EQ(scale.log10Min, scale.log10Max - 4.0);
  // The PNG header: width and height are big-endian at bytes 16 and 20.
  std::ifstream file(path, std::ios::binary);
  unsigned char header[24];
  file.read(reinterpret_cast<char*>(header), sizeof header);
  ASSERT_TRUE(file.good());
  const auto be32 = [&](int at) {
    return (header[at] << 24) | (header[at + 1] << 16) | (header[at + 2] << 8) | header[at + 3];
  };
  EXPECT_EQ(be32(16), 180);
  EXPECT_EQ(be32(20), 180);
}

}  // namespace lab_report_curves_test
}  // namespace scatterlab
