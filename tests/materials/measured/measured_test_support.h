// What the measured-BRDF tests share: tables synthesised from registry materials or from
// published fits (data/published-fits), and scratch paths.
#pragma once

#include <gtest/gtest.h>

#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "materials/measured/measurement_synthesis.h"
#include "materials/measured/ngan_fits.h"
#include "materials/registry/spec_validation.h"

namespace scatterlab::measured_test {

// A fresh path under the test output directory, unique per process and call.
inline std::filesystem::path scratchPath(const std::string& stem) {
  static std::atomic<int> counter{0};
  const auto dir = std::filesystem::path(SCATTERLAB_TEST_OUTPUT_DIR) / "measured";
  std::filesystem::create_directories(dir);
  const auto path = dir / (stem + "-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
  std::filesystem::remove_all(path);
  return path;
}

// The registry materials of one published fit line.
inline std::vector<nlohmann::json> publishedFit(const std::string& name,
                                                const std::string& file = "ngan_cooktorrance.fit") {
  for (const PublishedFit& fit :
       readPublishedFits(std::filesystem::path(SCATTERLAB_DATA_DIR) / "published-fits" / file))
    if (fit.name == name) return fit.components();
  ADD_FAILURE() << name << " not in " << file;
  return {};
}

// The models of `components` (registry materials), and the table their sum gives.
struct SynthesisedTable {
  std::vector<std::unique_ptr<BsdfModel>> models;
  MerlTable table;

  // f of the ground truth at (wi, wo).
  Rgb truth(const Vec3d& wi, const Vec3d& wo) const {
    Rgb f(0.0);
    for (const auto& model : models) f += model->eval(wi, wo);
    return f;
  }
};

inline SynthesisedTable synthesise(const std::vector<nlohmann::json>& components,
                                   const MeasurementPerturbation& perturbation = {}) {
  SynthesisedTable out;
  std::vector<const BsdfModel*> pointers;
  for (const nlohmann::json& material : components) {
    out.models.push_back(makeBsdf(material));
    pointers.push_back(out.models.back().get());
  }
  out.table = MeasurementSynthesizer(pointers, perturbation).synthesize();
  return out;
}

}  // namespace scatterlab::measured_test
