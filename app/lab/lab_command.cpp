#include "app/lab/lab_command.h"

#include <chrono>
#include <ctime>
#include <iostream>
#include <optional>

#include <nlohmann/json.hpp>

#include "app/exit_code.h"
#include "app/explorer/explorer_page.h"
#include "app/lab/check_section.h"
#include "app/lab/fit_section.h"
#include "app/lab/html.h"
#include "app/lab/lab_material.h"
#include "app/lab/lab_settings.h"
#include "app/lab/lab_showcase.h"
#include "app/lab/measured_section.h"
#include "app/lab/phase_timer.h"
#include "app/lab/plots_section.h"
#include "app/lab/renders_section.h"
#include "app/lab/report_page.h"
#include "app/lab/staged_directory.h"
#include "app/lab/subsurface_section.h"
#include "app/option_values.h"
#include "app/output_guard.h"
#include "app/plugin_option.h"
#include "app/progress.h"
#include "materials/core/temporary_files.h"

namespace scatterlab {

namespace {

using nlohmann::json;
namespace fs = std::filesystem;

std::string utcNow() {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm utc{};
  gmtime_r(&now, &utc);
  char buffer[32];
  std::strftime(buffer, sizeof buffer, "%Y-%m-%d %H:%M UTC", &utc);
  return buffer;
}

// Everything one material's report holds, phase by phase.
class MaterialReporter {
 public:
  MaterialReporter(const LabMaterial& material, const LabSettings& settings,
                   const std::vector<LabEnvironment>& environments, const fs::path& reportDir,
                   PhaseTimer& timer, ProgressLine& progress, const std::string& step)
      : m_(material),
        settings_(settings),
        environments_(environments),
        dir_(reportDir / material.folder),
        timer_(timer),
        progress_(progress.callback(step + " " + material.name)) {
    createDirectoriesUninterrupted(dir_);
    report_.name = m_.name;
    report_.folder = m_.folder;
    report_.kind = toString(m_.kind);
    report_.about = m_.about;
    report_.description = m_.description;
  }

  MaterialReport run() {
    const CheckOutcome outcome =
        timer_.time("check", m_.name, [&] { return runLabChecks(m_, settings_, dir_, progress_); });
    report_.passed = outcome.passed();
    report_.verdict = verdictText(outcome);
    report_.sections.push_back(checkSection(m_, outcome, dir_));
    if (m_.bsdf) addBsdfSections();
    if (m_.subsurface) addSubsurfaceSection();
    addRendersSection();
    return std::move(report_);
  }

 private:
  void addBsdfSections() {
    ReportSection plots = timer_.time("plots", m_.name, [&] {
      if (progress_) progress_("lobes and albedo", 0.0);
      return plotsSection(m_, settings_);
    });
    const json& albedo = plots.data["directional_albedo"];
    if (!albedo.empty()) {
      const json& first = albedo.front()["albedo_rgb"];
      report_.keyNumbers.push_back(
          {"albedo at normal incidence",
           html::rgb(Rgb(first[0].get<double>(), first[1].get<double>(), first[2].get<double>()))});
    }
    report_.sections.push_back(std::move(plots));
    if (hasMeasuredData()) {
      ReportSection measured =
          timer_.time("measured", m_.name, [&] { return measuredSection(m_, settings_, dir_); });
      if (m_.table) {
        const double reachable = measured.data["reachable_cells"].get<double>();
        const double missing = measured.data["missing_reachable_cells"].get<double>();
        report_.keyNumbers.push_back(
            {"missing measurements",
             html::number(100.0 * missing / std::max(reachable, 1.0), 3) + "% of the reachable cells"});
      } else {
        report_.keyNumbers.push_back(
            {"RGL file",
             std::to_string(measured.data["tabulated_pairs"].get<size_t>()) + " tabulated pairs"});
      }
      report_.sections.push_back(std::move(measured));
      addFits();
    }
  }

  bool hasMeasuredData() const { return m_.table || m_.rgl; }

  // The fits now; their section once the renders exist, which it quotes (addRendersSection).
  void addFits() {
    fits_ = timer_.time("fit", m_.name, [&] { return fitMaterial(m_, settings_, progress_); });
    fitSectionIndex_ = report_.sections.size();
    report_.sections.push_back(fitSection(m_, settings_, fits_));
    const FamilyFit* best = nullptr;
    const auto meanError = [](const FamilyFit& f) {
      return (f.result.relativeError.x + f.result.relativeError.y + f.result.relativeError.z) / 3.0;
    };
    for (const FamilyFit& f : fits_.families)
      if (!f.result.x.empty() && (!best || meanError(f) < meanError(*best))) best = &f;
    if (best)
      report_.keyNumbers.push_back({"best fit", best->name + ", mean relative error " +
                                                    html::number(meanError(*best), 3) + " (" +
                                                    fitQuality(*best).grade + ")"});
  }

  void addSubsurfaceSection() {
    const SubsurfaceComparison comparison =
        timer_.time("walk", m_.name, [&] { return compareWithWalk(*m_.subsurface, settings_, progress_); });
    ReportSection section = subsurfaceSection(m_, comparison);
    // Walk paths that stopped being finite fail the material, as a failed check.
    if (const uint64_t nonFinite = section.data.value("non_finite_paths", uint64_t(0)); nonFinite > 0) {
      report_.passed = false;
      report_.verdict += "; " + std::to_string(nonFinite) + " walk paths not finite";
    }
    report_.sections.push_back(std::move(section));
    Rgb walk(0.0), se(0.0);
    double worst = 0;
    for (int c = 0; c < 3; ++c) {
      walk[c] = comparison.walk[size_t(c)].totalReflectance;
      se[c] = comparison.walk[size_t(c)].totalStdError;
      if (se[c] > 0) worst = std::max(worst, std::abs(comparison.profileTotal[c] - walk[c]) / se[c]);
    }
    report_.keyNumbers.push_back({"Rd profile", html::rgb(comparison.profileTotal)});
    report_.keyNumbers.push_back(
        {"Rd random walk", html::rgb(walk) + " (largest difference " + html::number(worst, 3) + " se)"});
  }

  // Every material goes to the renderer, which decides what it can render (renders_section.h).
  void addRendersSection() {
    ReportSection renders = timer_.time("render", m_.name, [&] {
      return rendersSection(m_, hasMeasuredData() ? &fits_ : nullptr, settings_, environments_, dir_,
                            progress_);
    });
    // Samples the film dropped (not finite or negative) fail the material, as a failed check.
    if (const uint64_t dropped = renders.data.value("dropped_samples", uint64_t(0)); dropped > 0) {
      report_.passed = false;
      report_.verdict += "; " + std::to_string(dropped) + " render samples dropped";
      report_.keyNumbers.push_back(
          {"renders", std::to_string(dropped) + " samples dropped (not finite or negative)"});
    }
    if (fitSectionIndex_)
      report_.sections[*fitSectionIndex_] = fitSection(m_, settings_, fits_, fitRenderDifferences(renders));
    if (const std::string refusal = renderRefusal(renders); !refusal.empty())
      report_.keyNumbers.push_back({"renders", "not rendered: " + refusal});
    if (const std::string closest = closestFitInRenders(renders); !closest.empty())
      report_.keyNumbers.push_back(
          {"closest fit in the renders", closest + " mean |difference| on the sphere"});
    report_.sections.push_back(std::move(renders));
  }

  const LabMaterial& m_;
  const LabSettings& settings_;
  const std::vector<LabEnvironment>& environments_;
  fs::path dir_;
  PhaseTimer& timer_;
  ProgressCallback progress_;
  MaterialReport report_;
  MaterialFits fits_;
  std::optional<size_t> fitSectionIndex_;
};

// The command as the user could type it again (materials in single quotes).
std::string commandLine(const LabCommandOptions& options) {
  std::string line = "scatterlab lab";
  for (const std::string& material : options.materials) line += " '" + material + "'";
  line += " --out '" + options.out + "'";
  if (options.quick) line += " --quick";
  for (const std::string& environment : options.environments) line += " --env '" + environment + "'";
  line += " --seed " + std::to_string(options.seed);
  return line;
}

void printSummary(const std::vector<MaterialReport>& reports, const fs::path& index, bool asJson,
                  const PhaseTimer& timer) {
  bool allPassed = true;
  for (const MaterialReport& r : reports) allPassed = allPassed && r.passed;
  if (asJson) {
    json materials = json::array();
    for (const MaterialReport& r : reports)
      materials.push_back({{"name", r.name}, {"kind", r.kind}, {"passed", r.passed}, {"verdict", r.verdict}});
    std::cout << json{{"report", index.string()},
                      {"passed", allPassed},
                      {"materials", materials},
                      {"timings", timer.toJson()}}
                     .dump(2, ' ', false, json::error_handler_t::replace)
              << "\n";
    return;
  }
  for (const MaterialReport& r : reports)
    std::cout << (r.passed ? "PASS  " : "FAIL  ") << r.name << " (" << r.kind << "): " << r.verdict << "\n";
  std::cout << "verdict: " << (allPassed ? "PASS" : "FAIL") << "\n";
  std::cout << "report: " << index.string() << "\n";
}

}  // namespace

CLI::App* addLabCommand(CLI::App& app, LabCommandOptions& options) {
  CLI::App* command = app.add_subcommand(
      "lab",
      "Write a static HTML report (DIR/index.html, PNG images, JSON data) on materials: the kit's verdict "
      "with its chi-square maps, lobes, albedo, measured slices, fits and renders; none given: a showcase");
  command->add_option(
      "material", options.materials,
      "Materials: inline JSON, JSON files, or measured files (MERL .binary, RGL .bsdf, told apart by "
      "content); none: the built-in showcase");
  command->add_option("--out", options.out, "Report directory, replaced whole when the report is complete")
      ->type_name("DIR")
      ->capture_default_str();
  command->add_flag("--quick", options.quick,
                    "Fewer samples, angles and paths (the showcase in under 2 minutes on 2 cores)");
  command
      ->add_option("--seed", options.seed, "Seed of every random number; the same seed gives the same report")
      ->type_name("INTEGER")
      ->transform(integerIn(0))
      ->capture_default_str();
  command
      ->add_option("--env", options.environments,
                   "Environment maps for the renders (equirectangular OpenEXR, width = 2 x height); default: "
                   "studio.exr and courtyard.exr of data/envmaps; repeat for more")
      ->type_name("FILE")
      ->allow_extra_args(false);  // one file per --env: a MATERIAL after it stays a material
  command->add_flag("--json", options.json, "Print the verdicts, the report's path and the timings as JSON");
  addPluginOption(*command);
  return command;
}

int runLabCommand(const LabCommandOptions& options) {
  // Every input is checked before the first file is written.
  std::vector<LabMaterial> materials;
  std::vector<InputPath> inputs;
  for (const std::string& argument : options.materials) {
    materials.push_back(loadLabMaterial(argument));
    addMaterialInputs(inputs, argument, materials.back().description);
  }
  makeNamesUnique(materials);
  const std::vector<std::string> environmentFiles =
      options.environments.empty() ? defaultLabEnvironmentFiles() : options.environments;
  const std::vector<LabEnvironment> environments = loadLabEnvironments(environmentFiles);
  for (const std::string& file : environmentFiles) inputs.push_back({"environment map (--env)", file});
  if (options.materials.empty())
    if (const auto cache = showcaseCacheDirectory()) inputs.push_back({"showcase's table cache", *cache});
  StagedDirectory staged(options.out, ReportGenerator, "--out", inputs);

  const LabSettings settings =
      options.quick ? LabSettings::quickMode(options.seed) : LabSettings::fullMode(options.seed);
  ProgressLine progress;
  PhaseTimer timer(!progressIsQuiet(), [&progress] { progress.clear(); });
  const auto start = std::chrono::steady_clock::now();
  if (materials.empty())
    materials = showcaseLabMaterials(staged.path() / "scratch", timer, progress.callback("showcase"));

  std::vector<MaterialReport> reports;
  for (size_t i = 0; i < materials.size(); ++i) {
    const std::string step = "[" + std::to_string(i + 1) + "/" + std::to_string(materials.size()) + "]";
    reports.push_back(
        MaterialReporter(materials[i], settings, environments, staged.path(), timer, progress, step).run());
  }
  // The explorer, preloaded with every material (each section links to it), before the scratch
  // tables it embeds are removed.
  timer.time("explorer", "", [&] {
    std::vector<ExplorerMaterial> explorerMaterials;
    for (const LabMaterial& m : materials) explorerMaterials.push_back({m.folder, m.name, m.description});
    writeExplorer(staged.path() / LabExplorerFolder, explorerMaterials);
  });
  std::error_code error;
  fs::remove_all(staged.path() / "scratch", error);  // tables of a showcase that had no cache directory

  ReportRun run;
  run.mode = settings.quick ? "quick" : "full";
  run.createdAt = utcNow();
  run.settings = settings.toJson();
  run.timings = timer.toJson();
  run.timings["total_wall_seconds"] =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  run.command = commandLine(options);
  timer.time("write", "", [&] { writeReport(staged.path(), run, reports); });
  staged.commit();
  progress.clear();
  if (!progressIsQuiet())
    std::fprintf(stderr, "lab: total %.2f s; open %s\n",
                 std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
                 (staged.target() / "index.html").c_str());
  printSummary(reports, staged.target() / "index.html", options.json, timer);
  bool allPassed = true;
  for (const MaterialReport& r : reports) allPassed = allPassed && r.passed;
  return static_cast<int>(allPassed ? ExitCode::Success : ExitCode::CheckFailed);
}

}  // namespace scatterlab
