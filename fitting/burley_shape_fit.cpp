#include "fitting/burley_shape_fit.h"

#include <cmath>
#include <stdexcept>

#include <ceres/jet.h>
#include <Eigen/Dense>

#include "materials/bssrdf/annulus_profile.h"
#include "materials/bssrdf/chandrasekhar_h.h"

namespace scatterlab::fitting {

HalfSpaceWalkSettings burleyShapeWalkSettings(double albedo, uint64_t paths, uint64_t seed,
                                              double annulusWidth) {
  if (!(albedo > 0 && albedo < 1)) throw std::invalid_argument("Burley shape fit: A must be in (0, 1)");
  if (!(annulusWidth > 0))
    throw std::invalid_argument("Burley shape fit: the annulus width must be positive");
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

// The profile's annulus averages at parameters p (with their derivatives when T is a Jet).
template <typename Profile, typename T>
std::vector<T> annulusMeans(const Profile& profile, const T* p, const std::vector<double>& edges) {
  std::vector<T> means;
  for (size_t k = 0; k + 1 < edges.size(); ++k)
    means.push_back((profile.cumulative(p, edges[k + 1]) - profile.cumulative(p, edges[k])) /
                    (Pi * (sqr(edges[k + 1]) - sqr(edges[k]))));
  return means;
}

// Least squares of r R(r) on the walk's annuli, started at `start`.
template <typename Profile>
RadialFitResult fitRadiusWeighted(const Profile& profile, const HalfSpaceWalkResult& walk,
                                  std::vector<double> start, std::vector<double> lower,
                                  std::vector<double> upper) {
  const std::vector<double>& edges = walk.settings.radiusEdges;
  RadialFitOptions options;
  options.start = std::move(start);
  options.lower = std::move(lower);
  options.upper = std::move(upper);
  options.weighting = RadialWeighting::Radius;
  for (size_t k = 0; k + 1 < edges.size(); ++k) options.weights.push_back(std::sqrt(edges[k + 1] - edges[k]));
  return fitRadialAnnuli(profile, edges, walk.profile, options);
}

// The walk's noise in the fitted parameters. For weighted least squares with residual weights
// w_k and sensitivities J_k = d Rbar_k / dp, the estimate moves by
// (sum_k w_k^2 J_k J_k^T)^-1 sum_k w_k^2 J_k e_k for annulus errors e_k with standard errors
// se_k (their weak multinomial correlation neglected): the sandwich H^-1 M H^-1 with
// M = sum_k w_k^4 se_k^2 J_k J_k^T. Returns the standard deviations.
template <typename Profile> std::vector<double> walkNoiseStdDeviations(const Profile& profile,
                                                                       const std::vector<double>& parameters,
                                                                       const HalfSpaceWalkResult& walk) {
  constexpr int K = Profile::ParameterCount;
  using Jet = ceres::Jet<double, K>;
  const std::vector<double>& edges = walk.settings.radiusEdges;
  Jet p[K];
  for (int i = 0; i < K; ++i) p[i] = Jet(parameters[i], i);
  const std::vector<Jet> model = annulusMeans(profile, p, edges);
  Eigen::Matrix<double, K, K> H = Eigen::Matrix<double, K, K>::Zero(), M = H;
  for (size_t k = 0; k < model.size(); ++k) {
    const double mid = 0.5 * (edges[k] + edges[k + 1]);
    const double w2 = sqr(mid) * (edges[k + 1] - edges[k]);
    H += w2 * model[k].v * model[k].v.transpose();
    M += sqr(w2 * walk.profileStdError[k]) * model[k].v * model[k].v.transpose();
  }
  const Eigen::Matrix<double, K, K> Hinv = H.inverse();
  const Eigen::Matrix<double, K, K> covariance = Hinv * M * Hinv;
  std::vector<double> out;
  for (int i = 0; i < K; ++i) out.push_back(std::sqrt(std::max(0.0, covariance(i, i))));
  return out;
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
  const double length = 1.0 / walk.settings.extinction;

  const BurleyPowerAndShapeProfile shape{length};
  out.shapeFit =
      fitRadiusWeighted(shape, walk, {albedo, out.publishedShapeFactor}, {0.0, 1e-2}, {2.0, 100.0});
  out.power = out.shapeFit.parameters[0];
  out.shapeFactor = out.shapeFit.parameters[1];
  const std::vector<double> shapeNoise = walkNoiseStdDeviations(shape, out.shapeFit.parameters, walk);
  out.powerStdError = shapeNoise[0];
  out.shapeStdError = shapeNoise[1];

  const BurleyShapeProfile normalised{albedo, length};
  out.normalisedFit = fitRadiusWeighted(normalised, walk, {out.publishedShapeFactor}, {1e-2}, {100.0});
  out.normalisedShapeFactor = out.normalisedFit.parameters[0];
  out.normalisedStdError = walkNoiseStdDeviations(normalised, out.normalisedFit.parameters, walk)[0];

  // The errors on 32 log-spaced groups of annuli, with the power beyond the last edge: the
  // walk's escapes there, and Burley's tail.
  const std::vector<size_t> groups = logAnnulusGroups(edges, ErrorAnnuli);
  const std::vector<double> coarse = groupedEdges(edges, groups);
  const std::vector<double> walkMeans = groupedMeans(edges, walk.profile, groups);
  uint64_t inside = 0;
  for (const uint64_t c : walk.counts) inside += c;
  const double walkBeyond = double(walk.escaped - inside) / double(walk.settings.paths);
  const auto error = [&](double s) {
    const double beyond = albedo - normalised.cumulative(&s, edges.back());
    return radialRelativeError(coarse, annulusMeans(normalised, &s, coarse), walkMeans, beyond, walkBeyond);
  };
  out.shapeError = error(out.shapeFactor);
  out.normalisedError = error(out.normalisedShapeFactor);
  out.publishedError = error(out.publishedShapeFactor);
  out.errorNoiseFloor = radialNoiseFloor(coarse, walkMeans, double(walk.settings.paths));
  return out;
}

}  // namespace scatterlab::fitting
