// The chi-square domain for directions: the whole sphere parameterised by (cos theta, phi)
// in [-1, 1] x [-pi, pi]. The map is equal-area, so a cell's solid angle is its area in
// these coordinates (docs/validation.md section 1).
#pragma once

#include <vector>

#include "materials/core/spherical.h"

namespace scatterlab {

struct SphericalGrid {
  int thetaBins = 64;  // rows: cos(theta) from -1 (row 0) to 1
  int phiBins = 128;   // columns: phi from -pi to pi

  int cellCount() const { return thetaBins * phiBins; }
  double cosThetaEdge(int row) const { return -1.0 + 2.0 * row / thetaBins; }
  double phiEdge(int col) const { return -Pi + 2.0 * Pi * col / phiBins; }
  double cellSolidAngle() const { return 4.0 * Pi / cellCount(); }

  int row(double cosTheta) const {
    return clampBin(int(std::floor((cosTheta + 1.0) * 0.5 * thetaBins)), thetaBins);
  }
  int col(double phi) const { return clampBin(int(std::floor((phi + Pi) / (2.0 * Pi) * phiBins)), phiBins); }
  int cellIndex(const Vec3d& w) const { return row(w.z) * phiBins + col(std::atan2(w.y, w.x)); }

  static Vec3d direction(double cosTheta, double phi) {
    const double sinTheta = safeSqrt(1.0 - cosTheta * cosTheta);
    return {sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta};
  }

 private:
  static int clampBin(int i, int n) { return i < 0 ? 0 : (i >= n ? n - 1 : i); }
};

// A row-major table over the grid's cells (rows = cos theta, columns = phi).
struct Table2D {
  int rows = 0, cols = 0;
  std::vector<double> values;

  Table2D() = default;
  Table2D(int rows_, int cols_, double fill = 0.0)
      : rows(rows_), cols(cols_), values(size_t(rows_) * cols_, fill) {}
  double& operator()(int r, int c) { return values[size_t(r) * cols + c]; }
  double operator()(int r, int c) const { return values[size_t(r) * cols + c]; }
  double sum() const {
    double s = 0;
    for (double v : values) s += v;
    return s;
  }
};

}  // namespace scatterlab
