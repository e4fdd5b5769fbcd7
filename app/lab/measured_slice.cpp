#include "app/lab/measured_slice.h"

#include <algorithm>
#include <cmath>

#include "app/lab/lobe_curves.h"
#include "materials/measured/half_diff.h"
#include "materials/measured/merl_format.h"
#include "materials/measured/tabulated_brdf.h"
#include "validation/heatmap.h"

namespace scatterlab {

double thetaHalfCentreDeg(int cell) { return merl::thetaHalfAt(cell + 0.5) * 180.0 / Pi; }
double thetaDiffCentreDeg(int cell) { return merl::thetaDiffAt(cell + 0.5) * 180.0 / Pi; }
int thetaDiffCellAt(double thetaDiffDeg) { return merl::thetaDiffCell(thetaDiffDeg * Pi / 180.0); }

MeasuredSlice sliceAtPhiDiff(const MerlTable& table, double phiDiffDeg) {
  MeasuredSlice slice;
  slice.phiDiffCell = merl::clampCell(merl::phiDiffCoordinate(phiDiffDeg * Pi / 180.0), merl::PhiDiffCells);
  slice.phiDiffDeg = merl::phiDiffAt(slice.phiDiffCell + 0.5) * 180.0 / Pi;
  slice.value.resize(size_t(merl::ThetaHalfCells) * merl::ThetaDiffCells);
  slice.state.resize(slice.value.size());
  for (int h = 0; h < merl::ThetaHalfCells; ++h)
    for (int d = 0; d < merl::ThetaDiffCells; ++d) {
      const size_t cell = merl::cellIndex(h, d, slice.phiDiffCell);
      const size_t k = size_t(h) * merl::ThetaDiffCells + size_t(d);
      slice.state[k] = table.isMissing(cell)    ? CellState::Missing
                       : !isReachableCell(cell) ? CellState::Unreachable
                                                : CellState::Measured;
      slice.value[k] = slice.state[k] == CellState::Measured ? table.rgb(cell) : Rgb(0.0);
    }
  return slice;
}

MeasuredSlice sliceAtPhiDiff(const BsdfModel& model, double phiDiffDeg) {
  MeasuredSlice slice;
  slice.phiDiffCell = merl::clampCell(merl::phiDiffCoordinate(phiDiffDeg * Pi / 180.0), merl::PhiDiffCells);
  slice.phiDiffDeg = merl::phiDiffAt(slice.phiDiffCell + 0.5) * 180.0 / Pi;
  slice.value.resize(size_t(merl::ThetaHalfCells) * merl::ThetaDiffCells);
  slice.state.resize(slice.value.size());
  const double phiDiff = merl::phiDiffAt(slice.phiDiffCell + 0.5);
  for (int h = 0; h < merl::ThetaHalfCells; ++h)
    for (int d = 0; d < merl::ThetaDiffCells; ++d) {
      const size_t k = size_t(h) * merl::ThetaDiffCells + size_t(d);
      const auto [wi, wo] =
          directionsFromHalfDiff(merl::thetaHalfAt(h + 0.5), 0.0, merl::thetaDiffAt(d + 0.5), phiDiff);
      const bool reachable = wi.z > 0 && wo.z > 0;
      slice.state[k] = reachable ? CellState::Measured : CellState::Unreachable;
      slice.value[k] = reachable ? model.eval(wi, wo) : Rgb(0.0);
    }
  return slice;
}

TableCoverage tableCoverage(const MerlTable& table) {
  TableCoverage coverage;
  for (size_t cell = 0; cell < merl::CellCount; ++cell) {
    const bool missing = table.isMissing(cell);
    coverage.missing += missing ? 1 : 0;
    if (isReachableCell(cell)) {
      ++coverage.reachable;
      coverage.missingReachable += missing ? 1 : 0;
    }
  }
  return coverage;
}

SliceImageScale writeSliceImage(const std::filesystem::path& path, const MeasuredSlice& slice, double decades,
                                int cellPixels) {
  SliceImageScale scale{0, -INFINITY};
  for (size_t k = 0; k < slice.value.size(); ++k) {
    const double y = rec709Luminance(slice.value[k]);
    if (slice.state[k] == CellState::Measured && y > 0)
      scale.log10Max = std::max(scale.log10Max, std::log10(y));
  }
  if (!std::isfinite(scale.log10Max)) scale.log10Max = 0;  // nothing measured: any scale will do
  scale.log10Min = scale.log10Max - decades;
  Table2D image(merl::ThetaDiffCells, merl::ThetaHalfCells);
  for (int h = 0; h < merl::ThetaHalfCells; ++h)
    for (int d = 0; d < merl::ThetaDiffCells; ++d) {
      // writeHeatmapPng puts the last row at the top: theta_d = 0 goes there.
      double& pixel = image(merl::ThetaDiffCells - 1 - d, h);
      const double y = rec709Luminance(slice.at(h, d));
      switch (slice.stateAt(h, d)) {
        case CellState::Missing: pixel = NAN; break;  // magenta
        case CellState::Unreachable: pixel = 0.0; break;
        case CellState::Measured: pixel = y > 0 ? std::max(std::log10(y) - scale.log10Min, 0.0) : 0.0; break;
      }
    }
  writeHeatmapPng(path, image, HeatmapScale::Sequential, decades, cellPixels);
  return scale;
}

void writeColourBar(const std::filesystem::path& path, int width, int height) {
  Table2D bar(height, width);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) bar(y, x) = (x + 0.5) / width;
  writeHeatmapPng(path, bar, HeatmapScale::Sequential, 1.0, 1);
}

}  // namespace scatterlab
