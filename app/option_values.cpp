#include "app/option_values.h"

#include <algorithm>

#include <charconv>
#include <cmath>
#include <filesystem>
#include <optional>

#include "app/exit_code.h"
#include "materials/core/quoted.h"

namespace scatterlab {

namespace {

// The whole of `text` as a number of type T, or nothing (no partial parses: "12abc" is not 12).
template <typename T> std::optional<T> parseWhole(const std::string& text) {
  T value{};
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, value);
  if (error != std::errc() || stop != end) return std::nullopt;
  return value;
}

// Integers written in floating-point notation ("1e6") are exact up to 2^53.
std::optional<uint64_t> parseInteger(const std::string& text) {
  if (const auto exact = parseWhole<uint64_t>(text)) return exact;
  const auto real = parseWhole<double>(text);
  constexpr double MaxExact = 9007199254740992.0;  // 2^53
  if (!real || !(*real >= 0 && *real <= MaxExact) || std::floor(*real) != *real) return std::nullopt;
  return static_cast<uint64_t>(*real);
}

}  // namespace

CLI::Validator numberIn(const ValueRange& range, const std::string& what) {
  const std::string allowed = what + " " + range.describe();
  return CLI::Validator(
      [range, allowed](std::string& text) -> std::string {
        const auto value = parseWhole<double>(text);
        if (!value || !std::isfinite(*value))
          return inQuotes(text) + " is not a finite number; allowed: " + allowed;
        if (!range.contains(*value)) return inQuotes(text) + " is out of range; allowed: " + allowed;
        return "";
      },
      range.describe());
}

void addSeedAndThreadOptions(CLI::App* command, uint64_t& seed, int& threads, const std::string& work) {
  command->add_option("--seed", seed, "Seed of the " + work + "; the same seed gives the same numbers")
      ->type_name("INTEGER")
      ->transform(integerIn(0))
      ->capture_default_str();
  command
      ->add_option("--threads", threads, "Worker threads of the " + work + ", 0 for all cores (same result)")
      ->type_name("INTEGER")
      ->check(CLI::Range(0, 1024))
      ->capture_default_str();
}

CLI::Validator integerIn(uint64_t lo, uint64_t hi) {
  const std::string range = hi == std::numeric_limits<uint64_t>::max()
                                ? ">= " + std::to_string(lo)
                                : "in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
  const std::string allowed = "an integer " + range;
  return CLI::Validator(
      [lo, hi, allowed](std::string& text) -> std::string {
        const auto value = parseInteger(text);
        if (!value) return inQuotes(text) + " is not an integer; allowed: " + allowed;
        if (*value < lo || *value > hi) return inQuotes(text) + " is out of range; allowed: " + allowed;
        text = std::to_string(*value);
        return "";
      },
      range);
}

std::optional<GridSize> parseGrid(const std::string& text) {
  const auto separator = text.find('x');
  if (separator == std::string::npos) return std::nullopt;
  const auto cosTheta = parseWhole<int>(text.substr(0, separator));
  const auto phi = parseWhole<int>(text.substr(separator + 1));
  const auto inRange = [](const std::optional<int>& cells) {
    return cells && *cells >= MinGridCells && *cells <= MaxGridCells;
  };
  if (!inRange(cosTheta) || !inRange(phi)) return std::nullopt;
  return GridSize{*cosTheta, *phi};
}

CLI::Validator gridValidator() {
  const std::string allowed = "COSxPHI, cos(theta) cells x phi cells, each an integer in [" +
                              std::to_string(MinGridCells) + ", " + std::to_string(MaxGridCells) +
                              "], e.g. 64x128";
  return CLI::Validator(
      [allowed](std::string& text) -> std::string {
        return parseGrid(text) ? "" : inQuotes(text) + " is not a valid grid; allowed: " + allowed;
      },
      "each in [" + std::to_string(MinGridCells) + ", " + std::to_string(MaxGridCells) + "]");
}

CLI::Validator outputDirectoryValidator() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        const std::string allowed = "; allowed: a directory, or a path where one can be created";
        if (text.empty()) return "an empty path" + allowed;
        std::error_code error;
        const auto status = std::filesystem::status(text, error);
        if (std::filesystem::exists(status) && !std::filesystem::is_directory(status))
          return inQuotes(text) + " exists and is not a directory" + allowed;
        return "";
      },
      "");
}

CLI::Validator choiceOf(const std::vector<std::string>& names, const std::string& what) {
  std::string allowed = "one of ";
  for (size_t i = 0; i < names.size(); ++i) allowed += (i ? ", " : "") + inQuotes(names[i]);
  return CLI::Validator(
      [names, what, allowed](std::string& text) -> std::string {
        if (std::find(names.begin(), names.end(), text) != names.end()) return "";
        return inQuotes(text) + " is not " + what + "; allowed: " + allowed;
      },
      "");
}

void checkOutputFile(const std::string& option, const std::string& path, const std::string& example) {
  const std::string allowed = "; allowed: a file path in an existing directory, e.g. " + example;
  if (path.empty()) throw InputError(option + ": missing" + allowed);
  std::error_code error;
  if (std::filesystem::is_directory(path, error))
    throw InputError(option + ": " + inQuotes(path) + " is a directory" + allowed);
  const std::filesystem::path directory = std::filesystem::path(path).parent_path();
  if (!directory.empty() && !std::filesystem::is_directory(directory, error))
    throw InputError(option + ": directory " + inQuotes(directory.string()) + " does not exist" + allowed);
}

}  // namespace scatterlab
