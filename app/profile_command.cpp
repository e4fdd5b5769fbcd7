#include "app/profile_command.h"

#include <cmath>
#include <iostream>

#include <nlohmann/json.hpp>

#include "app/exit_code.h"
#include "app/format_number.h"
#include "app/json_output.h"
#include "app/option_values.h"
#include "app/profile_annuli.h"
#include "app/progress.h"
#include "app/walk_estimate.h"
#include "materials/bssrdf/annulus_profile.h"
#include "materials/bssrdf/chandrasekhar_h.h"
#include "materials/bssrdf/subsurface_registry.h"
#include "materials/registry/material_file.h"
#include "materials/registry/spec_validation.h"
#include "validation/half_space_reference.h"
#include "validation/profile_comparison.h"

namespace scatterlab {

namespace {

using nlohmann::json;

constexpr const char* ChannelNames[3] = {"r", "g", "b"};
constexpr uint64_t MaxPaths = 10'000'000'000;

struct LoadedMaterial {
  std::string label;
  json completed;
  SubsurfaceMaterial material;
};

LoadedMaterial loadSubsurface(const std::string& argument) {
  const json description = loadMaterialArgument(argument);
  try {
    return {isInlineMaterial(argument) ? jsonText(description, -1) : argument, completeMaterial(description),
            makeSubsurface(description)};
  } catch (const MaterialError& error) {
    if (isInlineMaterial(argument)) throw;
    throw MaterialError("material file \"" + argument + "\": " + error.what());
  }
}

// Annuli from 0: [0, min], then log-spaced to max. By default max is where every reflecting
// channel holds 99.9% of its profile, and min a thousandth of it.
std::vector<double> radiusEdges(const ProfileCommandOptions& options, const RadialProfile& profile) {
  const double extent = profileExtent(profile);
  // Without --min-radius and --max-radius the annuli come from the profile: one that reflects
  // nothing has none, which is the material's doing, not an option's.
  if (!options.maxRadius && !(extent > 0.0 && std::isfinite(extent)))
    throw MaterialError("material: the profile reflects nothing to tabulate (total diffuse reflectance " +
                        std::to_string(profile.totalReflectance()[0]) + ", " +
                        std::to_string(profile.totalReflectance()[1]) + ", " +
                        std::to_string(profile.totalReflectance()[2]) +
                        "); allowed: a medium that reflects in some channel, or --max-radius MM");
  const double maxRadius = options.maxRadius.value_or(extent);
  const double minRadius = options.minRadius.value_or(1e-3 * maxRadius);
  if (!(minRadius < maxRadius))
    throw InputError(std::string(options.minRadius ? "--min-radius: " : "--max-radius: ") +
                     std::to_string(minRadius) + " mm is not below the largest radius " +
                     std::to_string(maxRadius) + " mm; allowed: 0 < --min-radius < --max-radius");
  return logRadiusEdges(minRadius, maxRadius, options.bins);
}

struct ChannelWalk {
  HalfSpaceWalkResult result;
  std::optional<double> exactTotal;  // index-matched isotropic: Chandrasekhar's H
};

HalfSpaceWalkSettings walkSettings(const ProfileCommandOptions& options, const ScatteringMedium& medium,
                                   int channel, const std::vector<double>& edges) {
  HalfSpaceWalkSettings s =
      mediumWalkSettings(medium, channel, edges, options.paths, options.seed, options.threads);
  if (!options.albedo.empty()) s.albedo = options.albedo[options.albedo.size() == 3 ? channel : 0];
  s.g = options.g.value_or(s.g);
  s.eta = options.eta.value_or(s.eta);
  return s;
}

void checkWalkOptions(const ProfileCommandOptions& options) {
  if (options.compare) {
    if (options.reference.empty())
      throw InputError("--compare: compares the models with the walk; allowed: only with --reference walk");
    const char* own = !options.albedo.empty() ? "--albedo"
                      : options.eta           ? "--eta"
                      : options.g             ? "--g"
                                              : nullptr;
    if (own)
      throw InputError(
          std::string(own) +
          ": with --compare the walk and every model share the material's medium; allowed: change the "
          "material instead");
    const char* grid = options.minRadius ? "--min-radius" : options.maxRadius ? "--max-radius" : nullptr;
    if (grid)
      throw InputError(std::string(grid) +
                       ": --compare chooses its own annuli (out to twice the widest profile); "
                       "allowed: --bins for their number");
  }
  if (!options.reference.empty()) {
    if (!options.albedo.empty() && options.albedo.size() != 1 && options.albedo.size() != 3)
      throw InputError(
          "--albedo: " + std::to_string(options.albedo.size()) +
          " values given; allowed: one albedo for every channel, or three (r,g,b), each in [0, 1]");
    return;
  }
  const char* walkOnly = !options.albedo.empty() ? "--albedo"
                         : options.eta           ? "--eta"
                         : options.g             ? "--g"
                                                 : nullptr;
  if (walkOnly)
    throw InputError(std::string(walkOnly) +
                     ": sets the random walk's medium; allowed: only with --reference walk");
}

void printText(const LoadedMaterial& loaded, const std::vector<double>& edges,
               const std::vector<std::vector<double>>& means,
               const std::vector<std::optional<ChannelWalk>>& walks) {
  const RadialProfile& profile = *loaded.material.profile;
  std::cout << "material (every default filled in): " << jsonText(loaded.completed, -1) << "\n";
  std::cout << "profile " << profile.name() << ", eta " << loaded.material.medium.eta
            << "; lengths in mm, R in mm^-2\n\n";
  std::cout << "channel  total diffuse reflectance";
  if (walks[0]) std::cout << "   random walk (+- standard error)";
  std::cout << "\n";
  for (int c = 0; c < 3; ++c) {
    std::cout << "  " << ChannelNames[c] << "      "
              << formatNumber(walks[0] ? "%-26.6f" : "%.6f", profile.totalReflectance()[c]);
    if (const auto& walk = walks[size_t(c)]) {
      std::cout << formatNumber("%.6f", walk->result.totalReflectance) << " +- "
                << formatNumber("%.6f", walk->result.totalStdError) << "  (albedo "
                << formatNumber("%.6g", walk->result.settings.albedo) << ", " << walk->result.settings.paths
                << " paths";
      if (walk->exactTotal)
        std::cout << "; exact " << formatNumber("%.6f", *walk->exactTotal) << " by Chandrasekhar's H";
      std::cout << ")";
    }
    std::cout << "\n";
  }
  std::string header = "\nR(r) averaged over annuli\n  r from     r to       ";
  for (int c = 0; c < 3; ++c) {
    header += std::string("R_") + ChannelNames[c] + " profile  ";
    if (walks[0]) header += std::string("R_") + ChannelNames[c] + " walk     +- se        ";
  }
  header.erase(header.find_last_not_of(' ') + 1);
  std::cout << header << "\n";
  for (size_t k = 0; k + 1 < edges.size(); ++k) {
    std::string line = "  " + formatNumber("%-10.4g", edges[k]) + " " + formatNumber("%-10.4g", edges[k + 1]);
    for (int c = 0; c < 3; ++c) {
      line += ' ';
      line += formatNumber("%-12.5e", means[size_t(c)][k]);
      if (const auto& walk = walks[size_t(c)]) {
        line += ' ';
        line += formatNumber("%-12.5e", walk->result.profile[k]);
        line += ' ';
        line += formatNumber("%-12.3e", walk->result.profileStdError[k]);
      }
    }
    line.erase(line.find_last_not_of(' ') + 1);
    std::cout << line << "\n";
  }
}

// Walk paths whose position stopped being finite (half_space_walk.h) are named on stderr and
// fail the command (exit 1) after its output is written.
int nonFiniteWalkStatus(const std::vector<const HalfSpaceWalkResult*>& walks) {
  uint64_t nonFinite = 0, paths = 0;
  for (const HalfSpaceWalkResult* w : walks) {
    nonFinite += w->nonFinite;
    paths += w->settings.paths;
  }
  if (nonFinite == 0) return static_cast<int>(ExitCode::Success);
  std::cerr << "profile: " << nonFinite << " of " << paths
            << " walk paths stopped being finite; they are left out of every tally\n";
  return static_cast<int>(ExitCode::CheckFailed);
}

json walkJson(const ChannelWalk& walk) {
  const HalfSpaceWalkResult& r = walk.result;
  json out{{"albedo", r.settings.albedo},
           {"extinction", r.settings.extinction},
           {"eta", r.settings.eta},
           {"g", r.settings.g},
           {"paths", r.settings.paths},
           {"seed", r.settings.seed},
           {"total_reflectance", r.totalReflectance},
           {"std_error", r.totalStdError},
           {"truncated_paths", r.truncated},
           {"non_finite_paths", r.nonFinite},
           {"mean_scattering_events", double(r.scatteringEvents) / double(r.settings.paths)},
           {"profile", r.profile},
           {"profile_std_error", r.profileStdError}};
  if (walk.exactTotal) out["exact_total_reflectance"] = *walk.exactTotal;
  return out;
}

json rgbJson(const Rgb& v) { return json::array({v.x, v.y, v.z}); }

std::string percent(double v) { return formatNumber("%+.1f%%", 100.0 * v); }

// `text` right-aligned (negative width: left-aligned) in a column of |width| characters.
std::string column(const std::string& text, int width) {
  const size_t w = size_t(std::abs(width));
  if (text.size() >= w) return text;
  return width < 0 ? text + std::string(w - text.size(), ' ') : std::string(w - text.size(), ' ') + text;
}

void printComparison(const LoadedMaterial& loaded, const ProfileComparison& comparison) {
  const ScatteringMedium& m = comparison.medium;
  std::cout << "material (every default filled in): " << jsonText(loaded.completed, -1) << "\n";
  std::cout << "medium: sigma_s " << formatNumber("%.4g", m.sigmaS.x) << " "
            << formatNumber("%.4g", m.sigmaS.y) << " " << formatNumber("%.4g", m.sigmaS.z) << ", sigma_a "
            << formatNumber("%.4g", m.sigmaA.x) << " " << formatNumber("%.4g", m.sigmaA.y) << " "
            << formatNumber("%.4g", m.sigmaA.z) << " mm^-1, g " << m.g << ", eta " << m.eta << "\n";
  std::cout << "walk: " << comparison.walks[0].settings.paths
            << " paths per channel, normal incidence; profile errors on " << comparison.edges.size() - 1
            << " annuli to " << formatNumber("%.4g", comparison.edges.back())
            << " mm plus the power beyond\n\n";
  std::cout
      << "channel  albedo     walk total          single scattering   multiple only       noise floor\n";
  for (int c = 0; c < 3; ++c) {
    const HalfSpaceWalkResult& w = comparison.walks[size_t(c)];
    std::cout << "  " << ChannelNames[c] << "      " << formatNumber("%-10.6g", w.settings.albedo) << " "
              << formatNumber("%.4f", comparison.walkTotal[c]) << " +- "
              << formatNumber("%-8.4f", comparison.walkStdError[c]) << " "
              << formatNumber("%.4f", w.singleReflectance) << " +- "
              << formatNumber("%-8.4f", w.singleStdError) << " "
              << formatNumber("%.4f", comparison.walkMultipleTotal[c]) << " +- "
              << formatNumber("%-8.4f", comparison.walkMultipleStdError[c]) << " "
              << formatNumber("%.3f", comparison.noiseFloor[c]) << "\n";
  }
  std::cout << "\nagainst the walk (relative errors): total diffuse reflectance, and R(r) weighted by r\n"
            << "model           ch  total     all orders: total  R(r)    multiple only: total  R(r)\n";
  for (const ModelComparison& model : comparison.models) {
    const ProfileErrors& e = model.errors;
    for (int c = 0; c < 3; ++c)
      std::cout << column(c == 0 ? toString(model.model) : "", -16) << ChannelNames[c] << "   "
                << formatNumber("%-9.4f", e.total[c]) << " " << column(percent(e.totalError[c]), 18) << "  "
                << formatNumber("%6.1f%%", 100.0 * e.profileError[c]) << " "
                << column(percent(e.multipleTotalError[c]), 21) << "  "
                << formatNumber("%6.1f%%", 100.0 * e.multipleProfileError[c]) << "\n";
  }
}

json comparisonJson(const LoadedMaterial& loaded, const ProfileComparison& comparison) {
  const ScatteringMedium& m = comparison.medium;
  json walks = json::array();
  for (const HalfSpaceWalkResult& w : comparison.walks)
    walks.push_back({{"albedo", w.settings.albedo},
                     {"extinction", w.settings.extinction},
                     {"paths", w.settings.paths},
                     {"seed", w.settings.seed},
                     {"total_reflectance", w.totalReflectance},
                     {"std_error", w.totalStdError},
                     {"single_scattering", w.singleReflectance},
                     {"single_scattering_std_error", w.singleStdError},
                     {"non_finite_paths", w.nonFinite}});
  json models = json::array();
  for (const ModelComparison& model : comparison.models)
    models.push_back({{"model", toString(model.model)},
                      {"total_reflectance", rgbJson(model.errors.total)},
                      {"total_error", rgbJson(model.errors.totalError)},
                      {"profile_error", rgbJson(model.errors.profileError)},
                      {"multiple_total_error", rgbJson(model.errors.multipleTotalError)},
                      {"multiple_profile_error", rgbJson(model.errors.multipleProfileError)}});
  return {{"material", loaded.completed},
          {"label", loaded.label},
          {"medium",
           {{"sigma_s", rgbJson(m.sigmaS)}, {"sigma_a", rgbJson(m.sigmaA)}, {"g", m.g}, {"eta", m.eta}}},
          {"errors",
           "relative to the walk: total (model / walk - 1) and R(r) weighted by r (L1 distance of the radial "
           "power "
           "distributions over the walk's total), against all orders and against multiple scattering only"},
          {"radius_edges", comparison.edges},
          {"walk",
           {{"channels", std::move(walks)},
            {"total", rgbJson(comparison.walkTotal)},
            {"std_error", rgbJson(comparison.walkStdError)},
            {"multiple_total", rgbJson(comparison.walkMultipleTotal)},
            {"multiple_std_error", rgbJson(comparison.walkMultipleStdError)},
            {"profile_error_noise_floor", rgbJson(comparison.noiseFloor)}}},
          {"models", std::move(models)}};
}

ProfileComparison compareWithWalk(const ProfileCommandOptions& options, const LoadedMaterial& loaded,
                                  bool showProgress) {
  ProfileComparisonOptions compare;
  compare.paths = options.paths;
  compare.seed = options.seed;
  compare.threads = options.threads;
  compare.annuli = options.bins;
  compare.burleyFit = loaded.material.burleyFit;
  std::vector<HalfSpaceWalkSettings> channels;  // the walks' cost does not depend on the annuli
  for (int c = 0; c < 3; ++c)
    channels.push_back(mediumWalkSettings(loaded.material.medium, c, {0.0, 1.0}, options.paths, options.seed,
                                          options.threads));
  announceWork(
      estimateWalks("profile --compare: 3 walks of " + std::to_string(options.paths) + " paths", channels));
  ProgressLine progress;
  ProfileComparison comparison = compareProfilesWithWalk(
      loaded.material.medium, compare, showProgress ? progress.walkCallback("walk") : WalkProgress());
  progress.clear();
  return comparison;
}

int runComparison(const ProfileCommandOptions& options, const LoadedMaterial& loaded) {
  const ProfileComparison comparison = compareWithWalk(options, loaded, true);
  if (options.json)
    std::cout << jsonText(comparisonJson(loaded, comparison)) << "\n";
  else
    printComparison(loaded, comparison);
  std::vector<const HalfSpaceWalkResult*> walks;
  for (const HalfSpaceWalkResult& w : comparison.walks) walks.push_back(&w);
  return nonFiniteWalkStatus(walks);
}

// The profile's annuli and, with --reference walk, the walk per channel.
struct ProfileRun {
  std::vector<double> edges;
  std::vector<std::vector<double>> means;
  std::vector<std::optional<ChannelWalk>> walks = std::vector<std::optional<ChannelWalk>>(3);
};

ProfileRun tabulateProfile(const ProfileCommandOptions& options, const LoadedMaterial& loaded,
                           bool showProgress) {
  ProfileRun run;
  const RadialProfile& profile = *loaded.material.profile;
  run.edges = radiusEdges(options, profile);
  for (int c = 0; c < 3; ++c) run.means.push_back(annulusMeans(profile, c, run.edges));
  if (options.reference == "walk") {
    std::vector<HalfSpaceWalkSettings> channels;
    for (int c = 0; c < 3; ++c)
      channels.push_back(walkSettings(options, loaded.material.medium, c, run.edges));
    announceWork(estimateWalks("profile: 3 walks of " + std::to_string(options.paths) + " paths", channels));
    ProgressLine progress;
    for (int c = 0; c < 3; ++c) {
      const HalfSpaceWalkSettings& settings = channels[size_t(c)];
      ChannelWalk walk{simulateHalfSpace(settings, showProgress ? progress.walkCallback(std::string("walk ") +
                                                                                        ChannelNames[c])
                                                                : WalkProgress()),
                       std::nullopt};
      if (settings.eta == 1.0 && settings.g == 0.0 && settings.incidentCosTheta == 1.0)
        walk.exactTotal = ChandrasekharH(settings.albedo).directionalAlbedo(1.0);
      run.walks[size_t(c)] = std::move(walk);
    }
  }
  return run;
}

json profileJson(const LoadedMaterial& loaded, const ProfileRun& run) {
  const RadialProfile& profile = *loaded.material.profile;
  json channels = json::array();
  for (int c = 0; c < 3; ++c) {
    json channel{{"channel", ChannelNames[c]},
                 {"total_reflectance", profile.totalReflectance()[c]},
                 {"profile", run.means[size_t(c)]}};
    if (run.walks[size_t(c)]) channel["walk"] = walkJson(*run.walks[size_t(c)]);
    channels.push_back(std::move(channel));
  }
  const ScatteringMedium& m = loaded.material.medium;
  return {{"material", loaded.completed},
          {"label", loaded.label},
          {"profile_model", profile.name()},
          {"medium",
           {{"sigma_s", {m.sigmaS.x, m.sigmaS.y, m.sigmaS.z}},
            {"sigma_a", {m.sigmaA.x, m.sigmaA.y, m.sigmaA.z}},
            {"g", m.g},
            {"eta", m.eta}}},
          {"units", "lengths mm, coefficients mm^-1, R mm^-2 (averaged over each annulus)"},
          {"radius_edges", run.edges},
          {"channels", std::move(channels)}};
}

}  // namespace

CLI::App* addProfileCommand(CLI::App& app, ProfileCommandOptions& options) {
  CLI::App* command = app.add_subcommand(
      "profile",
      "Print a subsurface material's radial profile R(r) and total diffuse reflectance per channel, "
      "optionally next to the half-space random walk (--reference walk)");
  command->add_option("material", options.material, "Subsurface material: inline JSON or a JSON file")
      ->required();
  command
      ->add_option("--reference", options.reference, "Also run the ground truth: the half-space random walk")
      ->check(CLI::IsMember({"walk"}))
      ->type_name("walk");
  command
      ->add_option(
          "--albedo", options.albedo,
          "Walk: single-scattering albedo sigma_s / sigma_t, one value or r,g,b (default: the medium's)")
      ->delimiter(',')
      ->type_name("ALBEDO")
      ->check(numberIn(ValueRange::closed(0.0, 1.0), "an albedo"));
  command
      ->add_option("--eta", options.eta,
                   "Walk: boundary index of refraction, 1 = index-matched (default: the material's)")
      ->type_name("NUMBER")
      ->check(numberIn(ValueRange{0.0, 4.0, true, false}, "an index of refraction"));
  command->add_option("--g", options.g, "Walk: Henyey-Greenstein mean cosine (default: the material's)")
      ->type_name("NUMBER")
      ->check(numberIn(ValueRange{-1.0, 1.0, true, true}, "a mean cosine"));
  command->add_option("--paths", options.paths, "Walk: paths per channel")
      ->type_name("INTEGER")
      ->transform(integerIn(1000, MaxPaths))
      ->capture_default_str();
  command
      ->add_option("--min-radius", options.minRadius,
                   "Outer radius of the first annulus, mm (default: max / 1000)")
      ->type_name("MM")
      ->check(numberIn(ValueRange::above(0.0), "a radius in mm"));
  command
      ->add_option(
          "--max-radius", options.maxRadius,
          "Outer radius of the last annulus, mm (default: where every channel holds 99.9% of its profile)")
      ->type_name("MM")
      ->check(numberIn(ValueRange::above(0.0), "a radius in mm"));
  command->add_option("--bins", options.bins, "Annuli after the first (log-spaced)")
      ->type_name("INTEGER")
      ->check(CLI::Range(2, 1000))
      ->capture_default_str();
  addSeedAndThreadOptions(command, options.seed, options.threads, "walk");
  command->add_flag(
      "--compare", options.compare,
      "With --reference walk: every profile model (dipole, better-dipole, beam-diffusion, burley) on the "
      "material's medium against the walk, in one table of relative errors");
  command->add_flag("--json", options.json, "Print one JSON document");
  return command;
}

json profileReport(const ProfileCommandOptions& options, bool progress) {
  checkWalkOptions(options);
  const LoadedMaterial loaded = loadSubsurface(options.material);
  if (options.compare) return comparisonJson(loaded, compareWithWalk(options, loaded, progress));
  return profileJson(loaded, tabulateProfile(options, loaded, progress));
}

int runProfileCommand(const ProfileCommandOptions& options) {
  checkWalkOptions(options);
  const LoadedMaterial loaded = loadSubsurface(options.material);
  if (options.compare) return runComparison(options, loaded);
  const ProfileRun run = tabulateProfile(options, loaded, true);
  std::vector<const HalfSpaceWalkResult*> walkResults;
  for (const std::optional<ChannelWalk>& walk : run.walks)
    if (walk) walkResults.push_back(&walk->result);
  if (options.json)
    std::cout << jsonText(profileJson(loaded, run)) << "\n";
  else
    printText(loaded, run.edges, run.means, run.walks);
  return nonFiniteWalkStatus(walkResults);
}

}  // namespace scatterlab
