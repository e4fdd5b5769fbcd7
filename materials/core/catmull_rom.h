// Catmull-Rom interpolation of tables: a cubic through each interval with central-difference
// slopes, C1 across nodes, error O(h^3) for smooth data; the value is a fixed linear
// combination of 4 (1-D) or 16 (2-D) node values. On uniform nodes (catmullRom,
// CatmullRomTable2D) and on non-uniform ones (catmullRomWeights, at the end of the file).
//
// On uniform nodes, beyond the ends of a table, the missing neighbour is the quadratic through
// the last three nodes continued one step (p[-1] = 3 p[0] - 3 p[1] + p[2]), so the end
// intervals keep the accuracy of the interior ones.
#pragma once

#include <algorithm>
#include <span>
#include <stdexcept>
#include <vector>

namespace scatterlab {

// The cubic through p1 at t = 0 and p2 at t = 1 with slopes (p2 - p0) / 2 and (p3 - p1) / 2.
inline double catmullRom(double p0, double p1, double p2, double p3, double t) {
  return p1 +
         0.5 * t * (p2 - p0 + t * (2.0 * p0 - 5.0 * p1 + 4.0 * p2 - p3 + t * (3.0 * (p1 - p2) + p3 - p0)));
}

// Values at the nodes (i / (rows - 1), j / (cols - 1)) of [0, 1]^2, row-major; a table with one
// row (or one column) is interpolated along the other coordinate only.
class CatmullRomTable2D {
 public:
  CatmullRomTable2D() = default;
  CatmullRomTable2D(int rows, int cols, std::vector<double> values)
      : rows_(rows), cols_(cols), values_(std::move(values)) {
    if (rows < 1 || cols < 1 || (rows < 3 && rows != 1) || (cols < 3 && cols != 1) ||
        values_.size() != size_t(rows) * size_t(cols))
      throw std::invalid_argument(
          "a Catmull-Rom table needs 1 or at least 3 nodes per axis and rows x cols values");
  }

  int rows() const { return rows_; }
  int cols() const { return cols_; }
  double node(int i, int j) const { return values_[size_t(i) * size_t(cols_) + size_t(j)]; }

  // x along the rows, y along the columns, both clamped to [0, 1].
  double operator()(double x, double y) const {
    const auto [j, ty] = locate(y, cols_);
    if (rows_ == 1) return interpolateRow(0, j, ty);
    const auto [i, tx] = locate(x, rows_);
    double p[4];
    for (int k = 0; k < 4; ++k) p[k] = rowValue(i - 1 + k, j, ty);
    return catmullRom(p[0], p[1], p[2], p[3], tx);
  }

 private:
  // The interval [k, k + 1] holding x in node units, and the position inside it.
  static std::pair<int, double> locate(double x, int n) {
    if (n == 1) return {0, 0.0};
    const double s = std::clamp(x, 0.0, 1.0) * (n - 1);
    const int k = std::min(int(s), n - 2);
    return {k, s - k};
  }
  // Column j of row i, with the phantom columns -1 and cols.
  double at(int i, int j) const {
    if (j < 0) return 3.0 * node(i, 0) - 3.0 * node(i, 1) + node(i, 2);
    if (j >= cols_) return 3.0 * node(i, cols_ - 1) - 3.0 * node(i, cols_ - 2) + node(i, cols_ - 3);
    return node(i, j);
  }
  double interpolateRow(int i, int j, double t) const {
    if (cols_ == 1) return node(i, 0);
    return catmullRom(at(i, j - 1), at(i, j), at(i, j + 1), at(i, j + 2), t);
  }
  // Row i interpolated along y, with the phantom rows -1 and rows.
  double rowValue(int i, int j, double t) const {
    if (i < 0) return 3.0 * interpolateRow(0, j, t) - 3.0 * interpolateRow(1, j, t) + interpolateRow(2, j, t);
    if (i >= rows_)
      return 3.0 * interpolateRow(rows_ - 1, j, t) - 3.0 * interpolateRow(rows_ - 2, j, t) +
             interpolateRow(rows_ - 3, j, t);
    return interpolateRow(i, j, t);
  }

  int rows_ = 0, cols_ = 0;
  std::vector<double> values_;
};

}  // namespace scatterlab

namespace scatterlab {

// Catmull-Rom interpolation on non-uniform nodes (as pbrt-v3's CatmullRomWeights, Pharr,
// Jakob & Humphreys, "Physically Based Rendering", 3rd ed., section 8.6.1): on [x1, x2] the
// cubic Hermite through f1 and f2 whose end slopes are the finite differences
// (f2 - f0) / (x2 - x0) and (f3 - f1) / (x3 - x1), one-sided (f2 - f1) / (x2 - x1) at the ends
// of the table. The value is sum_k weight[k] f[offset + k]; weights of nodes outside the table
// are 0. Tables interpolated this way in one coordinate and evaluated in another (a profile
// per albedo row) stay linear in their node values.
struct CatmullRomWeights {
  int offset = 0;
  double weight[4] = {0, 0, 0, 0};
};

// Needs at least 2 increasing nodes; x is clamped to [nodes.front(), nodes.back()].
inline CatmullRomWeights catmullRomWeights(std::span<const double> nodes, double x) {
  const int n = int(nodes.size());
  if (n < 2) throw std::invalid_argument("catmullRomWeights needs at least two nodes");
  x = std::clamp(x, nodes.front(), nodes.back());
  const int i =
      std::clamp(int(std::upper_bound(nodes.begin(), nodes.end(), x) - nodes.begin()) - 1, 0, n - 2);
  const double x1 = nodes[i], x2 = nodes[i + 1], width = x2 - x1;
  const double t = (x - x1) / width, t2 = t * t, t3 = t2 * t;
  // Hermite basis: value h00 f1 + h01 f2, slopes (in units of t) h10 m1 + h11 m2.
  const double h00 = 2 * t3 - 3 * t2 + 1, h01 = 3 * t2 - 2 * t3, h10 = t3 - 2 * t2 + t, h11 = t3 - t2;
  CatmullRomWeights w;
  w.offset = i - 1;
  w.weight[1] = h00;
  w.weight[2] = h01;
  // m1 = (f2 - f0) width / (x2 - x0), or f2 - f1 at the first interval.
  if (i > 0) {
    const double scale = width / (x2 - nodes[i - 1]);
    w.weight[0] -= h10 * scale;
    w.weight[2] += h10 * scale;
  } else {
    w.weight[1] -= h10;
    w.weight[2] += h10;
  }
  // m2 = (f3 - f1) width / (x3 - x1), or f2 - f1 at the last interval.
  if (i + 2 < n) {
    const double scale = width / (nodes[i + 2] - x1);
    w.weight[3] += h11 * scale;
    w.weight[1] -= h11 * scale;
  } else {
    w.weight[2] += h11;
    w.weight[1] -= h11;
  }
  return w;
}

}  // namespace scatterlab
