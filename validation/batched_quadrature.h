// The kit's adaptive quadrature (materials/core/quadrature.h) over many integrals at once, level
// by level, for an integrand that is cheap only in bulk: a BSDF written in Python answers a
// million points in one numpy call in the time it takes to answer a few hundred one by one
// (docs/python.md, "The kit on any object").
//
// adaptiveSimpsonEstimate refines depth first, and each refinement waits for the values of the
// one before it. Here every integral advances one level at a time: the points all of them need
// next are asked for in one call, `evaluate(points, values)`, and the next level is decided from
// the answers. The intervals accepted, the arithmetic and the order of every sum are those of
// the depth-first code (each accepted interval's terms are summed in its left-to-right, depth-
// first order, as the recursion returns them), so the results are the same bit for bit; the
// batched_quadrature tests compare them.
#pragma once

#include <algorithm>
#include <cstdint>
#include <span>
#include <vector>

#include "materials/core/quadrature.h"
#include "validation/chi_square.h"

namespace scatterlab {

// One 1D integral of a batch: f over [a, b] with its own options.
struct BatchedInterval {
  double a = 0.0, b = 0.0;
  QuadratureOptions options;
};

// A point the quadrature asks for: integral `integral` of the batch at x.
struct BatchedPoint {
  uint32_t integral = 0;
  double x = 0.0;
};

namespace detail {

// The refinement tree of every integral of a batch: a node is an interval; a leaf holds the
// interval's accepted estimate and its error term, an inner node the index of its left child (the
// right child follows it).
template <typename V> struct SimpsonTree {
  std::vector<int64_t> firstChild;  // -1: a leaf
  std::vector<V> leafValue, leafError;

  int64_t add() {
    firstChild.push_back(-1);
    leafValue.push_back(V(0.0));
    leafError.push_back(V(0.0));
    return int64_t(firstChild.size()) - 1;
  }
  // The value of a node as adaptiveSimpsonStep returns it: left + right, recursively.
  V value(int64_t node) const {
    const int64_t child = firstChild[size_t(node)];
    return child < 0 ? leafValue[size_t(node)] : value(child) + value(child + 1);
  }
  // adaptiveSimpsonStep's `error = error + |delta| / 15` at each leaf, in depth-first order.
  void addErrors(int64_t node, V& error) const {
    const int64_t child = firstChild[size_t(node)];
    if (child < 0) {
      error = error + leafError[size_t(node)];
      return;
    }
    addErrors(child, error);
    addErrors(child + 1, error);
  }
};

// An interval waiting for the values at its quarter points (adaptiveSimpsonStep's arguments).
template <typename V> struct PendingInterval {
  uint32_t integral;
  int64_t node;
  double a, b;
  V fa, fm, fb, whole;
  double tolerance;
  int depth;
};

}  // namespace detail

// adaptiveSimpsonEstimate of every integral in `integrals`, each with its own options;
// evaluate(std::span<const BatchedPoint>, std::span<V>) fills in f at the points (V a double, a
// glm vector or detail::WithInnerError of one). Results in the integrals' order.
template <typename V, typename Evaluate>
std::vector<QuadratureEstimate<V>> adaptiveSimpsonBatched(std::span<const BatchedInterval> integrals,
                                                          const Evaluate& evaluate) {
  constexpr int MaxPieces = 64;  // as adaptiveSimpsonEstimate
  detail::SimpsonTree<V> tree;
  std::vector<int64_t> firstRoot(integrals.size());
  std::vector<int> pieceCount(integrals.size());
  std::vector<BatchedPoint> points;
  std::vector<V> values;

  // The first level: 2^minDepth equal pieces, their edges and midpoints.
  for (size_t k = 0; k < integrals.size(); ++k) {
    const BatchedInterval& in = integrals[k];
    const int n = std::min(1 << std::max(in.options.minDepth, 0), MaxPieces);
    pieceCount[k] = n;
    const double h = (in.b - in.a) / n;
    for (int i = 0; i <= n; ++i) points.push_back({uint32_t(k), i == n ? in.b : in.a + i * h});
    for (int i = 0; i < n; ++i) points.push_back({uint32_t(k), in.a + (i + 0.5) * h});
  }
  values.assign(points.size(), V(0.0));
  evaluate(std::span<const BatchedPoint>(points), std::span<V>(values));
  std::vector<detail::PendingInterval<V>> pending, next;
  std::vector<V> piece;
  size_t offset = 0;
  for (size_t k = 0; k < integrals.size(); ++k) {
    const BatchedInterval& in = integrals[k];
    const int n = pieceCount[k];
    const double h = (in.b - in.a) / n;
    const V* fx = values.data() + offset;
    const V* fmid = fx + n + 1;
    offset += size_t(2 * n + 1);
    V coarse = V(0.0);
    piece.assign(size_t(n), V(0.0));
    for (int i = 0; i < n; ++i) {
      piece[size_t(i)] = (h / 6.0) * (fx[i] + 4.0 * fmid[i] + fx[i + 1]);
      coarse = coarse + piece[size_t(i)];
    }
    const double tolerance =
        std::max(in.options.relativeTolerance * quadratureErrorNorm(coarse), in.options.absoluteTolerance) /
        n;
    firstRoot[k] = int64_t(tree.firstChild.size());
    for (int i = 0; i < n; ++i) {
      const double x0 = in.a + i * h, x1 = (i + 1 == n) ? in.b : in.a + (i + 1) * h;
      pending.push_back({uint32_t(k), tree.add(), x0, x1, fx[i], fmid[i], fx[i + 1], piece[size_t(i)],
                         tolerance, in.options.minDepth});
    }
  }

  // One level at a time: the quarter points of every pending interval, then accept or split each.
  while (!pending.empty()) {
    points.clear();
    for (const detail::PendingInterval<V>& p : pending) {
      const double m = 0.5 * (p.a + p.b);
      points.push_back({p.integral, 0.5 * (p.a + m)});
      points.push_back({p.integral, 0.5 * (m + p.b)});
    }
    values.assign(points.size(), V(0.0));
    evaluate(std::span<const BatchedPoint>(points), std::span<V>(values));
    next.clear();
    for (size_t i = 0; i < pending.size(); ++i) {
      const detail::PendingInterval<V>& p = pending[i];
      const QuadratureOptions& options = integrals[p.integral].options;
      const double m = 0.5 * (p.a + p.b);
      const V& flm = values[2 * i];
      const V& frm = values[2 * i + 1];
      const V left = ((m - p.a) / 6.0) * (p.fa + 4.0 * flm + p.fm);
      const V right = ((p.b - m) / 6.0) * (p.fm + 4.0 * frm + p.fb);
      const V delta = left + right - p.whole;
      if (p.depth >= options.maxDepth || quadratureErrorNorm(delta) <= 15.0 * p.tolerance) {
        tree.leafValue[size_t(p.node)] = left + right + delta / 15.0;
        tree.leafError[size_t(p.node)] = quadratureAbs(delta) / 15.0;
        continue;
      }
      const int64_t leftNode = tree.add();
      tree.add();
      tree.firstChild[size_t(p.node)] = leftNode;
      const double half = 0.5 * p.tolerance;
      next.push_back({p.integral, leftNode, p.a, m, p.fa, flm, p.fm, left, half, p.depth + 1});
      next.push_back({p.integral, leftNode + 1, m, p.b, p.fm, frm, p.fb, right, half, p.depth + 1});
    }
    std::swap(pending, next);
  }

  // The sums, in the depth-first code's order.
  std::vector<QuadratureEstimate<V>> result(integrals.size(), QuadratureEstimate<V>{V(0.0), V(0.0)});
  for (size_t k = 0; k < integrals.size(); ++k)
    for (int i = 0; i < pieceCount[k]; ++i) {
      const int64_t root = firstRoot[k] + i;
      result[k].value = result[k].value + tree.value(root);
      tree.addErrors(root, result[k].error);
    }
  return result;
}

// One 2D integral of a batch: f(x, y) over [x0, x1] x [y0, y1].
struct BatchedRectangle {
  double x0 = 0.0, x1 = 0.0, y0 = 0.0, y1 = 0.0;
};

// adaptiveSimpson2DEstimate of every rectangle, all with `options`;
// evaluate(std::span<const Vec2d> xy, std::span<V> values) fills in f at the points.
template <typename V, typename Evaluate>
std::vector<QuadratureEstimate<V>> adaptiveSimpson2DBatched(std::span<const BatchedRectangle> rectangles,
                                                            const QuadratureOptions& options,
                                                            const Evaluate& evaluate) {
  using Inner = detail::WithInnerError<V>;
  std::vector<BatchedInterval> outer(rectangles.size());
  for (size_t r = 0; r < rectangles.size(); ++r) outer[r] = {rectangles[r].x0, rectangles[r].x1, options};
  // The outer quadrature's values are inner quadratures over y, all of one level at once.
  const auto integrateY = [&](std::span<const BatchedPoint> xs, std::span<Inner> out) {
    std::vector<BatchedInterval> inner(xs.size());
    for (size_t i = 0; i < xs.size(); ++i) {
      const BatchedRectangle& rect = rectangles[xs[i].integral];
      QuadratureOptions innerOptions = options;
      innerOptions.absoluteTolerance = options.absoluteTolerance / std::max(rect.x1 - rect.x0, 1e-300) * 0.1;
      inner[i] = {rect.y0, rect.y1, innerOptions};
    }
    std::vector<Vec2d> xy;
    const auto atXY = [&](std::span<const BatchedPoint> ys, std::span<V> values) {
      xy.resize(ys.size());
      for (size_t j = 0; j < ys.size(); ++j) xy[j] = Vec2d(xs[ys[j].integral].x, ys[j].x);
      evaluate(std::span<const Vec2d>(xy), values);
    };
    const std::vector<QuadratureEstimate<V>> integrals =
        adaptiveSimpsonBatched<V>(std::span<const BatchedInterval>(inner), atXY);
    for (size_t i = 0; i < xs.size(); ++i) out[i] = Inner(integrals[i].value, integrals[i].error);
  };
  const std::vector<QuadratureEstimate<Inner>> integrals =
      adaptiveSimpsonBatched<Inner>(std::span<const BatchedInterval>(outer), integrateY);
  std::vector<QuadratureEstimate<V>> result(rectangles.size(), QuadratureEstimate<V>{V(0.0), V(0.0)});
  for (size_t r = 0; r < rectangles.size(); ++r)
    result[r] = {integrals[r].value.value,
                 integrals[r].error.value + quadratureAbs(integrals[r].value.innerError)};
  return result;
}

// integrateCellsWithError (chi_square.h), the same numbers, with the integrand's values asked for
// in batches: evaluate(std::span<const Vec3d> directions, std::span<V> values). Cells are taken
// `cellsPerBatch` at a time, which bounds the memory the refinement trees hold.
template <typename V, typename Evaluate>
CellIntegrals<V> integrateCellsInBatches(const SphericalGrid& grid, const Evaluate& evaluate,
                                         const std::vector<Vec2d>& probes, const QuadratureOptions& options,
                                         int cellsPerBatch = 2048) {
  CellIntegrals<V> result(grid.cellCount());
  std::vector<Vec3d> directions;
  const auto atDirections = [&](std::span<const Vec2d> cosThetaPhi, std::span<V> values) {
    directions.resize(cosThetaPhi.size());
    for (size_t i = 0; i < cosThetaPhi.size(); ++i)
      directions[i] = SphericalGrid::direction(cosThetaPhi[i].x, cosThetaPhi[i].y);
    evaluate(std::span<const Vec3d>(directions), values);
  };
  for (int first = 0; first < grid.cellCount(); first += cellsPerBatch) {
    const int last = std::min(grid.cellCount(), first + cellsPerBatch);
    std::vector<BatchedRectangle> rectangles;
    std::vector<int> pieceCell;
    for (int cell = first; cell < last; ++cell) {
      const CellPieces pieces = cellPieces(grid, cell, probes.empty() ? Vec2d(NAN) : probes[size_t(cell)]);
      for (int k = 0; k < pieces.count; ++k) {
        const CellPiece& p = pieces.pieces[k];
        rectangles.push_back({p.cosLo, p.cosHi, p.phiLo, p.phiHi});
        pieceCell.push_back(cell);
      }
    }
    const std::vector<QuadratureEstimate<V>> integrals =
        adaptiveSimpson2DBatched<V>(std::span<const BatchedRectangle>(rectangles), options, atDirections);
    // A cell's pieces are consecutive and in cellPieces' order: summed as integrateCellsWithError does.
    for (size_t k = 0; k < integrals.size(); ++k) {
      const size_t cell = size_t(pieceCell[k]);
      result.values[cell] = result.values[cell] + integrals[k].value;
      result.errors[cell] = result.errors[cell] + integrals[k].error;
    }
  }
  return result;
}

}  // namespace scatterlab
