// Starting points of a BRDF fit that do not depend on luck.
//
// The shape parameters are laid on a coarse grid (per parameter evenly spaced, in the log for
// roughness and exponents, at the centres of G equal cells of its range; G = round(B^(1/d))
// for d <= 3 parameters and a budget of B points, and B points of the R_d low-discrepancy
// sequence (Roberts 2018) above that). The RGB copies of one parameter (per-channel shapes,
// an RGB shape) take the same grid value. At each grid point the linear scales are solved in
// closed form: the metric's linear analogue (metric.h) makes the model linear in them, and
// each channel's small box-constrained least-squares problem (bounds from the registry) is
// solved by projected Gauss-Seidel, which converges for the positive semi-definite normal
// equations. The point's cost is then the metric's own. For lobes of one type repeated
// (--lobes N) only grid points whose first shape parameter increases from lobe to lobe are
// kept, so that relabelled copies of one configuration are not tried twice. A point whose cost
// is not finite (the model's value or the scales' solution is not finite there) cannot start a
// fit: it is left out and counted, and the count reaches the fit's result (brdf_fit.h), so
// that no point is lost without a number.
#pragma once

#include <cstddef>
#include <vector>

#include "fitting/brdf_samples.h"
#include "fitting/fit_model.h"
#include "fitting/metric.h"

namespace scatterlab::fitting {

struct GridPoint {
  std::vector<double> x;     // every parameter: grid shapes, solved scales
  std::vector<double> unit;  // the point's position in [0, 1]^d
  double cost = 0;           // the metric's S on the grid samples
};

struct GridSearch {
  std::vector<GridPoint> points;  // those with a finite cost, sorted by cost, best first
  size_t nonFinitePoints = 0;     // points left out because their cost is not finite
  size_t dimensions = 0;
  double cellWidth = 1;  // of the grid in unit coordinates
};

// Every grid point with its solved scales and cost on `samples` (parallel over points,
// each point summed in sample order: the same for any thread count).
GridSearch searchGrid(const FitModel& model, const BrdfSamples& samples, Metric metric, int budget,
                      int threads);

// The best `count` points of a search that are not grid neighbours of a better one.
std::vector<GridPoint> distinctStarts(const GridSearch& search, int count);

// The closed-form scales at the shapes of x (x's scale entries are replaced).
void solveScales(const FitModel& model, const BrdfSamples& samples, Metric metric, std::vector<double>& x);

}  // namespace scatterlab::fitting
