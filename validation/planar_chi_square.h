// The 2-D chi-square test of points sampled on a plane (exit points of the probe sampler,
// docs/validation.md section 6) against a density per unit area: polar cells (rings x sectors)
// around the entry point, expected counts N * integral of pdf() over each cell by nested
// adaptive quadrature in (ln rho, phi), and the pooling, statistic and p-value of
// chi_square.h. Ring edges are given by the caller (equal in the radial CDF of the expected
// density, so cells expect similar counts; discontinuities of the density, the probe's r_max
// per channel, on edges). Points beyond the outermost ring fall into one cell whose
// expectation is 0: the outer radius must enclose the density's support.
#pragma once

#include <cmath>
#include <functional>
#include <optional>
#include <vector>

#include "materials/core/math.h"
#include "validation/cell_counts.h"
#include "validation/chi_square.h"

namespace scatterlab {

struct PolarGrid {
  std::vector<double> ringEdges;  // 0 = first < ... < last = outer radius
  int sectors = 32;               // equal angles over (-pi, pi]

  int rings() const { return int(ringEdges.size()) - 1; }
  int cellCount() const { return rings() * sectors + 1; }  // + the cell beyond the outer ring
  int outsideCell() const { return rings() * sectors; }
  int cellIndex(const Vec2d& p) const;
};

struct PlanarChiSquareOptions {
  size_t sampleCount = 1'000'000;
  uint64_t seed = 1;
  double threshold = 0.01;
  double minExpected = 5.0;
};

// Per cell (the outside cell: 0): N * integral over the cell of pdf(p) dA.
std::vector<double> planarExpectedCounts(const std::function<double(const Vec2d&)>& pdf,
                                         const PolarGrid& grid, size_t sampleCount);

// The verdict for counted samples and expected counts (tables laid out rings x sectors, plus
// a last row holding the outside cell).
ChiSquareResult planarChiSquareVerdict(const CellCounts& counts, const std::vector<double>& expected,
                                       const PolarGrid& grid, size_t sampleCount, double threshold,
                                       double minExpected);

// `draw(CounterRng&) -> std::optional<Vec2d>` (a point, or nothing when sampling failed).
template <typename DrawFn>
CellCounts countPlanarSamples(const DrawFn& draw, const PolarGrid& grid, size_t n, uint64_t seed) {
  return countSamples(grid.cellCount(), n, seed, [&](CounterRng& rng) {
    const std::optional<Vec2d> p = draw(rng);
    if (!p) return CellDraw::failed();
    if (!std::isfinite(p->x) || !std::isfinite(p->y)) return CellDraw{-1, "point not finite"};
    return CellDraw{grid.cellIndex(*p), nullptr};
  });
}

template <typename DrawFn>
ChiSquareResult planarChiSquareTest(const DrawFn& draw, const std::function<double(const Vec2d&)>& pdf,
                                    const PolarGrid& grid, const PlanarChiSquareOptions& options) {
  const CellCounts counts = countPlanarSamples(draw, grid, options.sampleCount, options.seed);
  return planarChiSquareVerdict(counts, planarExpectedCounts(pdf, grid, options.sampleCount), grid,
                                options.sampleCount, options.threshold, options.minExpected);
}

}  // namespace scatterlab
