#include "app/synth_command.h"

#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#include <nlohmann/json.hpp>

#include "app/exit_code.h"
#include "app/json_output.h"
#include "app/measured_bundle.h"
#include "app/option_values.h"
#include "app/output_guard.h"
#include "app/plugin_option.h"
#include "app/progress.h"
#include "app/staged_outputs.h"
#include "app/table_cache.h"
#include "materials/core/atomic_file.h"
#include "materials/core/quoted.h"
#include "materials/measured/merl_io.h"
#include "materials/measured/ngan_fits.h"
#include "materials/registry/material_file.h"
#include "materials/registry/spec_validation.h"

namespace scatterlab {

namespace {

using nlohmann::json;
namespace fs = std::filesystem;

// The models whose sum is tabulated, and how --json describes them.
struct GroundTruth {
  std::string label;
  json description;
  std::vector<std::unique_ptr<BsdfModel>> models;

  std::vector<const BsdfModel*> components() const {
    std::vector<const BsdfModel*> out;
    for (const auto& model : models) out.push_back(model.get());
    return out;
  }
};

// A table holds f at directions spread over the hemisphere: delta lobes (a mirror, smooth
// glass) put nothing there, and transmission is not tabulated.
bool reflectsIntoTable(const BsdfModel& model) {
  return hasAny(model.flags(), LobeFlags::Reflection) &&
         hasAny(model.flags(), LobeFlags::Diffuse | LobeFlags::Glossy);
}

GroundTruth fromMaterialArgument(const std::string& argument, std::vector<InputPath>& inputs) {
  const json material = loadMaterialArgument(argument);
  addMaterialInputs(inputs, argument, material);
  try {
    GroundTruth truth{isInlineMaterial(argument) ? jsonText(material, -1) : argument, json::object(), {}};
    const json completed = completeMaterial(material);
    truth.models.push_back(makeBsdf(material));
    if (!reflectsIntoTable(*truth.models.back()))
      throw MaterialError("material key \"type\": " + inQuotes(completed.value("type", std::string())) +
                          " has no diffuse or glossy reflection (" + toString(truth.models.back()->flags()) +
                          "), so its table would hold nothing; allowed: a material that reflects over the "
                          "hemisphere");
    truth.description = {{"material", completed}};
    return truth;
  } catch (const MaterialError& error) {
    if (isInlineMaterial(argument)) throw;
    throw MaterialError("material file " + inQuotes(argument) + ": " + error.what());
  }
}

GroundTruth fromFit(const PublishedFit& fit, const std::string& source) {
  GroundTruth truth{fit.name, json::object(), {}};
  json components = json::array();
  try {
    for (const json& component : fit.components()) {
      components.push_back(completeMaterial(component));
      truth.models.push_back(makeBsdf(component));
    }
  } catch (const MaterialError& error) {
    throw MaterialError("published fit " + inQuotes(fit.name) + " of " + inQuotes(source) + ": " +
                        error.what());
  }
  truth.description = {
      {"fit", {{"file", source}, {"name", fit.name}, {"line", fit.line}, {"components", components}}}};
  return truth;
}

GroundTruth fromFitFile(const std::string& file, const std::string& name) {
  const std::vector<PublishedFit> fits = readPublishedFits(file);
  for (const PublishedFit& fit : fits)
    if (fit.name == name) return fromFit(fit, file);
  std::string names;
  for (size_t i = 0; i < fits.size() && i < 8; ++i) names += (i ? ", " : "") + inQuotes(fits[i].name);
  if (fits.size() > 8) names += ", ... (" + std::to_string(fits.size()) + " in all)";
  throw InputError("--name: " + inQuotes(name) + " is not a material of " + inQuotes(file) +
                   (fits.empty() ? "; the file has no fits" : "; allowed: one of " + names));
}

MeasurementPerturbation perturbationOf(const SynthCommandOptions& options) {
  MeasurementPerturbation p;
  p.gainSigma = options.gainSigma;
  p.logSigma = options.logNoise;
  p.noiseFloor = options.noiseFloor;
  p.missingAboveDeg = options.missingAboveDeg;
  p.seed = options.seed;
  return p;
}

json perturbationJson(const MeasurementPerturbation& p) {
  return {{"seed", p.seed},
          {"gain_sigma", p.gainSigma},
          {"log_noise", p.logSigma},
          {"noise_floor", p.noiseFloor},
          {"missing_above_deg", p.missingAboveDeg ? json(*p.missingAboveDeg) : json()}};
}

// Synthesises, writes `written` (atomically; the output's temporary when it is staged), and
// returns what --json reports about `out`.
json synthesizeAndWrite(const GroundTruth& truth, const MeasurementPerturbation& perturbation,
                        const fs::path& out, const fs::path& written, int threads, ProgressLine& progress,
                        const std::string& step) {
  const MeasurementSynthesizer synthesizer(truth.components(), perturbation);
  const auto start = std::chrono::steady_clock::now();
  const MerlTable table = synthesizeTable(synthesizer, threads, progress.callback(step + " " + truth.label));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  try {
    writeMerl(written, table);
  } catch (const MerlError& error) {
    throw InputError(std::string("--out: ") + error.what());
  }
  const Rgb gains = synthesizer.channelGains();
  json entry{{"file", out.string()},
             {"bytes", merl::FileBytes},
             {"missing_cells", table.missingCount()},
             {"channel_gains", {gains.x, gains.y, gains.z}},
             {"seconds", seconds},
             {"perturbation", perturbationJson(perturbation)}};
  entry.update(truth.description);
  return entry;
}

void printWritten(const json& entry, const std::string& label) {
  if (entry.value("cached", false)) {
    std::cout << "cached " << entry["file"].get<std::string>() << " (" << label << ")\n";
    return;
  }
  std::cout << "wrote " << entry["file"].get<std::string>() << ": " << label << ", "
            << entry["missing_cells"].get<size_t>() << " missing cells, " << entry["seconds"].get<double>()
            << " s\n";
}

fs::path bundleDirectory(const std::string& given) {
  if (!given.empty()) return given;
  const auto directory = defaultBundleDirectory();
  if (!directory)
    throw InputError(
        "--bundle: no directory given and none of SCATTERLAB_CACHE_DIR, XDG_CACHE_HOME, HOME is set; "
        "allowed: --bundle DIR");
  return *directory;
}

// Every bundle material not already in the cache (same fit line and perturbation, file of
// the right size), then the manifest that records what each file is.
int runBundle(const SynthCommandOptions& options, const MeasurementPerturbation& perturbation) {
  const fs::path directory = bundleDirectory(*options.bundle);
  createOutputDirectory("--bundle", directory, "; allowed: a directory");
  TableCache cache(directory);

  json written = json::array();
  ProgressLine progress;
  const auto bundle = measuredBundle();
  for (size_t i = 0; i < bundle.size(); ++i) {
    const BundleMaterial& material = bundle[i];
    const fs::path file = cache.file(material.name);
    const json source{{"fit_file", BundleFitFile},
                      {"fit", material.fitLine},
                      {"perturbation", perturbationJson(perturbation)}};
    json entry;
    if (!options.force && cache.holds(material.name, source)) {
      entry = {{"file", file.string()}, {"cached", true}};
    } else {
      const GroundTruth truth = fromFit(parsePublishedFitLine(material.fitLine), BundleFitFile);
      const std::string step = "[" + std::to_string(i + 1) + "/" + std::to_string(bundle.size()) + "]";
      entry = synthesizeAndWrite(truth, perturbation, file, file, options.threads, progress, step);
      entry["cached"] = false;
      cache.record(material.name, material.category, source);
    }
    entry["name"] = material.name;
    entry["category"] = material.category;
    progress.clear();
    if (!options.json) printWritten(entry, std::string(material.name) + ", " + material.category);
    written.push_back(std::move(entry));
  }
  if (options.json)
    std::cout << json{{"bundle", directory.string()},
                      {"manifest", cache.manifestPath().string()},
                      {"written", written}}
                     .dump(2, ' ', false, json::error_handler_t::replace)
              << "\n";
  else
    std::cout << "bundle: " << directory.string() << " (" << bundle.size() << " materials, manifest "
              << cache.manifestPath().filename().string() << ")\n";
  return static_cast<int>(ExitCode::Success);
}

}  // namespace

MerlTable synthesizeTable(const MeasurementSynthesizer& synthesizer, int threads,
                          const ProgressCallback& progress) {
  MerlTable table;
  std::atomic<int> done{0};
  tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
  arena.execute([&] {
    // One theta_h cell (16,200 table cells) per task: cells near the pole cost the same as
    // the others, so equal chunks balance.
    tbb::parallel_for(tbb::blocked_range<int>(0, merl::ThetaHalfCells, 1),
                      [&](const tbb::blocked_range<int>& range) {
                        synthesizer.fillThetaHalfCells(range.begin(), range.end(), table);
                        const int finished = done += range.size();
                        if (progress) progress("synthesising", double(finished) / merl::ThetaHalfCells);
                      });
  });
  return table;
}

CLI::App* addSynthCommand(CLI::App& app, SynthCommandOptions& options) {
  CLI::App* command = app.add_subcommand(
      "synth",
      "Write measured-style MERL tables (.binary) from a material, a published fit or the named bundle, "
      "optionally perturbed like a measurement");
  command->add_option("material", options.material, "Material to tabulate: inline JSON or a JSON file");
  command
      ->add_option("--fit", options.fitFile, "Published-fits file (data/published-fits/*.fit); with --name")
      ->type_name("FILE");
  command->add_option("--name", options.fitName, "Material (line) of the --fit file, e.g. alum-bronze")
      ->type_name("MATERIAL");
  command
      ->add_option_function<std::vector<std::string>>(
          "--bundle",
          [&options](const std::vector<std::string>& values) {
            options.bundle = values.empty() ? "" : values.front();
          },
          "Generate the named bundle (10 MERL materials from their Ngan Cook-Torrance fits) into DIR, "
          "default "
          "$XDG_CACHE_HOME/scatterlab/merl-bundle; files already there with the same source are kept")
      ->type_name("[DIR]")
      ->expected(0, 1)
      ->allow_extra_args(false);
  command->add_option("--out", options.out, "Output MERL file (with MATERIAL or --fit)")->type_name("FILE");
  command->add_option("--seed", options.seed, "Seed of the perturbations; the same seed gives the same bytes")
      ->type_name("INTEGER")
      ->transform(integerIn(0))
      ->capture_default_str();
  command
      ->add_option("--gain-sigma", options.gainSigma, "Per-channel gain error: each channel times exp(S z)")
      ->type_name("S")
      ->check(numberIn(ValueRange::closed(0.0, 1.0)))
      ->capture_default_str();
  command
      ->add_option("--log-noise", options.logNoise,
                   "Multiplicative log-normal noise per cell and channel, sigma of ln (mean-preserving)")
      ->type_name("SIGMA")
      ->check(numberIn(ValueRange::closed(0.0, 2.0)))
      ->capture_default_str();
  command
      ->add_option("--noise-floor", options.noiseFloor,
                   "Additive noise of std sqrt(F^2 + F f) (floor plus shot noise), clamped at 0; in 1/sr")
      ->type_name("F")
      ->check(numberIn(ValueRange::closed(0.0, 1000.0)))
      ->capture_default_str();
  command
      ->add_option("--missing-above", options.missingAboveDeg,
                   "Mark cells whose wi or wo is further than DEG from the normal as missing (-1)")
      ->type_name("DEG")
      ->check(numberIn(ValueRange{0.0, 90.0, true, false}, "degrees"));
  command
      ->add_option("--threads", options.threads,
                   "Worker threads (0: all cores); the output does not depend on it")
      ->type_name("N")
      ->transform(integerIn(0, 1024))
      ->capture_default_str();
  command->add_flag("--force", options.force, "With --bundle: regenerate files already in the cache");
  command->add_flag("--json", options.json, "Print what was written as JSON");
  addPluginOption(*command);
  return command;
}

int runSynthCommand(const SynthCommandOptions& options) {
  const int sources =
      int(!options.material.empty()) + int(!options.fitFile.empty()) + int(options.bundle.has_value());
  const std::string allowed = "; allowed: one of MATERIAL, --fit FILE --name MATERIAL, or --bundle [DIR]";
  if (sources == 0) throw InputError("synth: nothing to tabulate" + allowed);
  if (sources > 1) throw InputError("synth: more than one source given" + allowed);
  if (!options.fitFile.empty() && options.fitName.empty())
    throw InputError("--fit: needs --name MATERIAL" + allowed);
  if (options.fitFile.empty() && !options.fitName.empty())
    throw InputError("--name: needs --fit FILE" + allowed);
  if (options.force && !options.bundle) throw InputError("--force: only applies to --bundle");
  const MeasurementPerturbation perturbation = perturbationOf(options);
  if (options.bundle) {
    if (!options.out.empty()) throw InputError("--out: not used with --bundle (the bundle names its files)");
    return runBundle(options, perturbation);
  }
  std::vector<InputPath> inputs;
  if (!options.fitFile.empty()) inputs.push_back({"published-fits file (--fit)", options.fitFile});
  const GroundTruth truth = options.fitFile.empty() ? fromMaterialArgument(options.material, inputs)
                                                    : fromFitFile(options.fitFile, options.fitName);
  StagedOutputs outputs(inputs);
  outputs.addFile("--out", options.out, "gold.binary");
  outputs.prepare();
  json entry;
  {
    ProgressLine progress;
    entry = synthesizeAndWrite(truth, perturbation, options.out, outputs.staged(options.out), options.threads,
                               progress, "synth");
  }
  outputs.commit();
  if (options.json)
    std::cout << jsonText(json{{"written", json::array({entry})}}) << "\n";
  else
    printWritten(entry, truth.label);
  return static_cast<int>(ExitCode::Success);
}

}  // namespace scatterlab
