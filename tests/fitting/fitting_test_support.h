// What the fitting tests share: small measured-style sample sets at MERL cell centres made
// from registry materials or published fit lines, without tabulating all 1,458,000 cells.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "fitting/brdf_fit.h"
#include "fitting/brdf_samples.h"
#include "fitting/fit_model.h"
#include "materials/core/rng.h"
#include "materials/measured/half_diff.h"
#include "materials/measured/merl_format.h"
#include "materials/measured/ngan_fits.h"
#include "materials/registry/spec_validation.h"

namespace scatterlab::fitting::test {

using nlohmann::json;

// The sum of registry materials, evaluated through their BsdfModel (the renderer's path).
class GroundTruth {
 public:
  explicit GroundTruth(const std::vector<json>& components) {
    for (const json& c : components) models_.push_back(makeBsdf(c));
  }
  Rgb operator()(const Vec3d& wi, const Vec3d& wo) const {
    Rgb f(0.0);
    for (const auto& model : models_) f += model->eval(wi, wo);
    return f;
  }

 private:
  std::vector<std::unique_ptr<BsdfModel>> models_;
};

// `perStratum` cells of every (theta_h, theta_d) stratum of the MERL layout, phi_d chosen by
// CounterRng(seed, stratum), at their centres, valued by `truth`: a stratified sample of a
// noise-free MERL table (8100 strata; weight 180 / perStratum each, as stratifiedSubset).
inline BrdfSamples cellSamples(const GroundTruth& truth, int perStratum, uint64_t seed = 1) {
  BrdfSamples samples;
  samples.reserve(size_t(merl::ThetaHalfCells * merl::ThetaDiffCells * perStratum));
  for (int th = 0; th < merl::ThetaHalfCells; ++th)
    for (int td = 0; td < merl::ThetaDiffCells; ++td) {
      const auto stratum = uint32_t(th * merl::ThetaDiffCells + td);
      CounterRng rng(seed, stratum);
      std::vector<int> cells;
      for (int k = 0; k < perStratum; ++k) cells.push_back(int(rng.uniform() * merl::PhiDiffCells));
      std::sort(cells.begin(), cells.end());
      cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
      for (const int pd : cells) {
        const auto [wi, wo] = directionsFromHalfDiff(merl::thetaHalfAt(th + 0.5), 0.0,
                                                     merl::thetaDiffAt(td + 0.5), merl::phiDiffAt(pd + 0.5));
        if (!(wi.z > 0) || !(wo.z > 0)) continue;
        samples.add(wi, wo, truth(wi, wo), double(merl::PhiDiffCells) / double(cells.size()), stratum);
      }
    }
  return samples;
}

inline std::vector<json> publishedFit(const std::string& name, const std::string& file) {
  for (const PublishedFit& fit :
       readPublishedFits(std::filesystem::path(SCATTERLAB_DATA_DIR) / "published-fits" / file))
    if (fit.name == name) return fit.components();
  ADD_FAILURE() << name << " not in " << file;
  return {};
}

inline double parameterValue(const FitModel& model, const std::vector<double>& x, const std::string& name) {
  for (size_t j = 0; j < model.parameterCount(); ++j)
    if (model.parameters()[j].name == name) return x[j];
  ADD_FAILURE() << "no parameter " << name;
  return 0;
}

// Fit options for the small sample sets of the tests: every sample in every stage.
inline FitOptions quickOptions(Metric metric) {
  FitOptions options;
  options.metric = metric;
  options.gridSamples = 8000;
  options.startSamples = 0;  // 0: all samples (no separate refinement)
  options.starts = 2;
  options.gridBudget = 64;
  options.threads = 2;
  return options;
}

}  // namespace scatterlab::fitting::test
