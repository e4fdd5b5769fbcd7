#include "materials/bssrdf/chandrasekhar_h.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "materials/core/gauss_legendre.h"
#include "materials/core/root_finding.h"

namespace scatterlab {

namespace {
const GaussLegendreRule<ChandrasekharH::NodeCount>& rule() {
  return gaussLegendre<ChandrasekharH::NodeCount>();
}
constexpr int MaxIterations = 1'000'000;
}  // namespace

ChandrasekharH::ChandrasekharH(double albedo) : albedo_(albedo) {
  if (!(albedo >= 0 && albedo <= 1)) throw std::invalid_argument("H-function: the albedo must be in [0, 1]");
  values_.fill(1.0);
  const auto& mu = rule().nodes;
  const auto& w = rule().weights;
  for (iterations_ = 1; iterations_ <= MaxIterations; ++iterations_) {
    std::array<double, NodeCount> next{};
    double change = 0.0;
    for (int i = 0; i < NodeCount; ++i) {
      double sum = 0.0;
      for (int j = 0; j < NodeCount; ++j) sum += w[j] * values_[j] / (mu[i] + mu[j]);
      next[i] = 1.0 / (1.0 - 0.5 * albedo * mu[i] * sum);
      change = std::max(change, std::abs(next[i] - values_[i]));
    }
    values_ = next;
    if (change < 1e-15) break;
  }
}

const std::array<double, ChandrasekharH::NodeCount>& ChandrasekharH::nodes() const { return rule().nodes; }
const std::array<double, ChandrasekharH::NodeCount>& ChandrasekharH::weights() const {
  return rule().weights;
}

double ChandrasekharH::operator()(double mu) const {
  const auto& nodes = rule().nodes;
  const auto& w = rule().weights;
  double sum = 0.0;
  for (int j = 0; j < NodeCount; ++j) sum += w[j] * values_[j] / (mu + nodes[j]);
  return 1.0 / (1.0 - 0.5 * albedo_ * mu * sum);
}

double ChandrasekharH::moment(int k) const {
  double sum = 0.0;
  for (int j = 0; j < NodeCount; ++j) sum += rule().weights[j] * values_[j] * std::pow(rule().nodes[j], k);
  return sum;
}

double ChandrasekharH::directionalAlbedo(double mu0) const {
  return 1.0 - (*this)(mu0)*std::sqrt(1.0 - albedo_);
}

double ChandrasekharH::whiteSkyAlbedo() const { return 1.0 - 2.0 * std::sqrt(1.0 - albedo_) * moment(1); }

double ChandrasekharH::brdf(double muI, double muO) const {
  return albedo_ / (4.0 * Pi) * (*this)(muI) * (*this)(muO) / (muI + muO);
}

double searchlightAlbedoForReflectance(double reflectance) {
  if (!(reflectance >= 0 && reflectance < 1))
    throw std::invalid_argument("searchlight albedo: the reflectance must be in [0, 1)");
  return bisectIncreasing([](double c) { return ChandrasekharH(c).directionalAlbedo(1.0); }, reflectance, 0.0,
                          1.0, 1e-12);
}

}  // namespace scatterlab
