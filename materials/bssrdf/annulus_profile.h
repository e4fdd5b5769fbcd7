// A radial profile on annuli: R(r) averaged over rings [r_k, r_k+1] (exactly, from the radius
// CDF, so the divergence of some profiles at r = 0 does no harm), and the distance between two
// such tables that the profile-against-walk comparison and the shape-factor fit report.
#pragma once

#include <span>
#include <vector>

#include "materials/bssrdf/bssrdf.h"

namespace scatterlab {

// pi (r_k+1^2 - r_k^2) for each annulus of `edges` (increasing, in mm).
std::vector<double> annulusAreas(std::span<const double> edges);

// R of one channel averaged over each annulus: Rd (cdf(r_k+1) - cdf(r_k)) / area_k, mm^-2.
std::vector<double> annulusMeans(const RadialProfile& profile, int channel, std::span<const double> edges);

// The relative error of R(r) weighted by r: the L1 distance between the two radial
// distributions of exitant power, relative to the reference's total,
//   sum_k |model_k - reference_k| area_k / sum_k reference_k area_k
// (area_k = 2 pi r dr of the annulus), plus the power each puts beyond the last edge
// (`modelBeyond`, `referenceBeyond`) as one more bin. 0 for equal profiles; at most
// (total model + total reference) / total reference.
double radialRelativeError(std::span<const double> edges, std::span<const double> model,
                           std::span<const double> reference, double modelBeyond = 0.0,
                           double referenceBeyond = 0.0);

// Coarser annuli made of whole annuli of `edges`: the indices (into `edges`, first 0, last
// edges.size() - 1) of the fine edges nearest to `groups` log-spaced radii from edges[1] to
// the last edge. Comparing tallies on fewer, wider annuli keeps the Monte Carlo noise in an L1
// error small (it adds up over annuli).
std::vector<size_t> logAnnulusGroups(std::span<const double> edges, int groups);
std::vector<double> groupedEdges(std::span<const double> edges, std::span<const size_t> groups);
// Annulus averages over the grouped annuli (area-weighted means of the fine ones).
std::vector<double> groupedMeans(std::span<const double> edges, std::span<const double> means,
                                 std::span<const size_t> groups);

// What radialRelativeError reads from noise alone when `reference` is a Monte Carlo tally of
// `paths` paths (each annulus a binomial proportion p_k = reference_k area_k) and the model is
// exact: sum_k sqrt(2 / pi) sqrt(p_k (1 - p_k) / paths) / sum_k p_k, the mean absolute deviation
// of a normal error per annulus.
double radialNoiseFloor(std::span<const double> edges, std::span<const double> reference, double paths);

}  // namespace scatterlab
