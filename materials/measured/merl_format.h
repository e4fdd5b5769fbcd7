// The MERL BRDF layout (Matusik, Pfister, Brand & McMillan 2003, "A Data-Driven Reflectance
// Model", SIGGRAPH; the database's reference reader BRDFRead.cpp): an isotropic BRDF
// tabulated over Rusinkiewicz's (theta_h, theta_d, phi_d) in 90 x 90 x 180 cells.
//  - theta_h is non-linear, dense next to the highlight: cell i covers
//    theta_h in [(i/90)^2, ((i+1)/90)^2) x pi/2, i.e. the cell index coordinate is
//    sqrt(theta_h / (pi/2)) * 90;
//  - theta_d is linear over [0, pi/2); phi_d is linear over [0, pi), folded there by
//    reciprocity (phi_d < 0: add pi);
//  - index = phi_d cell + 180 theta_d cell + 180 * 90 theta_h cell (phi_d fastest);
//  - value = stored * channel scale (R 1/1500, G 1.15/1500, B 1.66/1500); stored < 0 marks
//    a missing measurement.
// The file: int32 (90, 90, 180), then 3 x 1,458,000 float64, all red, all green, all blue,
// little-endian; 34,992,012 bytes.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

#include "materials/core/math.h"

namespace scatterlab::merl {

inline constexpr int ThetaHalfCells = 90;
inline constexpr int ThetaDiffCells = 90;
inline constexpr int PhiDiffCells = 180;
inline constexpr size_t CellCount = size_t(ThetaHalfCells) * ThetaDiffCells * PhiDiffCells;  // 1,458,000
inline constexpr size_t HeaderBytes = 3 * 4;
inline constexpr size_t FileBytes = HeaderBytes + 3 * CellCount * sizeof(double);  // 34,992,012
inline constexpr std::array<double, 3> ChannelScale{1.0 / 1500.0, 1.15 / 1500.0, 1.66 / 1500.0};
inline constexpr double MissingValue = -1.0;  // what MERL stores for a missing measurement

inline constexpr size_t cellIndex(int thetaHalfCell, int thetaDiffCell, int phiDiffCell) {
  return size_t(phiDiffCell) +
         size_t(PhiDiffCells) * (size_t(thetaDiffCell) + size_t(ThetaDiffCells) * size_t(thetaHalfCell));
}

struct CellCoordinates {
  int thetaHalf, thetaDiff, phiDiff;
};
inline constexpr CellCoordinates cellCoordinates(size_t index) {
  return {int(index / (size_t(PhiDiffCells) * ThetaDiffCells)), int(index / PhiDiffCells % ThetaDiffCells),
          int(index % PhiDiffCells)};
}

// Continuous cell-index coordinates: cell i covers [i, i + 1), its centre is i + 0.5.
inline double thetaHalfCoordinate(double thetaHalf) {
  return std::sqrt(std::max(thetaHalf, 0.0) / PiOver2) * ThetaHalfCells;
}
inline double thetaDiffCoordinate(double thetaDiff) {
  return std::max(thetaDiff, 0.0) / PiOver2 * ThetaDiffCells;
}
// phi_d in (-pi, pi], folded to [0, pi] by reciprocity.
inline double foldPhiDiff(double phiDiff) { return phiDiff < 0 ? phiDiff + Pi : phiDiff; }
inline double phiDiffCoordinate(double foldedPhiDiff) { return foldedPhiDiff / Pi * PhiDiffCells; }

// The reference reader's cells: floor of the coordinate, clamped to the last cell (atan2 can
// return exactly pi, and theta_d exactly pi/2).
inline int clampCell(double coordinate, int cells) {
  return coordinate < 1.0 ? 0 : std::min(int(coordinate), cells - 1);
}
inline int thetaHalfCell(double thetaHalf) {
  return clampCell(thetaHalfCoordinate(thetaHalf), ThetaHalfCells);
}
inline int thetaDiffCell(double thetaDiff) {
  return clampCell(thetaDiffCoordinate(thetaDiff), ThetaDiffCells);
}
inline int phiDiffCell(double phiDiff) {
  return clampCell(phiDiffCoordinate(foldPhiDiff(phiDiff)), PhiDiffCells);
}

// Angles of a cell coordinate (the inverses of the maps above); cell i's lower edge is at
// coordinate i, its centre at i + 0.5.
inline double thetaHalfAt(double coordinate) { return sqr(coordinate / ThetaHalfCells) * PiOver2; }
inline double thetaDiffAt(double coordinate) { return coordinate / ThetaDiffCells * PiOver2; }
inline double phiDiffAt(double coordinate) { return coordinate / PhiDiffCells * Pi; }

}  // namespace scatterlab::merl
