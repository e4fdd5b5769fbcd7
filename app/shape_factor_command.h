// `scatterlab shape-factor`: Burley's searchlight shape factor s(A) fitted to the half-space
// random walk over a list of albedos A (fitting/burley_shape_fit.h), next to Christensen &
// Burley 2015's published fit s = 1.85 - A + 7 |A - 0.8|^3 (docs/validation.md section 6).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace scatterlab {

struct ShapeFactorCommandOptions {
  std::vector<double> albedos{0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.85, 0.9, 0.95, 0.99};
  uint64_t paths = 1'000'000;  // per albedo
  double annulusWidth = 0.02;  // mean free paths
  uint64_t seed = 1;
  int threads = 0;
  bool json = false;
};

CLI::App* addShapeFactorCommand(CLI::App& app, ShapeFactorCommandOptions& options);

int runShapeFactorCommand(const ShapeFactorCommandOptions& options);

}  // namespace scatterlab
