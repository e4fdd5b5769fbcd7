#include "app/sweep/sweep_spec.h"

#include <fnmatch.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <sstream>

#include "app/exit_code.h"
#include "materials/core/bounded_file.h"
#include "materials/core/json_text.h"
#include "materials/core/rng.h"

namespace scatterlab {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

[[noreturn]] void fail(const std::string& source, const std::string& message) {
  throw InputError("sweep spec " + source + ": " + message);
}

// FNV-1a, 64 bits: a stable digest of the canonical spec text (nlohmann::json::dump sorts
// object keys), the same on every machine and build.
uint64_t fnv1a64(const std::string& text) {
  uint64_t hash = 0xcbf29ce484222325ull;
  for (unsigned char c : text) {
    hash ^= c;
    hash *= 0x100000001b3ull;
  }
  return hash;
}

std::string hex16(uint64_t value) {
  std::ostringstream out;
  out << std::hex << std::setw(16) << std::setfill('0') << value;
  return out.str();
}

std::size_t checkedProduct(std::size_t a, std::size_t b, const std::string& where) {
  if (a != 0 && b > MaxSweepTasks / a)
    throw InputError(where + " expands to more than " + std::to_string(MaxSweepTasks) + " variants");
  return a * b;
}

// The values of one operator object ({"$linspace": [lo, hi, n]} and the like).
std::vector<json> operatorValues(const std::string& name, const json& argument, const std::string& where) {
  if (name == "$values") {
    if (!argument.is_array() || argument.empty())
      throw InputError(where + ": \"$values\" takes a non-empty array of alternatives");
    return std::vector<json>(argument.begin(), argument.end());
  }
  if (name == "$linspace" || name == "$logspace") {
    const bool log = name == "$logspace";
    const std::string usage = where + ": \"" + name +
                              "\" takes [first, last, count] with count an integer in [2, " +
                              std::to_string(MaxSweepTasks) + "]" + (log ? " and first, last > 0" : "");
    if (!argument.is_array() || argument.size() != 3 || !argument[0].is_number() ||
        !argument[1].is_number() || !argument[2].is_number_integer())
      throw InputError(usage);
    const double first = argument[0].get<double>(), last = argument[1].get<double>();
    const int64_t count = argument[2].get<int64_t>();
    if (count < 2 || static_cast<std::size_t>(count) > MaxSweepTasks || !std::isfinite(first) ||
        !std::isfinite(last) || (log && (first <= 0 || last <= 0)))
      throw InputError(usage);
    std::vector<json> values;
    for (int64_t i = 0; i < count; ++i) {
      const double t = static_cast<double>(i) / static_cast<double>(count - 1);
      // The end points exactly as written, so a grid's corners are the values the user typed.
      const double value = i == 0           ? first
                           : i == count - 1 ? last
                           : log            ? first * std::pow(last / first, t)
                                            : first + (last - first) * t;
      values.emplace_back(value);
    }
    return values;
  }
  throw InputError(where + ": unknown sweep operator \"" + name +
                   "\"; allowed: \"$values\", \"$linspace\", \"$logspace\"");
}

bool isOperator(const json& value) {
  return value.is_object() && value.size() == 1 && value.begin().key().rfind('$', 0) == 0;
}

// The cartesian product of per-part variants, the last part fastest.
template <typename Assign> std::vector<json> product(const json& start,
                                                     const std::vector<std::vector<json>>& parts,
                                                     const Assign& assign, const std::string& where) {
  std::size_t total = 1;
  for (const auto& part : parts) total = checkedProduct(total, part.size(), where);
  std::vector<json> variants;
  variants.reserve(total);
  std::vector<std::size_t> digit(parts.size(), 0);
  for (std::size_t n = 0; n < total; ++n) {
    json value = start;
    for (std::size_t p = 0; p < parts.size(); ++p) assign(value, p, parts[p][digit[p]]);
    variants.push_back(std::move(value));
    for (std::size_t p = parts.size(); p-- > 0;) {
      if (++digit[p] < parts[p].size()) break;
      digit[p] = 0;
    }
  }
  return variants;
}

bool hasGlobCharacters(const std::string& text) { return text.find_first_of("*?[") != std::string::npos; }

// The files a path or a glob names, relative to `base` and sorted; the pattern may only be in
// the last component ("data/merl/*.binary").
std::vector<std::string> expandPathEntry(const std::string& entry, const fs::path& base,
                                         const std::string& source, const std::string& where) {
  const fs::path relative(entry);
  if (entry.empty()) fail(source, where + ": an empty path");
  if (!hasGlobCharacters(entry)) {
    if (!fs::is_regular_file(base / relative))
      fail(source, where + ": \"" + entry + "\" is not a file (relative to " + base.string() + ")");
    return {entry};
  }
  if (hasGlobCharacters(relative.parent_path().string()))
    fail(source, where + ": \"" + entry + "\": a glob may only match file names, not directories");
  const fs::path directory = base / relative.parent_path();
  std::vector<std::string> matches;
  std::error_code error;
  for (fs::directory_iterator it(directory, error), end; !error && it != end; it.increment(error)) {
    const std::string name = it->path().filename().string();
    if (it->is_regular_file() && fnmatch(relative.filename().c_str(), name.c_str(), FNM_PERIOD) == 0)
      matches.push_back((relative.parent_path() / name).string());
  }
  if (matches.empty())
    fail(source, where + ": \"" + entry + "\" matches no file (relative to " + base.string() + ")");
  std::sort(matches.begin(), matches.end());
  return matches;
}

const std::vector<std::string> ReservedOptions = {"out", "json", "seed", "images", "help", "version"};

// One option as command-line words: true -> "--key", false -> nothing, an array -> the flag
// repeated once per element (CLI11 gathers repeated flags of list options).
void appendOption(std::vector<std::string>& arguments, const std::string& key, const json& value,
                  const std::string& source, const std::string& where) {
  const std::string flag = "--" + key;
  auto scalar = [&](const json& v) -> std::string {
    if (v.is_string()) return v.get<std::string>();
    if (v.is_number()) return v.dump();
    fail(source,
         where + ": a value must be a string, a number or a boolean (or an array of them), not " + v.dump());
  };
  if (value.is_boolean()) {
    if (value.get<bool>()) arguments.push_back(flag);
    return;
  }
  if (value.is_array()) {
    if (value.empty()) fail(source, where + ": an empty list");
    for (const json& element : value) {
      arguments.push_back(flag);
      arguments.push_back(scalar(element));
    }
    return;
  }
  arguments.push_back(flag);
  arguments.push_back(scalar(value));
}

void checkOptionKey(const std::string& key, const std::string& source, const std::string& where) {
  const bool wellFormed = !key.empty() && std::all_of(key.begin(), key.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-';
  });
  if (!wellFormed)
    fail(source, where + ": \"" + key +
                     "\" is not an option name; allowed: the command's long option without "
                     "\"--\" (\"samples\", \"wi-theta\")");
  if (std::find(ReservedOptions.begin(), ReservedOptions.end(), key) != ReservedOptions.end())
    fail(source, where + ": \"" + key +
                     "\" is set by the sweep itself (each task's --seed comes from the spec and its index, "
                     "--json and --out from the sweep's directory); remove it");
}

}  // namespace

std::vector<json> expandSweepValue(const json& value, const std::string& where) {
  if (isOperator(value)) return operatorValues(value.begin().key(), value.begin().value(), where);
  if (value.is_object()) {
    std::vector<std::string> keys;
    std::vector<std::vector<json>> parts;
    for (const auto& [key, sub] : value.items()) {
      keys.push_back(key);
      parts.push_back(expandSweepValue(sub, where + "." + key));
    }
    return product(
        value, parts, [&](json& v, std::size_t p, const json& part) { v[keys[p]] = part; }, where);
  }
  if (value.is_array()) {
    std::vector<std::vector<json>> parts;
    for (std::size_t i = 0; i < value.size(); ++i)
      parts.push_back(expandSweepValue(value[i], where + "[" + std::to_string(i) + "]"));
    return product(
        value, parts, [](json& v, std::size_t p, const json& part) { v[p] = part; }, where);
  }
  return {value};
}

SweepSpec expandSweepSpec(const json& spec, const fs::path& baseDirectory, const std::string& source) {
  if (!spec.is_object()) fail(source, "the spec must be a JSON object with \"command\" and \"materials\"");
  for (const auto& [key, value] : spec.items()) {
    static const std::vector<std::string> known = {"command", "materials", "options",
                                                   "vary",    "seed",      "description"};
    if (std::find(known.begin(), known.end(), key) == known.end())
      fail(source,
           "unknown key \"" + key +
               "\"; allowed: \"command\", \"materials\", \"options\", \"vary\", \"seed\", \"description\"");
  }
  SweepSpec result;
  result.source = source;
  result.baseDirectory = baseDirectory;
  result.spec = spec;

  const json command = spec.value("command", json());
  const auto isCommand = [&](const std::string& name) {
    return std::find(std::begin(SweepCommands), std::end(SweepCommands), name) != std::end(SweepCommands);
  };
  if (!command.is_string() || !isCommand(command.get<std::string>()))
    fail(source, "\"command\": " + (command.is_null() ? std::string("missing") : command.dump()) +
                     "; allowed: \"check\", \"fit\", \"render\", \"profile\"");
  result.command = command.get<std::string>();

  // Materials: each entry an object (expanded over its operators) or a path or glob.
  const json materials = spec.value("materials", json());
  if (!materials.is_array() || materials.empty())
    fail(source, "\"materials\" must be a non-empty array of material objects, files or globs");
  std::vector<json> expandedMaterials;
  for (std::size_t i = 0; i < materials.size(); ++i) {
    const std::string where = "materials[" + std::to_string(i) + "]";
    if (materials[i].is_string()) {
      for (const std::string& file :
           expandPathEntry(materials[i].get<std::string>(), baseDirectory, source, where))
        expandedMaterials.emplace_back(file);
    } else if (materials[i].is_object()) {
      for (json& variant : expandSweepValue(materials[i], source + ": " + where))
        expandedMaterials.push_back(std::move(variant));
    } else {
      fail(source, where + ": a material object, a file path or a glob, not " + materials[i].dump());
    }
  }

  // Options held for every task, and the varied ones.
  const json options = spec.value("options", json::object());
  if (!options.is_object()) fail(source, "\"options\" must be an object of option names and values");
  for (const auto& [key, value] : options.items()) checkOptionKey(key, source, "options");
  const json vary = spec.value("vary", json::object());
  if (!vary.is_object()) fail(source, "\"vary\" must be an object: option name -> list of alternatives");
  std::vector<std::string> varyKeys;
  std::vector<std::vector<json>> varyParts;
  for (const auto& [key, value] : vary.items()) {
    checkOptionKey(key, source, "vary");
    if (options.contains(key))
      fail(source, "\"" + key + "\" is both in \"options\" and in \"vary\"; keep one");
    const std::string where = "vary." + key;
    std::vector<json> alternatives;
    if (isOperator(value)) {
      alternatives = operatorValues(value.begin().key(), value.begin().value(), source + ": " + where);
    } else if (value.is_array() && !value.empty()) {
      alternatives.assign(value.begin(), value.end());
    } else {
      fail(source,
           where + ": a non-empty list of alternatives (or a \"$linspace\" / \"$logspace\" operator)");
    }
    varyKeys.push_back(key);
    varyParts.push_back(std::move(alternatives));
  }
  const std::vector<json> varyCombinations = product(
      json::object(), varyParts, [&](json& v, std::size_t p, const json& part) { v[varyKeys[p]] = part; },
      source);

  const json seed = spec.value("seed", json(1u));
  if (!seed.is_number_unsigned()) fail(source, "\"seed\": a non-negative integer, not " + seed.dump());

  const std::size_t total = checkedProduct(expandedMaterials.size(), varyCombinations.size(), source);
  if (total == 0) fail(source, "the spec expands to no task");

  // The hash covers the spec and the files its globs matched, so two machines that see
  // different files never merge their results as one sweep.
  json identity = {{"spec", spec}, {"materials", expandedMaterials}};
  const uint64_t hash = fnv1a64(identity.dump());
  result.hash = hex16(hash);

  result.tasks.reserve(total);
  for (const json& material : expandedMaterials) {
    for (const json& combination : varyCombinations) {
      SweepTask task;
      task.index = result.tasks.size();
      task.material = material;
      task.vary = combination;
      // 53 bits, so that every JSON reader (JavaScript's included) reads the seed exactly.
      task.seed = deriveSeed(hash, task.index) & ((uint64_t{1} << 53) - 1);
      task.arguments = {result.command, material.is_string() ? material.get<std::string>() : material.dump()};
      for (const auto& [key, value] : options.items())
        appendOption(task.arguments, key, value, source, "options." + key);
      for (const auto& [key, value] : combination.items())
        appendOption(task.arguments, key, value, source, "vary." + key);
      task.arguments.insert(task.arguments.end(), {"--seed", std::to_string(task.seed), "--json"});
      result.tasks.push_back(std::move(task));
    }
  }
  return result;
}

SweepSpec loadSweepSpec(const fs::path& file) {
  // Bounded and depth-limited like every JSON the tool reads (json_text.h, bounded_file.h).
  const std::string source = "sweep spec " + file.string();
  const json spec = parseJsonText(readFileBounded(file, MaxJsonFileBytes, "sweep spec"), source);
  const fs::path base = fs::absolute(file).parent_path();
  return expandSweepSpec(spec, base, file.string());
}

SweepShard parseSweepShard(const std::string& text) {
  const std::string allowed = "; allowed: K/N with 1 <= K <= N (\"2/4\"), or \"from-env\"";
  auto number = [&](const std::string& digits, const std::string& what) -> std::size_t {
    if (digits.empty() || digits.size() > 9 || !std::all_of(digits.begin(), digits.end(), ::isdigit))
      throw InputError("--shard: " + what + " \"" + digits + "\" is not a positive integer" + allowed);
    return std::stoul(digits);
  };
  SweepShard shard;
  if (text == "from-env") {
    auto variable = [&](const char* name) -> std::string {
      const char* value = std::getenv(name);
      if (value == nullptr)
        throw InputError(std::string("--shard from-env: ") + name +
                         " is not set (run inside a Slurm job array, e.g. sbatch --array=1-4)");
      return value;
    };
    const std::size_t id = number(variable("SLURM_ARRAY_TASK_ID"), "SLURM_ARRAY_TASK_ID");
    const std::size_t min = std::getenv("SLURM_ARRAY_TASK_MIN")
                                ? number(variable("SLURM_ARRAY_TASK_MIN"), "SLURM_ARRAY_TASK_MIN")
                                : 1;
    shard.count = number(variable("SLURM_ARRAY_TASK_COUNT"), "SLURM_ARRAY_TASK_COUNT");
    if (id < min) throw InputError("--shard from-env: SLURM_ARRAY_TASK_ID is below SLURM_ARRAY_TASK_MIN");
    shard.number = id - min + 1;
  } else {
    const std::size_t slash = text.find('/');
    if (slash == std::string::npos) throw InputError("--shard: \"" + text + "\" is not K/N" + allowed);
    shard.number = number(text.substr(0, slash), "K");
    shard.count = number(text.substr(slash + 1), "N");
  }
  if (shard.number < 1 || shard.count < 1 || shard.number > shard.count)
    throw InputError("--shard: shard " + std::to_string(shard.number) + " of " + std::to_string(shard.count) +
                     " does not exist" + allowed);
  return shard;
}

}  // namespace scatterlab
