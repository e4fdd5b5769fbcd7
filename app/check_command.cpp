#include "app/check_command.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/exit_code.h"
#include "app/json_output.h"
#include "app/option_values.h"
#include "app/output_guard.h"
#include "app/plugin_option.h"
#include "app/progress.h"
#include "app/render_agreement.h"
#include "app/showcase.h"
#include "app/staged_outputs.h"
#include "materials/bssrdf/subsurface_registry.h"
#include "materials/measured/tabulated_brdf.h"
#include "materials/registry/material_file.h"
#include "materials/registry/spec_validation.h"
#include "validation/check_bsdf.h"
#include "validation/chi_square.h"
#include "validation/chi_square_images.h"
#include "validation/negative_controls.h"
#include "validation/subsurface_check.h"

namespace scatterlab {

namespace {

using nlohmann::json;

// The roughness-mismatch negative control (docs/validation.md, "Negative controls"): sample from a
// roughness 10% off the one pdf() uses.
constexpr double RoughnessMismatchFactor = 1.1;

constexpr uint64_t MinSamples = 1000;
// --render-agreement: below 16 samples per pixel the pilot renders that choose the pixels
// compared have 4 or fewer, and almost no pixel qualifies; above 2^16 one material takes hours.
constexpr int MinRenderSpp = 16, MaxRenderSpp = 65536;
constexpr uint64_t MaxSamples = 100'000'000'000;

struct MaterialUnderTest {
  std::string label;  // names the material's rows and its image files
  json completed;
  std::unique_ptr<BsdfModel> model;  // a BSDF, or
  std::optional<SubsurfaceMaterial> subsurface;
  // With --negative-controls, for models that have a roughness.
  std::unique_ptr<BsdfModel> roughnessMismatchSampler;
};

// The material is validated here, once; what is built from it takes the typed value.
MaterialUnderTest prepareMaterial(std::string label, const json& material, bool negativeControls) {
  const ValidatedMaterial validated = validateMaterial(material);
  if (validated.isSubsurface())
    return {std::move(label), validated.completed, nullptr, makeSubsurface(validated), nullptr};
  MaterialUnderTest prepared{std::move(label), validated.completed, makeBsdf(validated), std::nullopt,
                             nullptr};
  if (negativeControls) prepared.roughnessMismatchSampler = makeRoughnessMismatchSampler(validated);
  return prepared;
}

// A file's material errors name the file: with several materials the user must know which.
MaterialUnderTest prepareArgument(const std::string& argument, bool negativeControls,
                                  std::vector<InputPath>& inputs) {
  const json material = loadMaterialArgument(argument);
  addMaterialInputs(inputs, argument, material);
  if (isInlineMaterial(argument)) return prepareMaterial(jsonText(material, -1), material, negativeControls);
  try {
    return prepareMaterial(argument, material, negativeControls);
  } catch (const MaterialError& error) {
    throw MaterialError("material file \"" + argument + "\": " + error.what());
  }
}

// Rows and image files are told apart by label, so the same material given twice gets a
// numbered second label.
void makeLabelsUnique(std::vector<MaterialUnderTest>& materials) {
  std::set<std::string> used;
  for (MaterialUnderTest& material : materials) {
    const std::string base = material.label;
    for (int copy = 2; !used.insert(material.label).second; ++copy)
      material.label = base + " #" + std::to_string(copy);
  }
}

std::vector<MaterialUnderTest> prepareMaterials(const CheckCommandOptions& options,
                                                std::vector<InputPath>& inputs) {
  std::vector<MaterialUnderTest> materials;
  if (options.materials.empty()) {
    for (const ShowcaseMaterial& showcase : showcaseMaterials())
      materials.push_back(prepareMaterial(showcase.name, showcase.material, options.negativeControls));
  } else {
    for (const std::string& argument : options.materials)
      materials.push_back(prepareArgument(argument, options.negativeControls, inputs));
  }
  makeLabelsUnique(materials);
  return materials;
}

CheckReport checkMaterial(const MaterialUnderTest& material, const BsdfCheckOptions& kit,
                          bool negativeControls, const ProgressCallback& progress) {
  if (material.subsurface) {
    CheckReport report = runSubsurfaceChecks(material.subsurface->bssrdf(), material.label,
                                             subsurfaceCheckOptions(kit), progress);
    if (negativeControls)
      report.append(runSubsurfaceNegativeControls(*material.subsurface->profile, material.label,
                                                  subsurfaceCheckOptions(kit), progress));
    return report;
  }
  return checkBsdf(*material.model, {.kit = kit,
                                     .negativeControls = negativeControls,
                                     .roughnessMismatchSampler = material.roughnessMismatchSampler.get(),
                                     .label = material.label,
                                     .progress = progress});
}

// `kit` as run; the images are reported where they end up (options), not where they were staged.
// The run's wall time and memory, from a pilot of each material: the kit with its samples
// and its cells both k times fewer at one incident angle (the kit's cost is linear in both),
// timed, times k and the number of angles. Only for runs that could last minutes.
WorkEstimate estimateCheck(const std::vector<MaterialUnderTest>& materials, const BsdfCheckOptions& kit,
                           bool negativeControls) {
  const double angles = double(kit.wiThetaDeg.size());
  const double cells = double(kit.thetaBins) * double(kit.phiBins);
  WorkEstimate estimate{"check: " + std::to_string(materials.size()) + " material(s), " +
                            std::to_string(kit.samples) + " samples on a " + std::to_string(kit.thetaBins) +
                            "x" + std::to_string(kit.phiBins) + " grid per test",
                        0.0,
                        // Per worker thread: the histogram and the expected counts, 8 bytes a cell each,
                        // plus the process itself.
                        30e6 + 16.0 * cells * double(std::max(1u, std::thread::hardware_concurrency()))};
  constexpr double PilotAboveWork = 5e7;  // samples (or 100 x cells) per run: about ten seconds
  const double work = double(materials.size()) * angles * (negativeControls ? 5.0 : 1.0) *
                      (double(kit.samples) + 100.0 * cells);
  if (work < PilotAboveWork) return estimate;
  constexpr double PilotSamples = 2e4, PilotCells = 512;
  const double k = std::max({1.0, double(kit.samples) / PilotSamples, cells / PilotCells});
  BsdfCheckOptions pilot = kit;
  pilot.samples = std::max<size_t>(1000, size_t(double(kit.samples) / k));
  pilot.thetaBins = std::max(MinGridCells, int(kit.thetaBins / std::sqrt(k)));
  pilot.phiBins = std::max(MinGridCells, int(kit.phiBins / std::sqrt(k)));
  pilot.wiThetaDeg = {kit.wiThetaDeg.front()};
  pilot.imageDir.reset();
  for (const MaterialUnderTest& material : materials) {
    const auto start = std::chrono::steady_clock::now();
    checkMaterial(material, pilot, negativeControls, {});
    estimate.seconds +=
        k * angles * std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  return estimate;
}

json optionsJson(const CheckCommandOptions& options, const BsdfCheckOptions& kit) {
  return {{"wi_theta_deg", kit.wiThetaDeg},
          {"wi_phi_deg", kit.wiPhiDeg},
          {"samples", kit.samples},
          {"grid", {kit.thetaBins, kit.phiBins}},
          {"seed", kit.seed},
          {"alpha", kit.alpha},
          {"chi_square_test_count", kit.chiSquareTestCount},
          {"negative_controls", options.negativeControls},
          {"render_agreement_spp", options.renderAgreementSpp ? json(*options.renderAgreementSpp) : json()},
          {"images", options.kit.imageDir ? json(options.kit.imageDir->string()) : json()}};
}

// A measured table's missing cells (negative in the file), which the fill rule of
// tabulated_brdf.h replaces; nothing for other models.
std::optional<size_t> missingCellsOf(const BsdfModel* model) {
  const auto* table = dynamic_cast<const TabulatedBrdf*>(model);
  return table ? std::optional<size_t>(table->missingCells()) : std::nullopt;
}

void printJson(const CheckCommandOptions& options, const BsdfCheckOptions& kit,
               const std::vector<MaterialUnderTest>& materials, const CheckReport& report) {
  json materialsJson = json::array();
  for (const MaterialUnderTest& material : materials) {
    materialsJson.push_back({{"label", material.label}, {"material", material.completed}});
    if (const auto missing = missingCellsOf(material.model.get()))
      materialsJson.back()["missing_cells"] = *missing;
  }
  const json document{{"options", optionsJson(options, kit)},
                      {"materials", std::move(materialsJson)},
                      {"report", toJson(report)},
                      {"passed", report.passed()}};
  std::cout << jsonText(document) << "\n";
}

void printText(const std::vector<MaterialUnderTest>& materials, const CheckReport& report) {
  std::cout << "materials (every default filled in):\n";
  for (const MaterialUnderTest& material : materials) {
    std::cout << "  " << material.label << " = " << jsonText(material.completed, -1) << "\n";
    if (const auto missing = missingCellsOf(material.model.get()); missing && *missing > 0)
      std::cout << "    " << *missing << " of " << merl::CellCount
                << " cells missing in the file, filled from the nearest measured cell along theta_d\n";
  }
  std::cout << formatVerdict(report);
}

}  // namespace

std::unique_ptr<BsdfModel> makeRoughnessMismatchSampler(const ValidatedMaterial& material) {
  const auto mismatched = withMismatchedRoughness(material, RoughnessMismatchFactor);
  return mismatched ? makeBsdf(*mismatched) : nullptr;
}

SubsurfaceCheckOptions subsurfaceCheckOptions(const BsdfCheckOptions& kit) {
  SubsurfaceCheckOptions options;
  options.samples = kit.samples;
  options.radiusBins = kit.thetaBins;
  options.probeRings = std::max(kit.thetaBins / 2, 2);
  options.probeSectors = std::max(kit.phiBins / 4, 2);
  options.seed = kit.seed;
  options.alpha = kit.alpha;
  options.chiSquareTestCount = kit.chiSquareTestCount;
  options.imageDir = kit.imageDir;
  options.imagesOnFailureOnly = kit.imagesOnFailureOnly;
  return options;
}

CLI::App* addCheckCommand(CLI::App& app, CheckCommandOptions& options) {
  CLI::App* command = app.add_subcommand(
      "check",
      "Test materials' sampling, pdf, energy and reciprocity statistically; exit 0 only if all pass");
  BsdfCheckOptions& kit = options.kit;
  command->add_option(
      "material", options.materials,
      "Materials: inline JSON ('{\"type\": \"conductor\"}'), JSON files, or measured files (a MERL .binary "
      "table or an RGL .bsdf file, told apart by content); none: a built-in showcase");
  // One value per --wi-theta, split at commas, so that the materials after it stay positional.
  command->add_option("--wi-theta", kit.wiThetaDeg, "Incident polar angles in degrees, comma-separated")
      ->type_name("DEGREES")
      ->delimiter(',')
      ->allow_extra_args(false)
      ->check(numberIn(ValueRange{0.0, 90.0, false, true}, "degrees"))
      ->capture_default_str();
  command->add_option("--wi-phi", kit.wiPhiDeg, "Incident azimuth in degrees")
      ->type_name("DEGREES")
      ->check(numberIn(ValueRange::closed(-360.0, 360.0), "degrees"))
      ->capture_default_str();
  command->add_option("--samples", kit.samples, "Samples per chi-square test")
      ->type_name("INTEGER")
      ->transform(integerIn(MinSamples, MaxSamples))
      ->capture_default_str();
  command
      ->add_option_function<std::string>(
          "--grid",
          [&kit](const std::string& text) {
            const GridSize grid = *parseGrid(text);
            kit.thetaBins = grid.cosThetaCells;
            kit.phiBins = grid.phiCells;
          },
          "Chi-square grid: cos(theta) cells x phi cells")
      ->type_name("COSxPHI")
      ->check(gridValidator())
      ->default_str(std::to_string(kit.thetaBins) + "x" + std::to_string(kit.phiBins));
  command->add_option("--seed", kit.seed, "Seed of the random numbers; the same seed gives the same numbers")
      ->type_name("INTEGER")
      ->transform(integerIn(0))
      ->capture_default_str();
  command
      ->add_option("--alpha", kit.alpha,
                   "Family-wise significance, Sidak-corrected over every chi-square test")
      ->type_name("NUMBER")
      ->check(numberIn(ValueRange{0.0, 0.5, true, false}))
      ->capture_default_str();
  command
      ->add_option_function<std::string>(
          "--images", [&kit](const std::string& directory) { kit.imageDir = directory; },
          "Write observed, expected and residual PNG maps into this directory")
      ->type_name("DIR")
      ->check(outputDirectoryValidator());
  command->add_flag("--negative-controls", options.negativeControls,
                    "Also run deliberately wrong samplers, which the kit must reject");
  command
      ->add_option("--render-agreement", options.renderAgreementSpp,
                   "Also render each BSDF material on the preview scene by path tracing, light tracing and "
                   "BDPT (16 x 12 pixels, this many path-traced samples per pixel; 1024 is thorough) and "
                   "test that the renders agree pixel by pixel, which proves the material's adjoint")
      ->type_name("SPP")
      ->transform(integerIn(MinRenderSpp, MaxRenderSpp));
  command->add_flag("--json", options.json,
                    "Print one JSON document: completed materials, every row, the verdict");
  addPluginOption(*command);
  return command;
}

int runCheckCommand(const CheckCommandOptions& options) {
  if (options.kit.wiThetaDeg.empty())
    throw InputError(
        "--wi-theta: no angle given; allowed: degrees in [0, 90), comma-separated, e.g. 0,30,60,85,89");
  std::vector<InputPath> inputs;
  const std::vector<MaterialUnderTest> materials = prepareMaterials(options, inputs);

  BsdfCheckOptions kit = options.kit;
  kit.chiSquareTestCount = 0;
  for (const MaterialUnderTest& material : materials)
    kit.chiSquareTestCount += material.subsurface
                                  ? subsurfaceChiSquareTestCount(*material.subsurface->profile)
                                  : chiSquareTestCount(kit);
  // Only the path tracer renders BSSRDFs: the render agreement covers the BSDF materials.
  size_t renderedMaterials = 0;
  if (options.renderAgreementSpp)
    for (const MaterialUnderTest& material : materials)
      if (!material.subsurface) ++renderedMaterials;
  if (options.renderAgreementSpp && renderedMaterials == 0)
    throw InputError(
        "--render-agreement: no BSDF material given; allowed: BSDF materials (subsurface "
        "materials are rendered by the path tracer only, so they have no adjoint to compare)");
  kit.chiSquareTestCount += RenderAgreementTestsPerMaterial * int(renderedMaterials);
  // The images are written into a staging directory and moved into --images DIR at the end
  // (staged_outputs.h): an interrupted or failed check leaves DIR as it was.
  StagedOutputs outputs(inputs);
  if (kit.imageDir) {
    outputs.addDirectory("--images", *kit.imageDir, chiSquareImageSuffixes());
    outputs.prepare();
    kit.imageDir = outputs.staged(*options.kit.imageDir);
  }

  announceWork(estimateCheck(materials, kit, options.negativeControls));
  CheckReport report;
  {
    ProgressLine progress;
    for (size_t i = 0; i < materials.size(); ++i) {
      const std::string step = "[" + std::to_string(i + 1) + "/" + std::to_string(materials.size()) + "]";
      report.append(checkMaterial(materials[i], kit, options.negativeControls, progress.callback(step)));
    }
  }
  if (options.renderAgreementSpp) {
    if (renderedMaterials < materials.size())
      std::cerr << "render agreement: " << materials.size() - renderedMaterials
                << " subsurface material(s) left out (only the path tracer renders them)\n";
    const double threshold = sidakSignificance(kit.alpha, kit.chiSquareTestCount);
    RenderAgreementOptions renderOptions;
    renderOptions.pathSpp = *options.renderAgreementSpp;
    ProgressLine progress;
    size_t done = 0;
    for (const MaterialUnderTest& material : materials) {
      if (material.subsurface) continue;
      const std::string step =
          "[render " + std::to_string(++done) + "/" + std::to_string(renderedMaterials) + "]";
      if (const ProgressCallback show = progress.callback(step))
        show("path, light and BDPT renders of " + material.label, 0.0);
      const json& completed = material.completed;
      const RenderAgreement agreement = compareEstimators([&] { return makeBsdf(completed); },
                                                          renderAgreementSeed(material.label), renderOptions);
      report.append(renderAgreementReport(material.label, agreement, threshold));
    }
  }
  if (kit.imageDir) outputs.commit();
  if (options.json)
    printJson(options, kit, materials, report);
  else
    printText(materials, report);
  return static_cast<int>(report.passed() ? ExitCode::Success : ExitCode::CheckFailed);
}

}  // namespace scatterlab
