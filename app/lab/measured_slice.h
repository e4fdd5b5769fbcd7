// A measured (MERL-layout) table seen as BRDF Explorer shows it: the image slice over
// (theta_h, theta_d) at one phi_d, and f along theta_h at a few theta_d. Values are the
// table's cells as stored (times the channel scales), not interpolated: the report shows the
// measurement, and missing cells stay missing.
#pragma once

#include <filesystem>
#include <vector>

#include "materials/bsdf/bsdf.h"
#include "materials/measured/merl_io.h"

namespace scatterlab {

enum class CellState : unsigned char { Measured, Missing, Unreachable };

struct MeasuredSlice {
  int phiDiffCell = 0;
  double phiDiffDeg = 0;  // the cell's centre
  // Indexed [thetaHalfCell * 90 + thetaDiffCell].
  std::vector<Rgb> value;
  std::vector<CellState> state;

  const Rgb& at(int thetaHalfCell, int thetaDiffCell) const {
    return value[size_t(thetaHalfCell) * 90 + size_t(thetaDiffCell)];
  }
  CellState stateAt(int thetaHalfCell, int thetaDiffCell) const {
    return state[size_t(thetaHalfCell) * 90 + size_t(thetaDiffCell)];
  }
};

// The cells of the phi_d cell that holds `phiDiffDeg` (in [0, 180)).
MeasuredSlice sliceAtPhiDiff(const MerlTable& table, double phiDiffDeg);
// The same cells of a model (a measurement in another format: an RGL file), evaluated at the
// cell centres (phi_h = 0); cells no reflection above the surface reaches are Unreachable.
MeasuredSlice sliceAtPhiDiff(const BsdfModel& model, double phiDiffDeg);

// Cell centres in degrees (theta_h is the non-linear MERL axis).
double thetaHalfCentreDeg(int cell);
double thetaDiffCentreDeg(int cell);
// The theta_d cell whose range holds `thetaDiffDeg`.
int thetaDiffCellAt(double thetaDiffDeg);

// How much of a table is measured: cells whose centre is a reflection above the surface
// (the rest no measurement can reach), and the missing ones (stored negative) among them.
struct TableCoverage {
  size_t reachable = 0, missingReachable = 0, missing = 0;
};
TableCoverage tableCoverage(const MerlTable& table);

struct SliceImageScale {
  double log10Min = 0, log10Max = 0;  // of the luminance, in sr^-1
};

// A PNG of log10 of the cells' luminance: theta_h cells from left to right, theta_d cells from
// the top (theta_d = 0) down, `cellPixels` square pixels per cell, the viridis scale of
// validation/heatmap.h over at most `decades` decades below the brightest cell. Missing cells
// are magenta; cells no reflection above the surface reaches, and zeros, are the bottom of the
// scale. Returns the scale (for the colour bar).
SliceImageScale writeSliceImage(const std::filesystem::path& path, const MeasuredSlice& slice,
                                double decades = 4.0, int cellPixels = 4);

// The colour bar of that scale, left (log10Min) to right (log10Max).
void writeColourBar(const std::filesystem::path& path, int width = 256, int height = 14);

}  // namespace scatterlab
