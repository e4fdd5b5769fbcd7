#include "materials/bsdf/rough_dielectric_multiscatter.h"

#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "materials/bsdf/refraction.h"
#include "materials/bsdf/rough_dielectric_albedo.h"
#include "materials/core/lobe_choice.h"
#include "materials/core/quadrature.h"
#include "materials/core/shared_cache.h"

namespace scatterlab {

namespace {

constexpr double CoordinateOffset = 1e-6;  // s = ln(mu + c) + mu / L
constexpr double CoordinateLinearScale = 0.1;

void checkParameters(double alpha, double eta) {
  if (!(alpha > 0.0 && alpha <= 1.0))
    throw std::invalid_argument("the rough dielectric's albedo is tabulated for roughness in (0, 1], got " +
                                std::to_string(alpha));
  if (!(eta > 0.0) || !std::isfinite(eta) || eta == 1.0)
    throw std::invalid_argument("rough dielectric index must be positive, finite and not 1, got " +
                                std::to_string(eta));
}

}  // namespace

double dielectricAlbedo(MicrofacetType type, double alpha, double eta, double mu, bool inside) {
  const LobeAlbedo e =
      type == MicrofacetType::Ggx
          ? roughDielectricAlbedoAboutIncidence(GgxDistribution<double>(alpha, alpha), eta, mu, inside)
          : roughDielectricAlbedoAboutIncidence(BeckmannDistribution<double>(alpha, alpha), eta, mu, inside);
  return e.total();
}

double DielectricAlbedoTable::coordinate(double mu) {
  mu = std::clamp(mu, 0.0, 1.0);
  return std::log(mu + CoordinateOffset) + mu / CoordinateLinearScale;
}

double DielectricAlbedoTable::cosAt(double s) {
  // s is increasing in mu: bisection to full precision (construction only).
  double lo = 0.0, hi = 1.0;
  if (!(s > coordinate(lo))) return lo;
  if (!(s < coordinate(hi))) return hi;
  for (int iteration = 0; iteration < 64; ++iteration) {
    const double mid = 0.5 * (lo + hi);
    (coordinate(mid) < s ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

DielectricAlbedoTable::DielectricAlbedoTable(MicrofacetType type, double alpha, double eta, bool inside) {
  checkParameters(alpha, eta);
  const auto albedoAt = [&](double mu) {
    return dielectricAlbedo(type, alpha, eta, std::max(mu, GrazingCos), inside);
  };
  const double s0 = coordinate(0.0), s1 = coordinate(1.0);
  // Nodes (s, E) kept sorted by s; `pending` are the intervals [s_k, s_{k+1}] still to check,
  // by their left end. Each round computes the midpoints of all pending intervals against the
  // interpolant of the nodes known at the round's start, then inserts them all: the result
  // does not depend on the order of the work.
  std::map<double, double> nodes;
  for (int k = 0; k < InitialNodes; ++k) {
    const double s = k + 1 == InitialNodes ? s1 : s0 + (s1 - s0) * k / (InitialNodes - 1);
    nodes.emplace(s, albedoAt(cosAt(s)));
  }
  // Features narrower than the first nodes' spacing, which a midpoint test could step over:
  // masking sets in at mu ~ alpha, and from the denser side total internal reflection at the
  // critical cosine, blurred by the facets over ~alpha sin(theta_c) = alpha / eta.
  std::vector<double> features;
  for (const double k : {0.25, 0.5, 1.0, 2.0, 4.0}) features.push_back(k * alpha);
  if (inside) {
    const double critical = std::sqrt(1.0 - 1.0 / (eta * eta)), width = alpha / eta;
    for (const double k : {-4.0, -2.0, -1.0, -0.5, 0.0, 0.5, 1.0, 2.0, 4.0})
      features.push_back(critical + k * width);
  }
  for (const double mu : features)
    if (mu > RefinedAbove && mu < 1.0) nodes.emplace(coordinate(mu), albedoAt(mu));
  const auto interpolant = [&] {
    std::vector<double> x, y;
    for (const auto& [s, e] : nodes) {
      x.push_back(s);
      y.push_back(e);
    }
    return PiecewiseCubic1D(std::move(x), std::move(y));
  };
  std::vector<std::pair<double, double>> pending;
  for (auto it = nodes.begin(); std::next(it) != nodes.end(); ++it)
    pending.emplace_back(it->first, std::next(it)->first);
  while (!pending.empty() && nodes.size() < size_t(MaxNodes)) {
    const PiecewiseCubic1D current = interpolant();
    std::vector<std::pair<double, double>> next;
    for (const auto& [lo, hi] : pending) {
      const double mid = 0.5 * (lo + hi);
      const double value = albedoAt(cosAt(mid));
      nodes.emplace(mid, value);
      if (std::abs(value - current(mid)) > Tolerance && cosAt(hi) > RefinedAbove) {
        next.emplace_back(lo, mid);
        next.emplace_back(mid, hi);
      }
    }
    pending = std::move(next);
  }
  table_ = interpolant();
  for (const auto& node : nodes) nodeCos_.push_back(cosAt(node.first));

  // 2 integral (1 - E) mu dmu, node interval by node interval (the interpolant is a cubic in s
  // inside each): relative accuracy 1e-9, the loss being ~1e-6 at alpha 0.001.
  QuadratureOptions options;
  options.relativeTolerance = 1e-10;
  options.absoluteTolerance = 1e-14;  // per interval; also ends the refinement at a clamp's kink
  options.minDepth = 2;
  options.maxDepth = 30;
  double sum = 0.0;
  for (size_t k = 0; k + 1 < nodeCos_.size(); ++k)
    sum += adaptiveSimpson([&](double mu) { return loss(mu) * mu; }, nodeCos_[k], nodeCos_[k + 1], options);
  averageLoss_ = 2.0 * sum;
}

double DielectricAlbedoTable::operator()(double mu) const {
  return std::clamp(table_(coordinate(mu)), 0.0, 1.0);
}

// ---- The compensation lobe ----

namespace {

// See SharedCache: bounded, for fits that move the roughness or index continuously.
constexpr size_t MaxCacheEntries = 64;

// w turned to the upper hemisphere (the samplers' and tables' frame).
Vec3d upward(const Vec3d& w) { return Vec3d(w.x, w.y, std::abs(w.z)); }

}  // namespace

RoughDielectricCompensation::RoughDielectricCompensation(MicrofacetType type, double alpha, double eta)
    : eta_(eta), outside_(type, alpha, eta, false), inside_(type, alpha, eta, true) {
  // The split of the header comment: tau, the crossing flux, as large as both shares allow.
  const double lossOut = outside_.averageLoss(), lossIn = inside_.averageLoss();
  const double crossing = std::min(lossOut, eta * eta * lossIn);
  if (lossOut > 0) reflectionOutside_ = std::clamp(1.0 - crossing / lossOut, 0.0, 1.0);
  if (lossIn > 0) reflectionInside_ = std::clamp(1.0 - crossing / (eta * eta * lossIn), 0.0, 1.0);
  outsideSampler_ =
      LossLobeSampler([this](const Vec3d& w) { return outside_.loss(w.z); }, lossOut, alpha, alpha);
  insideSampler_ =
      LossLobeSampler([this](const Vec3d& w) { return inside_.loss(w.z); }, lossIn, alpha, alpha);
}

std::shared_ptr<const RoughDielectricCompensation> RoughDielectricCompensation::shared(MicrofacetType type,
                                                                                       double alpha,
                                                                                       double eta) {
  static SharedCache<std::tuple<MicrofacetType, double, double>, RoughDielectricCompensation> cache(
      MaxCacheEntries);
  return cache.get({type, alpha, eta},
                   [&] { return std::make_shared<const RoughDielectricCompensation>(type, alpha, eta); });
}

double RoughDielectricCompensation::eval(const Vec3d& wi, const Vec3d& wo, double lossI,
                                         TransportMode mode) const {
  if (wi.z == 0 || wo.z == 0) return 0.0;
  const bool inside = wi.z < 0;
  if (wi.z * wo.z > 0) {
    const DielectricAlbedoTable& side = albedo(inside);
    return reflectionShare(inside) * kullaContyLobe(lossI, side.loss(std::abs(wo.z)), side.averageLoss());
  }
  const DielectricAlbedoTable& other = albedo(!inside);
  const double f = (1.0 - reflectionShare(inside)) *
                   kullaContyLobe(lossI, other.loss(std::abs(wo.z)), other.averageLoss());
  return mode == TransportMode::Radiance ? f / sqr(relativeIndex(wi, wo, eta_)) : f;
}

double RoughDielectricCompensation::pdf(const Vec3d& wi, const Vec3d& wo) const {
  if (wi.z == 0 || wo.z == 0) return 0.0;
  const bool inside = wi.z<0, reflection = wi.z * wo.z> 0;
  const double share = reflection ? reflectionShare(inside) : 1.0 - reflectionShare(inside);
  return share * sampler(wo.z < 0).pdf(upward(wo));
}

std::optional<Vec3d> RoughDielectricCompensation::sample(const Vec3d& wi, double uLobe,
                                                         const Vec2d& u) const {
  if (wi.z == 0) return std::nullopt;
  const bool inside = wi.z < 0, reflection = chooseLobe(uLobe, reflectionShare(inside)).lobe == 0;
  const bool below = reflection ? inside : !inside;
  std::optional<Vec3d> wo = sampler(below).sample(u);
  if (wo && below) wo->z = -wo->z;
  return wo;
}

}  // namespace scatterlab
