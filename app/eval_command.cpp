#include "app/eval_command.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/exit_code.h"
#include "app/material_argument.h"
#include "materials/bsdf/direction_pairs.h"
#include "materials/bsdf/sample_queries.h"
#include "materials/bssrdf/subsurface_registry.h"
#include "materials/registry/material_file.h"
#include "materials/registry/parameter_spec.h"
#include "materials/registry/spec_validation.h"

namespace scatterlab {

namespace {

using nlohmann::json;

// theta from the normal (beyond 90: below the surface, for transmission), phi about it.
const ValueRange ThetaRange = ValueRange::closed(0.0, 180.0);
const ValueRange PhiRange = ValueRange::closed(-360.0, 360.0);
const std::string AngleAllowed =
    "THETA,PHI in degrees, THETA " + ThetaRange.describe() + ", PHI " + PhiRange.describe() + ", e.g. 30,0";

std::optional<double> parseNumber(const std::string& text) {
  double value = 0;
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, value);
  if (error != std::errc() || stop != end || !std::isfinite(value)) return std::nullopt;
  return value;
}

// "THETA,PHI" as a unit direction, or nothing.
std::optional<Vec3d> parseAngles(const std::string& text) {
  const auto comma = text.find(',');
  if (comma == std::string::npos) return std::nullopt;
  const auto theta = parseNumber(text.substr(0, comma));
  const auto phi = parseNumber(text.substr(comma + 1));
  if (!theta || !phi || !ThetaRange.contains(*theta) || !PhiRange.contains(*phi)) return std::nullopt;
  return directionFromDegrees(*theta, *phi);
}

CLI::Validator angleValidator() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        return parseAngles(text) ? "" : "\"" + text + "\" is not a direction; allowed: " + AngleAllowed;
      },
      "");
}

// The JSON document of an option's file; InputError naming the option, the file and `allowed`.
json readJsonFile(const std::string& option, const std::string& path, const std::string& allowed) {
  const std::string source = option + " file \"" + path + "\": ";
  std::error_code error;
  const auto status = std::filesystem::status(path, error);
  if (!std::filesystem::exists(status)) throw InputError(source + "not found" + allowed);
  if (std::filesystem::is_directory(status)) throw InputError(source + "is a directory" + allowed);
  std::ifstream file(path, std::ios::binary);
  std::ostringstream text;
  if (file) text << file.rdbuf();
  if (!file.is_open() || file.bad()) throw InputError(source + "not readable" + allowed);
  try {
    return json::parse(text.str());
  } catch (const json::exception& parseError) {  // a syntax error, or a number beyond a double's range
    std::string detail = parseError.what();
    if (const auto bracket = detail.find("] ");
        detail.rfind("[json.exception", 0) == 0 && bracket != std::string::npos)
      detail = detail.substr(bracket + 2);
    throw InputError(source + "not valid JSON (" + detail + ")" + allowed);
  }
}

std::vector<DirectionPair> readDirectionsFile(const std::string& path) {
  const std::string allowed =
      "; allowed: a readable JSON file holding [{\"wi\": [x, y, z], \"wo\": [x, y, z]}, ...]";
  const json parsed = readJsonFile("--directions", path, allowed);
  try {
    return directionPairsFromJson(parsed);
  } catch (const DirectionError& directionError) {
    throw InputError("--directions file \"" + path + "\": " + directionError.what());
  }
}

std::vector<SampleQuery> readSamplesFile(const std::string& path) {
  const std::string allowed =
      "; allowed: a readable JSON file holding [{\"wi\": [x, y, z], \"u_lobe\": a, \"u\": [b, c]}, ...]";
  const json parsed = readJsonFile("--samples", path, allowed);
  try {
    return sampleQueriesFromJson(parsed);
  } catch (const DirectionError& queryError) {
    throw InputError("--samples file \"" + path + "\": " + queryError.what());
  }
}

const char* const DirectionSourcesAllowed =
    "; allowed: --directions FILE, --samples FILE, or --wi THETA,PHI with --wo THETA,PHI";

// One source of queries, checked before any file is read.
void checkOneDirectionSource(const EvalCommandOptions& options) {
  const bool angles = !options.wi.empty() || !options.wo.empty();
  if (!options.samplesFile.empty() && (angles || !options.directionsFile.empty()))
    throw InputError("eval: --samples and " + std::string(angles ? "--wi/--wo" : "--directions") +
                     " both given; allowed: --samples FILE alone, --directions FILE, or --wi THETA,PHI with "
                     "--wo THETA,PHI");
  if (!options.directionsFile.empty() && angles)
    throw InputError(std::string("eval: --directions and --wi/--wo both given") + DirectionSourcesAllowed);
}

std::vector<DirectionPair> pairsOf(const EvalCommandOptions& options) {
  const std::string allowed = DirectionSourcesAllowed;
  const bool angles = !options.wi.empty() || !options.wo.empty();
  if (!options.directionsFile.empty()) return readDirectionsFile(options.directionsFile);
  if (options.wi.empty() || options.wo.empty())
    throw InputError(
        std::string("eval: ") +
        (angles ? (options.wi.empty() ? "--wi" : "--wo") + std::string(" missing") : "no directions given") +
        allowed);
  return {DirectionPair{*parseAngles(options.wi), *parseAngles(options.wo)}};
}

std::string formatVector(const Vec3d& v) {
  char text[96];
  std::snprintf(text, sizeof text, "%.9g %.9g %.9g", v.x, v.y, v.z);
  return text;
}

void printTable(const json& material, std::span<const DirectionPair> pairs,
                std::span<const PairValue> values) {
  std::cout << "material: " << material.dump() << "\n";
  std::cout << "# wi_x wi_y wi_z  wo_x wo_y wo_z  f_r f_g f_b (1/sr, no cosine)  pdf (1/sr)\n";
  for (size_t i = 0; i < pairs.size(); ++i) {
    char pdf[32];
    std::snprintf(pdf, sizeof pdf, "%.9g", values[i].pdf);
    std::cout << formatVector(pairs[i].wi) << "  " << formatVector(pairs[i].wo) << "  "
              << formatVector(values[i].f) << "  " << pdf << "\n";
  }
}

void printSamples(const json& material, const json& samples) {
  std::cout << "material: " << material.dump() << "\n";
  std::cout << "# wi_x wi_y wi_z  u_lobe u_0 u_1  wo_x wo_y wo_z  weight_r weight_g weight_b  pdf  delta "
               "(an invalid sample: \"failed\")\n";
  const auto v = [](const json& a) {
    return formatVector(Vec3d(a[0].get<double>(), a[1].get<double>(), a[2].get<double>()));
  };
  for (const json& s : samples) {
    char numbers[96];
    std::snprintf(numbers, sizeof numbers, "%.9g %.9g %.9g", s["u_lobe"].get<double>(),
                  s["u"][0].get<double>(), s["u"][1].get<double>());
    std::cout << v(s["wi"]) << "  " << numbers << "  ";
    if (!s["valid"].get<bool>()) {
      std::cout << "failed\n";
      continue;
    }
    char pdf[32];
    std::snprintf(pdf, sizeof pdf, "%.9g", s["pdf"].get<double>());
    std::cout << v(s["wo"]) << "  " << v(s["weight"]) << "  " << pdf << "  "
              << (s["delta"].get<bool>() ? "1" : "0") << "\n";
  }
}

}  // namespace

CLI::App* addEvalCommand(CLI::App& app, EvalCommandOptions& options) {
  CLI::App* command = app.add_subcommand(
      "eval",
      "Evaluate a material at given direction pairs: f (RGB, 1/sr, without the cosine) and the pdf of its "
      "sampler (1/sr), in the local frame (z = normal, wi and wo pointing away from the surface, radiance "
      "transport). Delta lobes (smooth surfaces) have no density: 0 at every pair. A subsurface material "
      "gives its far-field BRDF, the BSSRDF integrated over the entry point");
  command
      ->add_option("material", options.material,
                   "Material: inline JSON, a JSON file, or a measured table file (MERL .binary)")
      ->required();
  command
      ->add_option("--directions", options.directionsFile,
                   "JSON file: an array of {\"wi\": [x, y, z], \"wo\": [x, y, z]}, unit vectors (to 1e-5)")
      ->type_name("FILE");
  command
      ->add_option(
          "--samples", options.samplesFile,
          "JSON file: an array of {\"wi\": [x, y, z], \"u_lobe\": a, \"u\": [b, c]}, a, b, c in [0, 1): "
          "print what the sampler returns for them (wo, weight = f |cos wo| / pdf, pdf, valid, delta)")
      ->type_name("FILE");
  command->add_option("--wi", options.wi, "Incident direction: theta,phi in degrees (theta from the normal)")
      ->type_name("THETA,PHI")
      ->check(angleValidator());
  command
      ->add_option("--wo", options.wo,
                   "Outgoing direction: theta,phi in degrees (theta > 90: below the surface, transmission)")
      ->type_name("THETA,PHI")
      ->check(angleValidator());
  command->add_flag(
      "--json", options.json,
      "Print {\"material\", \"values\": [{\"wi\", \"wo\", \"f\", \"pdf\"}, ...]} in full precision");
  return command;
}

int runEvalCommand(const EvalCommandOptions& options) {
  checkOneDirectionSource(options);
  const std::vector<SampleQuery> queries =
      options.samplesFile.empty() ? std::vector<SampleQuery>{} : readSamplesFile(options.samplesFile);
  const std::vector<DirectionPair> pairs = queries.empty() ? pairsOf(options) : std::vector<DirectionPair>{};
  const json material = materialFromArgument(options.material);
  json completed;
  std::unique_ptr<BsdfModel> model;
  try {
    completed = completeMaterial(material);
    model = makeFarFieldBsdf(material);
  } catch (const MaterialError& error) {
    if (isInlineMaterial(options.material)) throw;
    throw MaterialError("material \"" + options.material + "\": " + error.what());
  }
  if (!queries.empty()) {
    const json samples = sampleQueryValuesJson(*model, queries);
    if (options.json)
      std::cout << json{{"material", completed}, {"samples", samples}}.dump(2) << "\n";
    else
      printSamples(completed, samples);
    return static_cast<int>(ExitCode::Success);
  }
  const std::vector<PairValue> values = evaluatePairs(*model, pairs);
  if (options.json)
    std::cout << json{{"material", completed}, {"values", pairValuesJson(pairs, values)}}.dump(2) << "\n";
  else
    printTable(completed, pairs, values);
  return static_cast<int>(ExitCode::Success);
}

}  // namespace scatterlab
