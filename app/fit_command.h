// `scatterlab fit DATA --model SPEC --metric NAME`: fits a sum of registry models to a MERL
// table (or to a material tabulated in the MERL layout on the fly) with Ceres
// (fitting/brdf_fit.h), prints the parameters with error bars, the cost, the errors per
// channel, the iterations and the time, and writes the fitted material as registry JSON.
//
// Exit codes: 0 the fit is good (and written, with --out); 1 the fit ran but is poor: Ceres
// did not converge, a channel's relative error exceeds --max-relative-error, or the fitted
// sum has no registry form; it is reported (cost, iterations, termination reason, the
// problems) and NOT written; 2 bad input (nothing written); 3 internal error.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

namespace scatterlab {

struct FitCommandOptions {
  std::string data;   // a MERL .binary file, or a material (inline JSON or a .json file)
  std::string model;  // --model SPEC (fitting/fit_model.h)
  std::string metric;
  int lobes = 1;
  std::string robust = "none";
  std::optional<double> robustScale;
  bool perChannel = false;
  uint64_t samples = 0;  // 0: every usable cell
  uint64_t seed = 1;
  int starts = 3;
  int gridPoints = 256;
  int maxIterations = 100;
  double maxRelativeError = 0.7;  // fit_verdict.h DefaultMaxRelativeError
  int threads = 0;
  std::string out;
  bool json = false;
};

CLI::App* addFitCommand(CLI::App& app, FitCommandOptions& options);

// Validates every input before any work (bad input throws MaterialError or InputError and
// writes nothing); returns 0 or 1 (header comment).
int runFitCommand(const FitCommandOptions& options);

// One fit as the command runs it, validated the same way, printing nothing but the progress line
// (with `progress`) and writing nothing (--out and --json are not used): the report --json prints,
// with "written" null, and the parameters' covariance, row-major p x p in the order of
// report["fit"]["parameters"] (empty when not available: fitting/brdf_fit.h). The Python
// package's sl.fit (docs/python.md).
struct FitReport {
  nlohmann::json report;
  std::vector<double> covariance;
  bool good = false;  // the verdict: the command's exit code 0
};
FitReport fitReport(const FitCommandOptions& options, bool progress);

}  // namespace scatterlab
