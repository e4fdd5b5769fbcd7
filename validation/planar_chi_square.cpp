#include "validation/planar_chi_square.h"

#include <algorithm>

#include <tbb/parallel_for.h>

#include "materials/core/quadrature.h"

namespace scatterlab {

int PolarGrid::cellIndex(const Vec2d& p) const {
  const double rho = std::hypot(p.x, p.y);
  if (!(rho < ringEdges.back())) return outsideCell();
  const int ring = std::clamp(
      int(std::upper_bound(ringEdges.begin(), ringEdges.end(), rho) - ringEdges.begin()) - 1, 0, rings() - 1);
  const double phi = std::atan2(p.y, p.x);
  const int sector = std::clamp(int(std::floor((phi + Pi) / (2.0 * Pi) * sectors)), 0, sectors - 1);
  return ring * sectors + sector;
}

std::vector<double> planarExpectedCounts(const std::function<double(const Vec2d&)>& pdf,
                                         const PolarGrid& grid, size_t sampleCount) {
  std::vector<double> expected(size_t(grid.cellCount()), 0.0);
  QuadratureOptions options;
  options.relativeTolerance = 1e-7;
  options.absoluteTolerance = 1e-4 / double(std::max<size_t>(sampleCount, 1)) / double(grid.cellCount());
  options.minDepth = 2;
  options.maxDepth = 20;
  const int rings = grid.rings();
  tbb::parallel_for(0, rings * grid.sectors, [&](int cell) {
    const int ring = cell / grid.sectors, sector = cell % grid.sectors;
    const double outer = grid.ringEdges[size_t(ring) + 1];
    // The first ring starts at 1e-12 of its radius: rho pdf stays bounded at 0 (densities
    // diverge at most like 1 / rho), so what is left out is ~1e-12 of the ring.
    const double inner = ring == 0 ? 1e-12 * outer : grid.ringEdges[size_t(ring)];
    const double phi0 = -Pi + 2.0 * Pi * sector / grid.sectors,
                 phi1 = -Pi + 2.0 * Pi * (sector + 1) / grid.sectors;
    // The quadrature's end points stay 1e-12 inside the ring: a density that jumps exactly on a
    // ring edge (the probe's r_max) must not be sampled on the wrong side of it by round-off,
    // or the error estimate never shrinks there. What is left out is ~1e-12 of the ring.
    constexpr double Inset = 1e-12;
    const double mass = adaptiveSimpson2D(
        [&](double t, double phi) {
          const double rho = std::exp(t);
          return pdf(Vec2d(rho * std::cos(phi), rho * std::sin(phi))) * rho * rho;  // dA = rho^2 dt dphi
        },
        std::log(inner) + Inset, std::log(outer) - Inset, phi0, phi1, options);
    expected[size_t(cell)] = double(sampleCount) * mass;
  });
  return expected;
}

ChiSquareResult planarChiSquareVerdict(const CellCounts& counts, const std::vector<double>& expected,
                                       const PolarGrid& grid, size_t sampleCount, double threshold,
                                       double minExpected) {
  // rings x sectors, and a last row whose first cell is the outside cell.
  Table2D observed(grid.rings() + 1, grid.sectors), expectedTable(grid.rings() + 1, grid.sectors);
  for (int cell = 0; cell < grid.cellCount(); ++cell) {
    observed.values[size_t(cell)] = double(counts.counts[size_t(cell)]);
    expectedTable.values[size_t(cell)] = expected[size_t(cell)];
  }
  ChiSquareResult r = chiSquareFromTables(observed, expectedTable, sampleCount, threshold, minExpected);
  if (counts.invalid > 0) {
    r.passed = false;
    r.failure = std::to_string(counts.invalid) + " invalid samples, first: " + counts.firstInvalid;
  }
  return r;
}

}  // namespace scatterlab
