#include "materials/measured/tabulated_brdf.h"

#include <algorithm>
#include <memory>

namespace scatterlab {

namespace {

using merl::PhiDiffCells;
using merl::ThetaDiffCells;
using merl::ThetaHalfCells;

constexpr int Unfilled = -1;

// One axis of the fill rule: along a line of n cells (stride apart from `first`), every cell
// without a source takes the source of the nearest cell that has one (ties: the lower index).
// source[cell] is the cell whose value it takes, or Unfilled.
void fillAlongLine(std::vector<int>& source, size_t first, size_t stride, int n) {
  constexpr int None = -1;
  std::vector<int> previous(size_t(n), None), next(size_t(n), None);
  int last = None;
  for (int i = 0; i < n; ++i) {
    if (source[first + size_t(i) * stride] != Unfilled) last = i;
    previous[size_t(i)] = last;
  }
  last = None;
  for (int i = n - 1; i >= 0; --i) {
    if (source[first + size_t(i) * stride] != Unfilled) last = i;
    next[size_t(i)] = last;
  }
  for (int i = 0; i < n; ++i) {
    const size_t cell = first + size_t(i) * stride;
    if (source[cell] != Unfilled) continue;
    const int p = previous[size_t(i)], q = next[size_t(i)];
    if (p == None && q == None) continue;
    const int from = (q == None || (p != None && i - p <= q - i)) ? p : q;
    source[cell] = source[first + size_t(from) * stride];
  }
}

// Coordinate of the interpolation on an axis of `cells` centres, held constant past the
// first and last: the lower corner and the weight of the upper one.
std::pair<int, double> clampedAxis(double coordinate, int cells) {
  const double x = std::clamp(coordinate - 0.5, 0.0, double(cells - 1));
  const int i = std::min(int(x), cells - 2);
  return {i, x - i};
}

// cos and sin of the cell centres' angles, so that classifying 1.458M cells costs no trig.
struct CentreTrigonometry {
  std::array<double, ThetaHalfCells> cosH, sinH;
  std::array<double, ThetaDiffCells> cosD, sinD;
  std::array<double, PhiDiffCells> cosP;
  CentreTrigonometry() {
    for (int i = 0; i < ThetaHalfCells; ++i) {
      cosH[size_t(i)] = std::cos(merl::thetaHalfAt(i + 0.5));
      sinH[size_t(i)] = std::sin(merl::thetaHalfAt(i + 0.5));
    }
    for (int i = 0; i < ThetaDiffCells; ++i) {
      cosD[size_t(i)] = std::cos(merl::thetaDiffAt(i + 0.5));
      sinD[size_t(i)] = std::sin(merl::thetaDiffAt(i + 0.5));
    }
    for (int i = 0; i < PhiDiffCells; ++i) cosP[size_t(i)] = std::cos(merl::phiDiffAt(i + 0.5));
  }
};

}  // namespace

// polarCosinesFromHalfDiff at the centre, from the tables.
bool isReachableCell(size_t cell) {
  static const CentreTrigonometry t;
  const merl::CellCoordinates c = merl::cellCoordinates(cell);
  const double a = t.cosD[size_t(c.thetaDiff)] * t.cosH[size_t(c.thetaHalf)];
  const double b = t.sinD[size_t(c.thetaDiff)] * t.cosP[size_t(c.phiDiff)] * t.sinH[size_t(c.thetaHalf)];
  return a - b > 0 && a + b > 0;
}

TabulatedBrdf::FilledGrid TabulatedBrdf::fill(const MerlTable& table) {
  FilledGrid grid;
  // source[cell]: the usable cell whose value this cell takes (itself when usable).
  std::vector<int> source(merl::CellCount, Unfilled);
  for (size_t cell = 0; cell < merl::CellCount; ++cell) {
    const bool missing = table.isMissing(cell);
    grid.missing += missing ? 1 : 0;
    if (!missing && isReachableCell(cell)) source[cell] = int(cell);
  }
  // Along theta_d within each (theta_h, phi_d) column, then along theta_h within each
  // (theta_d, phi_d) row for the columns that had nothing usable.
  for (int th = 0; th < ThetaHalfCells; ++th)
    for (int pd = 0; pd < PhiDiffCells; ++pd)
      fillAlongLine(source, merl::cellIndex(th, 0, pd), PhiDiffCells, ThetaDiffCells);
  for (int td = 0; td < ThetaDiffCells; ++td)
    for (int pd = 0; pd < PhiDiffCells; ++pd)
      fillAlongLine(source, merl::cellIndex(0, td, pd), size_t(PhiDiffCells) * ThetaDiffCells,
                    ThetaHalfCells);

  grid.values.resize(merl::CellCount);
  for (size_t cell = 0; cell < merl::CellCount; ++cell) {
    const int from = source[cell];
    grid.filled += from == int(cell) ? 0 : 1;
    for (int c = 0; c < 3; ++c)
      grid.values[cell][size_t(c)] = from == Unfilled ? 0.0f : float(table.value(c, size_t(from)));
  }
  return grid;
}

TabulatedBrdf::TabulatedBrdf(const MerlTable& table, const HalfVectorSamplerOptions& sampling)
    : TabulatedBrdf(fill(table), sampling) {}

TabulatedBrdf::TabulatedBrdf(FilledGrid grid, const HalfVectorSamplerOptions& sampling)
    : grid_(std::move(grid.values)),
      missingCells_(grid.missing),
      filledCells_(grid.filled),
      sampler_([this](const Vec3d& wi, const Vec3d& wo) { return eval(wi, wo); }, sampling) {}

Rgb TabulatedBrdf::interpolate(const HalfDiff& angles) const {
  const auto [h0, th] = clampedAxis(merl::thetaHalfCoordinate(angles.thetaHalf), ThetaHalfCells);
  const auto [d0, td] = clampedAxis(merl::thetaDiffCoordinate(angles.thetaDiff), ThetaDiffCells);
  // phi_d is periodic with period pi: the cell before 0 is 179.
  const double x = merl::phiDiffCoordinate(merl::foldPhiDiff(angles.phiDiff)) - 0.5;
  const double xFloor = std::floor(x);
  const double tp = x - xFloor;
  const int p0 = (int(xFloor) + PhiDiffCells) % PhiDiffCells, p1 = (p0 + 1) % PhiDiffCells;

  Rgb result(0.0);
  for (int a = 0; a < 2; ++a) {
    const double wa = a ? th : 1.0 - th;
    for (int b = 0; b < 2; ++b) {
      const double wab = wa * (b ? td : 1.0 - td);
      const size_t row = merl::cellIndex(h0 + a, d0 + b, 0);
      const auto& v0 = grid_[row + size_t(p0)];
      const auto& v1 = grid_[row + size_t(p1)];
      for (int c = 0; c < 3; ++c)
        result[c] += wab * ((1.0 - tp) * double(v0[size_t(c)]) + tp * double(v1[size_t(c)]));
    }
  }
  return result;
}

std::optional<BsdfSample> TabulatedBrdf::sample(const Vec3d& wi, double uLobe, const Vec2d& u,
                                                TransportMode) const {
  const std::optional<Vec3d> wo = sampler_.sample(wi, uLobe, u);
  if (!wo) return std::nullopt;
  // pdf() recomputed from (wi, wo): sample() and pdf() agree to the last bit.
  const double pdf = sampler_.pdf(wi, *wo);
  if (!(pdf > 0)) return std::nullopt;
  BsdfSample s;
  s.wo = *wo;
  s.pdf = pdf;
  s.weight = eval(wi, *wo) * (wo->z / pdf);
  s.lobe = LobeFlags::GlossyReflection;
  return s;
}

}  // namespace scatterlab
