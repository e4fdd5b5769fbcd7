#include "materials/bsdf/microfacet_albedo.h"

#include <map>
#include <mutex>
#include <tuple>

#include "materials/core/catmull_rom.h"

namespace scatterlab {

namespace detail {

namespace {

using AlbedoKey = std::tuple<int, double, double, double>;

struct AlbedoCache {
  std::mutex mutex;
  std::map<AlbedoKey, std::shared_ptr<const DielectricReflectionAlbedoTable>> tables;
};
AlbedoCache& albedoCache() {
  static AlbedoCache cache;
  return cache;
}
// A fit that moves the roughness continuously would otherwise grow the cache without bound.
constexpr size_t MaxCachedTables = 64;

}  // namespace

std::shared_ptr<const DielectricReflectionAlbedoTable> findAlbedoTable(int family, double alphaX,
                                                                       double alphaY, double eta) {
  AlbedoCache& cache = albedoCache();
  const std::lock_guard lock(cache.mutex);
  const auto it = cache.tables.find({family, alphaX, alphaY, eta});
  return it == cache.tables.end() ? nullptr : it->second;
}

void storeAlbedoTable(int family, double alphaX, double alphaY, double eta,
                      std::shared_ptr<const DielectricReflectionAlbedoTable> table) {
  AlbedoCache& cache = albedoCache();
  const std::lock_guard lock(cache.mutex);
  if (cache.tables.size() >= MaxCachedTables) cache.tables.clear();
  cache.tables.emplace(AlbedoKey{family, alphaX, alphaY, eta}, std::move(table));
}

}  // namespace detail

namespace {

// Node spacing in s; s grows by 1/0.1 = 10 per unit of cos theta near the normal.
constexpr double TargetStep = 0.12;
constexpr double LinearScale = 0.1;
// The grazing node is evaluated here: E has a finite limit at cos theta = 0, where the
// quadrature itself divides by cos theta.
constexpr double GrazingCos = 1e-7;

}  // namespace

double DielectricReflectionAlbedoTable::s(double cosTheta) const {
  return std::log(cosTheta + offset_) + cosTheta / LinearScale;
}

void DielectricReflectionAlbedoTable::placeNodes() {
  s0_ = s(0.0);
  const double s1 = s(1.0);
  const int intervals = std::max(4, int(std::ceil((s1 - s0_) / TargetStep)));
  ds_ = (s1 - s0_) / intervals;
  nodeCos_.resize(intervals + 1);
  nodeCos_.front() = GrazingCos;
  nodeCos_.back() = 1.0;
  for (int i = 1; i < intervals; ++i) {
    // s is increasing: bisection to full precision (placement runs once per table).
    const double target = s0_ + i * ds_;
    double lo = 0.0, hi = 1.0;
    for (int iteration = 0; iteration < 60; ++iteration) {
      const double mid = 0.5 * (lo + hi);
      (s(mid) < target ? lo : hi) = mid;
    }
    nodeCos_[i] = 0.5 * (lo + hi);
  }
}

double DielectricReflectionAlbedoTable::operator()(const Vec3d& w) const {
  if (!(w.z > 0)) return 0.0;
  const double cosTheta = std::min(w.z, 1.0);
  const int count = int(ratio_.size());
  const double x = std::clamp((s(cosTheta) - s0_) / ds_, 0.0, double(count - 1));
  const int i = std::min(int(x), count - 2);
  const double p1 = ratio_[i], p2 = ratio_[i + 1];
  // Beyond the ends, the quadratic through the last three nodes continued (catmull_rom.h).
  const double p0 = i > 0 ? ratio_[i - 1] : 3.0 * p1 - 3.0 * p2 + ratio_[i + 2];
  const double p3 = i + 2 < count ? ratio_[i + 2] : 3.0 * p2 - 3.0 * p1 + ratio_[i - 1];
  return std::clamp(fresnelDielectric(cosTheta, eta_) * catmullRom(p0, p1, p2, p3, x - i), 0.0, 1.0);
}

double DielectricReflectionAlbedoTable::integrateAverage() const {
  QuadratureOptions options;
  options.relativeTolerance = 1e-10;
  options.absoluteTolerance = 1e-14;
  options.minDepth = 1;
  // Node interval by node interval: the interpolant is smooth inside each.
  double sum = 0.0;
  for (size_t i = 0; i + 1 < nodeCos_.size(); ++i) {
    const double lo = i == 0 ? 0.0 : nodeCos_[i];
    sum += adaptiveSimpson([&](double c) { return (*this)(Vec3d(safeSqrt(1.0 - c * c), 0.0, c)) * c; }, lo,
                           nodeCos_[i + 1], options);
  }
  return 2.0 * sum;
}

}  // namespace scatterlab
