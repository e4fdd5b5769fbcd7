#include "fitting/metric.h"

#include <array>
#include <optional>
#include <utility>

namespace scatterlab::fitting {

namespace {

constexpr std::array<std::pair<Metric, const char*>, 5> MetricNames{{
    {Metric::L2, "l2"},
    {Metric::Ngan, "ngan"},
    {Metric::LowL2, "low-l2"},
    {Metric::LowLog, "low-log"},
    {Metric::CubeRoot, "cube-root"},
}};

constexpr std::array<std::pair<RobustLoss, const char*>, 4> LossNames{{
    {RobustLoss::None, "none"},
    {RobustLoss::Huber, "huber"},
    {RobustLoss::Cauchy, "cauchy"},
    {RobustLoss::SoftL1, "soft-l1"},
}};

template <typename E, size_t N>
std::optional<E> parseName(const std::array<std::pair<E, const char*>, N>& table, std::string_view name) {
  for (const auto& [value, text] : table)
    if (name == text) return value;
  return std::nullopt;
}

template <typename E, size_t N>
std::string nameOf(const std::array<std::pair<E, const char*>, N>& table, E value) {
  for (const auto& [v, text] : table)
    if (v == value) return text;
  return "unknown";
}

template <typename E, size_t N>
std::vector<std::string> namesOf(const std::array<std::pair<E, const char*>, N>& table) {
  std::vector<std::string> names;
  for (const auto& entry : table) names.emplace_back(entry.second);
  return names;
}

}  // namespace

std::string toString(Metric metric) { return nameOf(MetricNames, metric); }
std::optional<Metric> parseMetric(std::string_view name) { return parseName(MetricNames, name); }
std::vector<std::string> metricNames() { return namesOf(MetricNames); }

std::string describe(Metric metric) {
  switch (metric) {
    case Metric::L2: return "l2: plain L2 on f";
    case Metric::Ngan: return "ngan: Ngan et al. 2005, [(f - m) cos_i]^2 sin_i sin_o";
    case Metric::LowL2: return "low-l2: Low et al. 2012, [(f - m) cos_i]^2 sin_i";
    case Metric::LowLog: return "low-log: Low et al. 2012, [ln(1 + f cos_i) - ln(1 + m cos_i)]^2 sin_i";
    case Metric::CubeRoot:
      return "cube-root: Fores et al. 2012, [(f cos_i)^(1/3) - (m cos_i)^(1/3)]^2 sin_i sin_o";
  }
  return "";
}

Metric linearAnalogue(Metric metric) {
  switch (metric) {
    case Metric::LowLog: return Metric::LowL2;
    case Metric::CubeRoot: return Metric::Ngan;
    default: return metric;
  }
}

std::string toString(RobustLoss loss) { return nameOf(LossNames, loss); }
std::optional<RobustLoss> parseRobustLoss(std::string_view name) { return parseName(LossNames, name); }
std::vector<std::string> robustLossNames() { return namesOf(LossNames); }

std::unique_ptr<ceres::LossFunction> makeLossFunction(RobustLoss loss, double scale) {
  switch (loss) {
    case RobustLoss::None: return nullptr;
    case RobustLoss::Huber: return std::make_unique<ceres::HuberLoss>(scale);
    case RobustLoss::Cauchy: return std::make_unique<ceres::CauchyLoss>(scale);
    case RobustLoss::SoftL1: return std::make_unique<ceres::SoftLOneLoss>(scale);
  }
  return nullptr;
}

}  // namespace scatterlab::fitting
