#include "fitting/initialization.h"

#include <algorithm>
#include <cmath>
#include <map>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "fitting/least_squares.h"

namespace scatterlab::fitting {

namespace {

// One grid dimension: a shape parameter, with its RGB copies.
struct Dimension {
  std::vector<size_t> parameters;
  size_t component = 0;
  bool firstOfComponent = false;
  GridSpacing spacing = GridSpacing::Linear;
  double lower = 0, upper = 1;

  double at(double u) const {
    if (spacing == GridSpacing::Log) {
      // Exponents start at 0: their log grid starts at 1.
      const double lo = lower > 0 ? lower : 1.0;
      return std::exp(std::log(lo) + u * (std::log(upper) - std::log(lo)));
    }
    return lower + u * (upper - lower);
  }
};

std::vector<Dimension> gridDimensions(const FitModel& model) {
  std::vector<Dimension> dims;
  std::map<std::pair<size_t, std::string>, size_t> byKey;
  for (const size_t index : model.parametersOf(ParameterRole::Shape)) {
    const FitParameter& p = model.parameters()[index];
    const auto key = std::make_pair(p.component, p.key);
    const auto found = byKey.find(key);
    if (found != byKey.end()) {
      dims[found->second].parameters.push_back(index);
      continue;
    }
    Dimension d;
    d.parameters = {index};
    d.component = p.component;
    d.firstOfComponent = std::none_of(dims.begin(), dims.end(),
                                      [&](const Dimension& o) { return o.component == p.component; });
    d.spacing = p.spacing;
    d.lower = p.lower;
    d.upper = p.upper;
    byKey[key] = dims.size();
    dims.push_back(d);
  }
  return dims;
}

// Unit coordinates of every candidate point (header comment).
std::vector<std::vector<double>> unitPoints(size_t d, int budget, double& cellWidth) {
  std::vector<std::vector<double>> points;
  if (d == 0) {
    cellWidth = 1;
    return {{}};
  }
  if (d <= 3) {
    const int g = std::max(2, int(std::lround(std::pow(double(budget), 1.0 / double(d)))));
    cellWidth = 1.0 / g;
    size_t total = 1;
    for (size_t k = 0; k < d; ++k) total *= size_t(g);
    for (size_t i = 0; i < total; ++i) {
      std::vector<double> u(d);
      size_t rest = i;
      for (size_t k = 0; k < d; ++k) {
        u[k] = (double(rest % size_t(g)) + 0.5) / g;
        rest /= size_t(g);
      }
      points.push_back(std::move(u));
    }
    return points;
  }
  // R_d (Roberts 2018, "The unreasonable effectiveness of quasirandom sequences"): phi_d is
  // the positive root of x^(d+1) = x + 1, alpha_k = phi_d^-(k+1).
  double phi = 2.0;
  for (int iteration = 0; iteration < 64; ++iteration) phi = std::pow(1.0 + phi, 1.0 / double(d + 1));
  std::vector<double> alpha(d);
  for (size_t k = 0; k < d; ++k) alpha[k] = std::pow(1.0 / phi, double(k + 1));
  cellWidth = std::pow(double(budget), -1.0 / double(d));
  for (int i = 0; i < budget; ++i) {
    std::vector<double> u(d);
    for (size_t k = 0; k < d; ++k) {
      const double v = 0.5 + alpha[k] * double(i + 1);
      u[k] = v - std::floor(v);
    }
    points.push_back(std::move(u));
  }
  return points;
}

// Lobes of one type repeated: their first shape parameter must increase (header comment).
bool isOrdered(const FitModel& model, const std::vector<Dimension>& dims, const std::vector<double>& u) {
  const auto& components = model.components();
  for (size_t a = 0; a < dims.size(); ++a) {
    if (!dims[a].firstOfComponent) continue;
    for (size_t b = a + 1; b < dims.size(); ++b) {
      if (!dims[b].firstOfComponent) continue;
      if (components[dims[a].component].type != components[dims[b].component].type) continue;
      if (!(u[a] < u[b])) return false;
      break;  // the next lobe of the type; it is compared with the one after it in turn
    }
  }
  return true;
}

// The scales of one channel: which (component, term) they are and where they live in x.
struct ChannelUnknowns {
  std::vector<std::pair<size_t, int>> terms;
  std::vector<size_t> index;
};

std::array<ChannelUnknowns, 3> channelUnknowns(const FitModel& model) {
  std::array<ChannelUnknowns, 3> unknowns;
  const auto& components = model.components();
  for (size_t k = 0; k < components.size(); ++k)
    for (int j = 0; j < components[k].terms; ++j)
      for (int c = 0; c < 3; ++c) {
        const int index = components[k].termParameter[size_t(j)][size_t(c)];
        if (index < 0) continue;
        unknowns[size_t(c)].terms.emplace_back(k, j);
        unknowns[size_t(c)].index.push_back(size_t(index));
      }
  return unknowns;
}

// Projected Gauss-Seidel for min s^T A s - 2 b^T s on a box; A positive semi-definite.
void solveBoxed(const Eigen::MatrixXd& a, const Eigen::VectorXd& b, const Eigen::VectorXd& lower,
                const Eigen::VectorXd& upper, Eigen::VectorXd& s) {
  const Eigen::Index n = b.size();
  for (int sweep = 0; sweep < 200; ++sweep) {
    double change = 0;
    for (Eigen::Index u = 0; u < n; ++u) {
      if (!(a(u, u) > 0)) {
        s[u] = lower[u];
        continue;
      }
      const double residual = b[u] - a.row(u).dot(s) + a(u, u) * s[u];
      const double next = std::clamp(residual / a(u, u), lower[u], upper[u]);
      change = std::max(change, std::abs(next - s[u]));
      s[u] = next;
    }
    if (change <= 1e-14 * (1.0 + s.cwiseAbs().maxCoeff())) break;
  }
}

// Per sample and channel: the unknown scales' term values, then the known part.
class ScaleSolver {
 public:
  ScaleSolver(const FitModel& model, const MetricSamples& linear, const MetricSamples* actual)
      : model_(model), linear_(linear), actual_(actual), unknowns_(channelUnknowns(model)) {}

  // Solves the scales into x; returns the actual metric's S when `actual` was given.
  double operator()(std::vector<double>& x) {
    const BrdfSamples& samples = linear_.samples();
    const size_t n = samples.size();
    std::array<Eigen::MatrixXd, 3> a;
    std::array<Eigen::VectorXd, 3> b;
    for (int c = 0; c < 3; ++c) {
      const auto m = Eigen::Index(unknowns_[size_t(c)].terms.size());
      a[size_t(c)] = Eigen::MatrixXd::Zero(m, m);
      b[size_t(c)] = Eigen::VectorXd::Zero(m);
      stride_[size_t(c)] = size_t(m) + 1;
    }
    const size_t perSample = stride_[0] + stride_[1] + stride_[2];
    cache_.resize(n * perSample);
    std::vector<std::array<Rgb, MaxTerms>> terms;
    std::vector<Rgb> rests;
    const auto& components = model_.components();
    for (size_t i = 0; i < n; ++i) {
      model_.evaluateTerms(x.data(), samples.wi[i], samples.wo[i], terms, rests);
      double* row = cache_.data() + i * perSample;
      const double w = sqr(linear_.sqrtWeight(i, 0));
      for (int c = 0; c < 3; ++c) {
        const ChannelUnknowns& u = unknowns_[size_t(c)];
        double known = 0;
        for (size_t k = 0; k < components.size(); ++k) {
          known += rests[k][c];
          for (int j = 0; j < components[k].terms; ++j)
            if (components[k].termParameter[size_t(j)][size_t(c)] < 0)
              known += components[k].heldTerm[size_t(j)][c] * terms[k][size_t(j)][c];
        }
        const size_t m = u.terms.size();
        for (size_t q = 0; q < m; ++q) row[q] = terms[u.terms[q].first][size_t(u.terms[q].second)][c];
        row[m] = known;
        const double data = linear_.target(i, 0, c) - known;
        for (size_t q = 0; q < m; ++q) {
          b[size_t(c)][Eigen::Index(q)] += w * row[q] * data;
          for (size_t r = 0; r <= q; ++r)
            a[size_t(c)](Eigen::Index(q), Eigen::Index(r)) += w * row[q] * row[r];
        }
        row += stride_[size_t(c)];
      }
    }
    const auto& parameters = model_.parameters();
    for (int c = 0; c < 3; ++c) {
      const ChannelUnknowns& u = unknowns_[size_t(c)];
      const auto m = Eigen::Index(u.terms.size());
      if (m == 0) continue;
      Eigen::MatrixXd full = a[size_t(c)].selfadjointView<Eigen::Lower>();
      Eigen::VectorXd lower(m), upper(m), s(m);
      for (Eigen::Index q = 0; q < m; ++q) {
        const FitParameter& p = parameters[u.index[size_t(q)]];
        lower[q] = p.lower;
        upper[q] = p.upper;
        s[q] = std::clamp(x[u.index[size_t(q)]], p.lower, p.upper);
      }
      solveBoxed(full, b[size_t(c)], lower, upper, s);
      for (Eigen::Index q = 0; q < m; ++q) x[u.index[size_t(q)]] = s[q];
    }
    if (!actual_) return 0;
    double cost = 0;
    for (size_t i = 0; i < n; ++i) {
      const double* row = cache_.data() + i * perSample;
      double model[3];
      for (int c = 0; c < 3; ++c) {
        const ChannelUnknowns& u = unknowns_[size_t(c)];
        double value = row[u.terms.size()];
        for (size_t q = 0; q < u.terms.size(); ++q) value += x[u.index[q]] * row[q];
        model[c] = value;
        row += stride_[size_t(c)];
      }
      const Metric metric = actual_->evaluationMetric();
      for (int o = 0; o < actual_->orderings(); ++o)
        for (int c = 0; c < 3; ++c)
          cost += sqr(actual_->sqrtWeight(i, o) *
                      (actual_->target(i, o, c) - metricTransform(metric, model[c], actual_->cosIn(i, o))));
    }
    return cost;
  }

 private:
  const FitModel& model_;
  const MetricSamples& linear_;
  const MetricSamples* actual_;
  std::array<ChannelUnknowns, 3> unknowns_;
  std::array<size_t, 3> stride_{};
  std::vector<double> cache_;
};

}  // namespace

GridSearch searchGrid(const FitModel& model, const BrdfSamples& samples, Metric metric, int budget,
                      int threads) {
  const std::vector<Dimension> dims = gridDimensions(model);
  GridSearch search;
  search.dimensions = dims.size();
  std::vector<std::vector<double>> units = unitPoints(dims.size(), std::max(budget, 1), search.cellWidth);
  std::erase_if(units, [&](const std::vector<double>& u) { return !isOrdered(model, dims, u); });
  const MetricSamples linear(samples, linearAnalogue(metric));
  const MetricSamples actual(samples, metric);
  const std::vector<double> start = model.startValues();
  search.points.resize(units.size());
  tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<size_t>(0, units.size(), 1),
                      [&](const tbb::blocked_range<size_t>& range) {
                        ScaleSolver solver(model, linear, &actual);
                        for (size_t i = range.begin(); i != range.end(); ++i) {
                          GridPoint& point = search.points[i];
                          point.unit = units[i];
                          point.x = start;
                          for (size_t k = 0; k < dims.size(); ++k)
                            for (const size_t index : dims[k].parameters)
                              point.x[index] = dims[k].at(units[i][k]);
                          point.cost = solver(point.x);
                        }
                      });
  });
  // A point whose cost is not finite is counted and left out (header comment): it could start
  // no fit, and NaN has no place in the ordering below.
  search.nonFinitePoints =
      size_t(std::erase_if(search.points, [](const GridPoint& point) { return !std::isfinite(point.cost); }));
  // Ties (equal costs) keep the grid's order, so the choice is reproducible.
  std::stable_sort(search.points.begin(), search.points.end(),
                   [](const GridPoint& a, const GridPoint& b) { return a.cost < b.cost; });
  return search;
}

std::vector<GridPoint> distinctStarts(const GridSearch& search, int count) {
  std::vector<GridPoint> starts;
  for (const GridPoint& point : search.points) {
    if (int(starts.size()) >= count) break;
    const bool neighbour = std::any_of(starts.begin(), starts.end(), [&](const GridPoint& chosen) {
      for (size_t k = 0; k < point.unit.size(); ++k)
        if (std::abs(point.unit[k] - chosen.unit[k]) > 1.01 * search.cellWidth) return false;
      return true;
    });
    if (!neighbour) starts.push_back(point);
  }
  return starts;
}

void solveScales(const FitModel& model, const BrdfSamples& samples, Metric metric, std::vector<double>& x) {
  const MetricSamples linear(samples, linearAnalogue(metric));
  ScaleSolver solver(model, linear, nullptr);
  solver(x);
}

}  // namespace scatterlab::fitting
