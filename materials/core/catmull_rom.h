// Catmull-Rom interpolation of tables on uniform nodes: a cubic through each interval with
// central-difference slopes, C1 across nodes, error O(h^3) for smooth data; the value is a
// fixed linear combination of 4 (1-D) or 16 (2-D) node values.
//
// Beyond the ends of a table, the missing neighbour is the quadratic through the last three
// nodes continued one step (p[-1] = 3 p[0] - 3 p[1] + p[2]), so the end intervals keep the
// accuracy of the interior ones.
#pragma once

#include <algorithm>
#include <stdexcept>
#include <vector>

namespace scatterlab {

// The cubic through p1 at t = 0 and p2 at t = 1 with slopes (p2 - p0) / 2 and (p3 - p1) / 2.
inline double catmullRom(double p0, double p1, double p2, double p3, double t) {
  return p1 + 0.5 * t * (p2 - p0 + t * (2.0 * p0 - 5.0 * p1 + 4.0 * p2 - p3 + t * (3.0 * (p1 - p2) + p3 - p0)));
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
      throw std::invalid_argument("a Catmull-Rom table needs 1 or at least 3 nodes per axis and rows x cols values");
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
