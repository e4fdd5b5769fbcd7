#include "app/fit_command.h"

#include <cmath>
#include <cstdio>
#include <functional>
#include <iostream>
#include <memory>
#include <optional>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/exit_code.h"
#include "app/fit_verdict.h"
#include "app/format_number.h"
#include "app/json_output.h"
#include "app/option_values.h"
#include "app/output_guard.h"
#include "app/plugin_option.h"
#include "app/progress.h"
#include "app/staged_outputs.h"
#include "app/synth_command.h"
#include "fitting/brdf_fit.h"
#include "fitting/material_writer.h"
#include "materials/core/atomic_file.h"
#include "materials/core/quoted.h"
#include "materials/measured/measured_file.h"
#include "materials/measured/measurement_synthesis.h"
#include "materials/measured/merl_io.h"
#include "materials/measured/rgl_brdf.h"
#include "materials/registry/material_file.h"
#include "materials/registry/spec_validation.h"

namespace scatterlab {

namespace {

using nlohmann::json;
using namespace fitting;

struct LoadedData {
  std::string label;
  std::string kind;  // "merl", "rgl" or "material"
  MerlSampleCounts counts;
  BrdfSamples samples;
};

// Inline JSON or a material file: anything that is not a measured file (told by content).
bool isMaterialData(const std::string& data) { return isInlineMaterial(data) || !measuredFormatOf(data); }

// An RGL file's own samples (brdf_samples.h samplesFromRgl); its nodes count as cells.
LoadedData loadRgl(const std::string& data) {
  std::unique_ptr<RglBrdf> brdf;
  try {
    brdf = readRglBrdf(data);
  } catch (const TensorFileError& error) {
    throw InputError(std::string(error.what()));
  }
  LoadedData loaded;
  loaded.label = data;
  loaded.kind = "rgl";
  RglSampleCounts counts;
  loaded.samples = samplesFromRgl(*brdf, &counts);
  loaded.counts.cells = counts.nodes;
  loaded.counts.unreachable = counts.belowHorizon;
  loaded.counts.usable = counts.usable;
  if (loaded.samples.empty())
    throw InputError("DATA " + inQuotes(data) + ": no tabulated direction pair above the surface");
  return loaded;
}

// A material tabulated in the MERL layout (no perturbation), a MERL file, or an RGL file (told
// apart by content, whatever the name: materials/measured/measured_file.h); its usable cells.
// `claimOutputs` runs once the data is known to be valid, before the tabulation.
LoadedData loadData(const std::string& data, int threads, const ProgressCallback& tabulating,
                    const std::function<void()>& claimOutputs) {
  const std::optional<MeasuredFormat> format = isInlineMaterial(data) ? std::nullopt : measuredFormatOf(data);
  if (format == MeasuredFormat::Rgl) {
    LoadedData loaded = loadRgl(data);
    claimOutputs();
    return loaded;
  }
  LoadedData loaded;
  MerlTable table;
  if (!format) {
    const json material = loadMaterialArgument(data);
    std::unique_ptr<BsdfModel> model;
    try {
      model = makeBsdf(material);
    } catch (const MaterialError& error) {
      if (isInlineMaterial(data)) throw;
      throw MaterialError("material file " + inQuotes(data) + ": " + error.what());
    }
    loaded.label = isInlineMaterial(data) ? jsonText(material, -1) : data;
    loaded.kind = "material";
    claimOutputs();
    const MeasurementSynthesizer synthesizer({model.get()}, MeasurementPerturbation{});
    table = synthesizeTable(synthesizer, threads, tabulating);
  } else {
    try {
      table = readMerl(data);
    } catch (const MerlError& error) {
      throw InputError(
          std::string(error.what()) +
          "; allowed: a MERL BRDF file (90 x 90 x 180 cells, 34992012 bytes), an RGL .bsdf tensor file, or a "
          "material as inline JSON or a .json file");
    }
    loaded.label = data;
    loaded.kind = "merl";
    claimOutputs();
  }
  loaded.samples = samplesFromMerl(table, &loaded.counts);
  if (loaded.samples.empty())
    throw InputError("DATA " + inQuotes(loaded.label) + ": no valid cells (" +
                     std::to_string(loaded.counts.missing) + " missing, " +
                     std::to_string(loaded.counts.unreachable) +
                     " below the horizon); allowed: a table with measured cells");
  return loaded;
}

FitOptions fitOptionsOf(const FitCommandOptions& options) {
  FitOptions fit;
  fit.metric = *parseMetric(options.metric);
  fit.robust = *parseRobustLoss(options.robust);
  fit.robustScale = options.robustScale;
  fit.gridBudget = options.gridPoints;
  fit.starts = options.starts;
  fit.seed = options.seed;
  fit.maxIterations = options.maxIterations;
  fit.threads = options.threads;
  return fit;
}

std::string rangeText(const ParameterEstimate& e) {
  const auto bound = [](double x) {
    return std::abs(x) >= 1e300 ? std::string("inf") : formatNumber("%g", x);
  };
  return "[" + bound(e.lower) + ", " + bound(e.upper) + "]";
}

void printReport(const FitCommandOptions& options, const LoadedData& data, const FitResult& result,
                 const WrittenMaterial& written, const FitVerdict& verdict, const std::string& writtenPath) {
  std::printf("fit: %s to %s\n", options.model.c_str(), data.label.c_str());
  const std::string fittedOn = result.samples == data.counts.usable
                                   ? "all of them"
                                   : "a stratified subset of " + std::to_string(result.samples);
  if (data.kind == "rgl")
    std::printf(
        "data: %zu direction pairs the file tabulates, weight 1 each (%zu more below the horizon, not "
        "used); fitted on %s\n",
        data.counts.usable, data.counts.unreachable, fittedOn.c_str());
  else
    std::printf("data: %zu usable cells (%zu missing, %zu below the horizon); fitted on %s\n",
                data.counts.usable, data.counts.missing, data.counts.unreachable, fittedOn.c_str());
  const Metric metric = *parseMetric(options.metric);
  std::printf("metric: %s; robust loss: %s", describe(metric).c_str(), options.robust.c_str());
  if (result.robustScale > 0) std::printf(" (scale %.4g)", result.robustScale);
  std::printf("\ngrid: %zu points on %zu samples", result.gridPoints, result.gridSamples);
  // Counted, never silent (fitting/brdf_fit.h): points and starts left out for a cost that is
  // not finite.
  if (result.gridNonFinitePoints > 0)
    std::printf(" (%zu left out: cost not finite)", result.gridNonFinitePoints);
  std::printf("; starts on %zu samples", result.startSamples);
  if (result.nonFiniteStarts > 0)
    std::printf(" (%zu of %zu ended on a cost that is not finite)", result.nonFiniteStarts,
                result.starts.size());
  std::printf(":\n");
  std::printf("  %-5s %14s %14s %10s  %s\n", "start", "initial cost", "final cost", "iterations",
              "termination");
  for (size_t s = 0; s < result.starts.size(); ++s)
    std::printf("  %-5zu %14.6g %14.6g %10d  %s\n", s + 1, result.starts[s].initialCost,
                result.starts[s].finalCost, result.starts[s].iterations,
                result.starts[s].termination.c_str());
  std::printf("final: cost %.6g, %d iterations, %s (%s), %.2f s\n\n", result.final.finalCost,
              result.final.iterations, result.final.termination.c_str(), result.final.message.c_str(),
              result.seconds);
  std::printf("%-40s %14s %12s  %s\n", "parameter", "value", "std dev", "range");
  for (const ParameterEstimate& e : result.parameters)
    std::printf("%-40s %14.6g %12.3g  %s%s\n", e.name.c_str(), e.value, e.standardDeviation,
                rangeText(e).c_str(), e.atBound ? "  at bound" : "");
  std::printf("error bars: sigma^2 = cost / (N - p) = %.4g (N = %zu observations, p = %zu parameters)%s\n",
              result.sigma2, result.observations, result.parameters.size(),
              result.covarianceAvailable ? "" : "; covariance not available");
  for (const std::string& direction : result.unidentified)
    std::printf(
        "warning: rank deficient: %s cannot be determined from the data; the error bars are the "
        "pseudo-inverse's\n",
        direction.c_str());
  std::printf("\n%-8s %14s %16s\n", "channel", "rms (metric)", "relative error");
  for (int c = 0; c < 3; ++c)
    std::printf("%-8c %14.6g %16.4g\n", "rgb"[c], result.rms[c], result.relativeError[c]);
  std::printf("\nverdict: %s\n", verdict.good ? "GOOD" : "POOR");
  for (const std::string& problem : verdict.problems) std::printf("  %s\n", problem.c_str());
  if (written.material) std::printf("material: %s\n", jsonText(*written.material, -1).c_str());
  if (!writtenPath.empty())
    std::printf("wrote %s\n", writtenPath.c_str());
  else if (!options.out.empty())
    std::printf("not written: the fit is poor\n");
}

}  // namespace

CLI::App* addFitCommand(CLI::App& app, FitCommandOptions& options) {
  CLI::App* command = app.add_subcommand(
      "fit",
      "Fit registry models to measured data (a MERL table, an RGL .bsdf file, or a material tabulated like a "
      "MERL table) with Ceres, with error bars; writes the fitted material as registry JSON");
  command
      ->add_option(
          "data", options.data,
          "MERL .binary file, RGL .bsdf file (the file's own tabulated direction pairs; format told by "
          "content), or a material (inline JSON or a .json file) to tabulate")
      ->required();
  command
      ->add_option(
          "--model", options.model,
          "Registry types joined by '+', e.g. lambertian+ngan-cook-torrance; a part may be a JSON object "
          "whose values are held, e.g. {\"type\":\"conductor\",\"distribution\":\"beckmann\"}. A conductor "
          "without metal or eta/k has its index fitted (f0 and edge tint per channel, written as eta and k) "
          "and "
          "is fitted alone; lambertian+{\"type\":\"conductor\",\"eta\":1,\"k\":1e8} is Lambert plus a white "
          "GGX lobe with a fitted RGB scale")
      ->type_name("SPEC")
      ->required();
  command->add_option("--metric", options.metric, "Error metric: l2, ngan, low-l2, low-log, cube-root")
      ->type_name("NAME")
      ->required()
      ->check(choiceOf(metricNames(), "a metric"));
  command->add_option("--lobes", options.lobes, "Copies of the last component (specular lobes)")
      ->type_name("N")
      ->transform(integerIn(1, 3))
      ->capture_default_str();
  command->add_option("--robust", options.robust, "Robust loss: none, huber, cauchy, soft-l1")
      ->type_name("NAME")
      ->check(choiceOf(robustLossNames(), "a robust loss"))
      ->capture_default_str();
  command
      ->add_option(
          "--robust-scale", options.robustScale,
          "Scale of the robust loss in residual units (default: 2.5 robust standard deviations of the "
          "residuals at the best grid point)")
      ->type_name("S")
      ->check(numberIn(ValueRange::above(0.0)));
  command->add_flag("--per-channel", options.perChannel, "Fit the shape parameters per colour channel");
  command
      ->add_option("--samples", options.samples,
                   "Fit a stratified subset of about N cells (0: every usable cell)")
      ->type_name("N")
      ->transform(integerIn(0))
      ->capture_default_str();
  command->add_option("--seed", options.seed, "Seed of the stratified subsets")
      ->type_name("INTEGER")
      ->transform(integerIn(0))
      ->capture_default_str();
  command->add_option("--starts", options.starts, "Ceres runs from the best distinct grid points")
      ->type_name("N")
      ->transform(integerIn(1, 16))
      ->capture_default_str();
  command
      ->add_option("--grid-points", options.gridPoints,
                   "Budget of the initial grid over the shape parameters")
      ->type_name("N")
      ->transform(integerIn(1, 100000))
      ->capture_default_str();
  command->add_option("--max-iterations", options.maxIterations, "Levenberg-Marquardt iterations per run")
      ->type_name("N")
      ->transform(integerIn(1, 100000))
      ->capture_default_str();
  command
      ->add_option(
          "--max-relative-error", options.maxRelativeError,
          "A fit whose relative error (in the metric) exceeds this in any channel is poor: reported, not "
          "written, exit 1")
      ->type_name("E")
      ->check(numberIn(ValueRange::above(0.0)))
      ->capture_default_str();
  command
      ->add_option("--threads", options.threads,
                   "Worker threads (0: all cores); the result does not depend on it")
      ->type_name("N")
      ->transform(integerIn(0, 1024))
      ->capture_default_str();
  command
      ->add_option("--out", options.out,
                   "Write the fitted material (registry JSON) here, atomically, if the fit is good")
      ->type_name("FILE");
  command->add_flag("--json", options.json, "Print the whole report as JSON");
  addPluginOption(*command);
  return command;
}

namespace {

// Everything one fit produced, for the report (text or JSON) and the Python package.
struct FitRun {
  std::vector<json> components;
  std::unique_ptr<FitModel> model;
  FitOptions fitOptions;
  LoadedData data;
  FitResult result;
  WrittenMaterial written;
  FitVerdict verdict;
};

// Checks every input before the data is read or anything is fitted, then fits. With `outputs`,
// --out is checked against the data and claimed before the tabulation or fit (staged_outputs.h);
// without, nothing is claimed or written.
FitRun fitData(const FitCommandOptions& options, std::optional<StagedOutputs>* outputs, bool showProgress) {
  FitRun run;
  try {
    run.components = parseModelSpec(options.model, options.lobes);
  } catch (const MaterialError& error) {
    throw MaterialError(std::string("--model: ") + error.what());
  }
  try {
    run.model = std::make_unique<FitModel>(run.components, options.perChannel);
  } catch (const MaterialError& error) {
    throw MaterialError(std::string("--model: ") + error.what());
  }
  run.fitOptions = fitOptionsOf(options);
  if (run.fitOptions.robust == RobustLoss::None && options.robustScale)
    throw InputError("--robust-scale: only applies with --robust huber, cauchy or soft-l1");

  std::vector<InputPath> inputs;
  if (isMaterialData(options.data))
    addMaterialInputs(inputs, options.data, loadMaterialArgument(options.data));
  else
    inputs.push_back({"data file", options.data});
  if (outputs) {
    outputs->emplace(inputs);
    if (!options.out.empty()) (*outputs)->addFile("--out", options.out, "fit.json");
  }
  // A plugin model without a fit kernel is differentiated numerically: say so before the work.
  for (const std::string& note : run.model->derivativeNotes())
    std::cerr << "scatterlab: note: " << note << "\n";

  ProgressLine progress;
  ProgressLine* shown = showProgress ? &progress : nullptr;
  const auto callback = [&](const char* stage) {
    return shown ? shown->callback(stage) : ProgressCallback();
  };
  run.data = loadData(options.data, options.threads, callback("tabulating"), [&] {
    if (outputs) (*outputs)->prepare();
  });
  const BrdfSamples samples = stratifiedSubset(run.data.samples, options.samples, options.seed);
  run.fitOptions.progress = callback("fit");
  run.result = fitBrdf(*run.model, samples, run.fitOptions);
  progress.clear();

  run.written = writeMaterial(run.model->fittedParts(run.result.x.data()));
  run.verdict = judgeFit(run.result, run.written, options.maxRelativeError);
  return run;
}

json reportJson(const FitCommandOptions& options, const FitRun& run, const std::string& writtenPath) {
  const LoadedData& data = run.data;
  return {{"data",
           {{"source", data.label},
            {"kind", data.kind},
            {"usable_cells", data.counts.usable},
            {"missing_cells", data.counts.missing},
            {"unreachable_cells", data.counts.unreachable}}},
          {"model", options.model},
          {"components", run.components},
          {"lobes", options.lobes},
          {"per_channel", options.perChannel},
          {"derivative_notes", run.model->derivativeNotes()},
          {"fit", toJson(run.result, *run.model, run.fitOptions)},
          {"material", run.written.material ? *run.written.material : json()},
          {"material_problem", run.written.problem},
          {"verdict", run.verdict.good ? "good" : "poor"},
          {"problems", run.verdict.problems},
          {"written", writtenPath.empty() ? json() : json(writtenPath)}};
}

}  // namespace

FitReport fitReport(const FitCommandOptions& options, bool progress) {
  const FitRun run = fitData(options, nullptr, progress);
  FitReport report{reportJson(options, run, ""), {}, run.verdict.good};
  const Eigen::MatrixXd& covariance = run.result.covariance;
  for (Eigen::Index i = 0; i < covariance.rows(); ++i)
    for (Eigen::Index j = 0; j < covariance.cols(); ++j) report.covariance.push_back(covariance(i, j));
  return report;
}

int runFitCommand(const FitCommandOptions& options) {
  std::optional<StagedOutputs> outputs;
  const FitRun run = fitData(options, &outputs, true);
  std::string writtenPath;
  if (run.verdict.good && !options.out.empty()) {
    writeTextFileAtomically(outputs->staged(options.out), run.written.material->dump(2) + "\n");
    outputs->commit();
    writtenPath = options.out;
  }
  if (options.json)
    std::cout << jsonText(reportJson(options, run, writtenPath)) << "\n";
  else
    printReport(options, run.data, run.result, run.written, run.verdict, writtenPath);
  return static_cast<int>(run.verdict.good ? ExitCode::Success : ExitCode::CheckFailed);
}

}  // namespace scatterlab
