#include "app/shape_factor_command.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>

#include <nlohmann/json.hpp>

#include "app/exit_code.h"
#include "app/json_output.h"
#include "app/option_values.h"
#include "app/progress.h"
#include "app/walk_estimate.h"
#include "fitting/burley_shape_fit.h"
#include "materials/core/rng.h"
#include "validation/half_space_reference.h"

namespace scatterlab {

namespace {

using nlohmann::json;

constexpr const char* Metric =
    "least squares of r R(r) over radius (annulus averages; Burley's exact from its CDF), the curve's power "
    "P "
    "free (shape) or held at A (normalised)";

void printTable(const ShapeFactorCommandOptions& options, const std::vector<fitting::BurleyShapeFit>& fits) {
  std::printf(
      "Burley's searchlight shape factor fitted to the half-space random walk: normal incidence, mean free\n"
      "path 1, g 0, index-matched, %llu paths per albedo; metric: %s;\n"
      "annuli of %g mfp. Errors: r-weighted relative error of R(r) at power A against the walk (L1 of the\n"
      "radial power over %d log-spaced annuli, relative to the walk's total) with the shape, normalised and\n"
      "published s; noise: what the walk's noise alone adds to them.\n\n",
      static_cast<unsigned long long>(options.paths), Metric, options.annulusWidth, fitting::ErrorAnnuli);
  std::printf(
      "A      walk albedo c   walk total          shape s            power P   published s  difference  "
      "normalised s       difference  errors: shape normalised published  noise\n");
  double sumShape = 0.0, sumNormalised = 0.0, maxShape = 0.0;
  for (const fitting::BurleyShapeFit& f : fits) {
    const double shape = f.shapeFactor / f.publishedShapeFactor - 1.0;
    const double normalised = f.normalisedShapeFactor / f.publishedShapeFactor - 1.0;
    sumShape += std::abs(shape);
    sumNormalised += std::abs(normalised);
    maxShape = std::max(maxShape, std::abs(shape));
    std::printf(
        "%-6.3g %-15.10f %.5f +- %.5f  %.4f +- %.4f  %.4f    %-12.4f %+9.1f%%  %.4f +- %.4f %+9.1f%%  "
        "%13.1f%% "
        "%9.1f%% %8.1f%%  %4.1f%%\n",
        f.albedo, f.walkAlbedo, f.walkReflectance, f.walkStdError, f.shapeFactor, f.shapeStdError, f.power,
        f.publishedShapeFactor, 100.0 * shape, f.normalisedShapeFactor, f.normalisedStdError,
        100.0 * normalised, 100.0 * f.shapeError, 100.0 * f.normalisedError, 100.0 * f.publishedError,
        100.0 * f.errorNoiseFloor);
  }
  const double n = double(fits.size());
  std::printf(
      "\nshape s against published: mean |difference| %.1f%%, largest %.1f%%; normalised s: mean "
      "|difference| "
      "%.1f%%\n",
      100.0 * sumShape / n, 100.0 * maxShape, 100.0 * sumNormalised / n);
}

json tableJson(const ShapeFactorCommandOptions& options, const std::vector<fitting::BurleyShapeFit>& fits) {
  json rows = json::array();
  for (const fitting::BurleyShapeFit& f : fits)
    rows.push_back({{"albedo", f.albedo},
                    {"walk_albedo", f.walkAlbedo},
                    {"walk_total_reflectance", f.walkReflectance},
                    {"walk_std_error", f.walkStdError},
                    {"published_shape_factor", f.publishedShapeFactor},
                    {"shape_factor", f.shapeFactor},
                    {"shape_factor_std_error", f.shapeStdError},
                    {"power", f.power},
                    {"power_std_error", f.powerStdError},
                    {"difference", f.shapeFactor / f.publishedShapeFactor - 1.0},
                    {"normalised_shape_factor", f.normalisedShapeFactor},
                    {"normalised_std_error", f.normalisedStdError},
                    {"normalised_difference", f.normalisedShapeFactor / f.publishedShapeFactor - 1.0},
                    {"shape_error", f.shapeError},
                    {"normalised_error", f.normalisedError},
                    {"published_error", f.publishedError},
                    {"error_noise_floor", f.errorNoiseFloor},
                    {"termination", f.shapeFit.termination},
                    {"normalised_termination", f.normalisedFit.termination}});
  return {{"configuration", "searchlight: normal incidence, mean free path 1, g 0, index-matched"},
          {"metric", Metric},
          {"annulus_width", options.annulusWidth},
          {"paths", options.paths},
          {"seed", options.seed},
          {"published", "s = 1.85 - A + 7 |A - 0.8|^3 (Christensen & Burley 2015)"},
          {"errors", "r-weighted relative error of R(r) at power A against the walk"},
          {"rows", std::move(rows)}};
}

}  // namespace

CLI::App* addShapeFactorCommand(CLI::App& app, ShapeFactorCommandOptions& options) {
  CLI::App* command = app.add_subcommand(
      "shape-factor",
      "Fit Burley's searchlight shape factor s(A) to half-space random walks over albedos A and print "
      "it next to Christensen & Burley's published fit");
  command->add_option("--albedos", options.albedos, "Total reflectances A to fit at, each in (0, 1)")
      ->delimiter(',')
      ->type_name("LIST")
      ->check(numberIn(ValueRange{0.0, 1.0, true, true}, "a total reflectance"))
      ->capture_default_str();
  command->add_option("--paths", options.paths, "Walk paths per albedo")
      ->type_name("INTEGER")
      ->transform(integerIn(1000, 10'000'000'000))
      ->capture_default_str();
  command
      ->add_option("--annulus-width", options.annulusWidth, "Width of the walk's annuli, in mean free paths")
      ->type_name("MFP")
      ->check(numberIn(ValueRange::closed(1e-4, 1.0), "a width in mean free paths"))
      ->capture_default_str();
  addSeedAndThreadOptions(command, options.seed, options.threads, "walks");
  command->add_flag("--json", options.json, "Print one JSON document");
  return command;
}

int runShapeFactorCommand(const ShapeFactorCommandOptions& options) {
  if (options.albedos.empty())
    throw InputError("--albedos: no albedo given; allowed: a list of values in (0, 1)");
  std::vector<HalfSpaceWalkSettings> walks;
  for (size_t i = 0; i < options.albedos.size(); ++i) {
    walks.push_back(fitting::burleyShapeWalkSettings(options.albedos[i], options.paths,
                                                     deriveSeed(options.seed, i), options.annulusWidth));
    walks.back().threads = options.threads;
  }
  announceWork(estimateWalks("shape-factor: " + std::to_string(walks.size()) + " walks of " +
                                 std::to_string(options.paths) + " paths",
                             walks));
  std::vector<fitting::BurleyShapeFit> fits;
  uint64_t nonFinite = 0;  // walk paths that stopped being finite (half_space_walk.h)
  ProgressLine progress;
  for (size_t i = 0; i < walks.size(); ++i) {
    const double albedo = options.albedos[i];
    const HalfSpaceWalkResult walk =
        simulateHalfSpace(walks[i], progress.walkCallback("walk at A " + std::to_string(albedo)));
    nonFinite += walk.nonFinite;
    fits.push_back(fitting::fitBurleyShapeFactor(walk, albedo));
  }
  progress.clear();
  if (options.json) {
    json table = tableJson(options, fits);
    table["non_finite_paths"] = nonFinite;
    std::cout << jsonText(table) << "\n";
  } else {
    printTable(options, fits);
  }
  if (nonFinite == 0) return static_cast<int>(ExitCode::Success);
  std::cerr << "shape-factor: " << nonFinite
            << " walk paths stopped being finite; they are left out of every tally\n";
  return static_cast<int>(ExitCode::CheckFailed);
}

}  // namespace scatterlab
