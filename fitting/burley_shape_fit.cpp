#include "fitting/burley_shape_fit.h"

#include <cmath>
#include <stdexcept>

#include <ceres/jet.h>

#include "materials/bssrdf/annulus_profile.h"
#include "materials/bssrdf/chandrasekhar_h.h"

namespace scatterlab::fitting {

HalfSpaceWalkSettings burleyShapeWalkSettings(double albedo, uint64_t paths, uint64_t seed, double annulusWidth) {
  if (!(albedo > 0 && albedo < 1)) throw std::invalid_argument("Burley shape fit: A must be in (0, 1)");
  if (!(annulusWidth > 0)) throw std::invalid_argument("Burley shape fit: the annulus width must be positive");
  HalfSpaceWalkSettings s;
  s.albedo = searchlightAlbedoForReflectance(albedo);
  s.extinction = 1.0;
  s.g = 0.0;
  s.eta = 1.0;
  s.incidence = WalkIncidence::Searchlight;
  s.incidentCosTheta = 1.0;
  s.paths = paths;
  s.seed = seed;
  const double d = 1.0 / burleyShapeFactor(BurleyFit::Searchlight, albedo);
  const double rMax = 3.0 * burleySampleRadius(d, 0.999);
  s.radiusEdges = linearRadiusEdges(rMax, int(std::ceil(rMax / annulusWidth)));
  return s;
}

namespace {

// Burley's annulus averages at s (with the derivative in s when T is a Jet).
template <typename T>
std::vector<T> burleyAnnulusMeans(const BurleyShapeProfile& profile, const T& s, const std::vector<double>& edges) {
  std::vector<T> means;
  for (size_t k = 0; k + 1 < edges.size(); ++k)
    means.push_back((profile.cumulative(&s, edges[k + 1]) - profile.cumulative(&s, edges[k])) /
                    (Pi * (sqr(edges[k + 1]) - sqr(edges[k]))));
  return means;
}

}  // namespace

BurleyShapeFit fitBurleyShapeFactor(const HalfSpaceWalkResult& walk, double albedo) {
  const std::vector<double>& edges = walk.settings.radiusEdges;
  if (edges.size() < 3) throw std::invalid_argument("Burley shape fit: the walk has no annuli");
  BurleyShapeFit out;
  out.albedo = albedo;
  out.walkAlbedo = walk.settings.albedo;
  out.walkReflectance = walk.totalReflectance;
  out.walkStdError = walk.totalStdError;
  out.publishedShapeFactor = burleyShapeFactor(BurleyFit::Searchlight, albedo);

  RadialFitOptions options;
  options.start = {out.publishedShapeFactor};
  options.lower = {1e-2};
  options.upper = {100.0};
  options.weighting = RadialWeighting::Radius;
  for (size_t k = 0; k + 1 < edges.size(); ++k) options.weights.push_back(std::sqrt(edges[k + 1] - edges[k]));
  const BurleyShapeProfile profile{albedo, 1.0 / walk.settings.extinction};
  out.fit = fitRadialAnnuli(profile, edges, walk.profile, options);
  out.shapeFactor = out.fit.parameters[0];

  // The walk's noise in s: for the least-squares estimate with weights w_k and sensitivities
  // J_k = d Rbar_k / ds, s - s_true ~ sum_k w_k^2 J_k e_k / sum_k w_k^2 J_k^2 for annulus
  // errors e_k with standard errors se_k (their weak multinomial correlation neglected).
  using Jet = ceres::Jet<double, 1>;
  const std::vector<Jet> model = burleyAnnulusMeans(profile, Jet(out.shapeFactor, 0), edges);
  double numerator = 0.0, denominator = 0.0;
  for (size_t k = 0; k < model.size(); ++k) {
    const double w2 = sqr(detail::radialWeight(RadialWeighting::Radius, 0.5 * (edges[k] + edges[k + 1]), 0.0) *
                          options.weights[k]);
    numerator += sqr(w2 * model[k].v[0] * walk.profileStdError[k]);
    denominator += w2 * sqr(model[k].v[0]);
  }
  out.shapeStdError = denominator > 0 ? std::sqrt(numerator) / denominator : 0.0;

  // The errors on 32 log-spaced groups of annuli, with the power beyond the last edge: the
  // walk's escapes there, and Burley's tail.
  const std::vector<size_t> groups = logAnnulusGroups(edges, ErrorAnnuli);
  const std::vector<double> coarse = groupedEdges(edges, groups);
  const std::vector<double> walkMeans = groupedMeans(edges, walk.profile, groups);
  uint64_t inside = 0;
  for (const uint64_t c : walk.counts) inside += c;
  const double walkBeyond = double(walk.escaped - inside) / double(walk.settings.paths);
  const auto error = [&](double s) {
    const double beyond = albedo - profile.cumulative(&s, edges.back());
    return radialRelativeError(coarse, burleyAnnulusMeans(profile, s, coarse), walkMeans, beyond, walkBeyond);
  };
  out.fitError = error(out.shapeFactor);
  out.publishedError = error(out.publishedShapeFactor);
  out.errorNoiseFloor = radialNoiseFloor(coarse, walkMeans, double(walk.settings.paths));
  return out;
}

}  // namespace scatterlab::fitting
