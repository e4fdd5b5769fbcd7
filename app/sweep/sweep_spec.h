// A sweep: one subcommand (check, fit, render or profile) over a list or product of materials
// and option values, expanded into a deterministic, ordered task list (docs/sweeps.md).
//
// The spec is JSON. Materials are registry JSON objects whose values may be sweep operators
// ({"$values": [...]}, {"$linspace": [lo, hi, n]}, {"$logspace": [lo, hi, n]}), or paths and
// globs of files (relative to the spec's directory). "options" are held for every task,
// "vary" gives each option a list of alternatives; tasks are the product materials x vary,
// the last axis fastest. Each task's seed is derived from the spec's hash and the task's
// index, never from the shard that runs it, so any sharding gives the same results.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace scatterlab {

// The subcommands a sweep can run.
inline constexpr const char* SweepCommands[] = {"check", "fit", "render", "profile"};

// More tasks than this is a spec mistake (a product that exploded), refused up front.
inline constexpr std::size_t MaxSweepTasks = 1'000'000;

struct SweepTask {
  std::size_t index = 0;
  nlohmann::json material;  // a registry object, or the file path as the spec's glob gave it
  nlohmann::json vary;      // this task's value of every varied option (an object)
  uint64_t seed = 0;
  // The command line after `scatterlab`, relative paths as in the spec (the runner starts the
  // command in the spec's directory): command, material, options, --seed, --json.
  std::vector<std::string> arguments;
};

struct SweepSpec {
  std::string source;                   // the spec file, for messages
  std::filesystem::path baseDirectory;  // relative paths in the spec are relative to this
  std::string command;
  nlohmann::json spec;  // as read
  std::string hash;     // 16 hex digits over the spec and its expanded task list
  std::vector<SweepTask> tasks;
};

// Reads and expands a spec file; throws InputError naming the file and the key on bad input
// (unknown command or key, an operator with bad arguments, a glob matching nothing, an empty
// expansion, a reserved option such as "out" or "seed").
SweepSpec loadSweepSpec(const std::filesystem::path& file);

// The same from a parsed document; `source` names it in messages.
SweepSpec expandSweepSpec(const nlohmann::json& spec, const std::filesystem::path& baseDirectory,
                          const std::string& source);

// Every variant of a value whose sub-values may be sweep operators, in a fixed order (object
// keys sorted, arrays by position, the last varying fastest). `where` names the value in
// messages.
std::vector<nlohmann::json> expandSweepValue(const nlohmann::json& value, const std::string& where);

// A shard: every task whose index i has i mod count == number - 1 (round robin, so each
// shard gets a mix of cheap and expensive parts of the grid).
struct SweepShard {
  std::size_t number = 1;  // 1-based
  std::size_t count = 1;
  bool contains(std::size_t taskIndex) const { return taskIndex % count == number - 1; }
};

// "K/N" with 1 <= K <= N, or "from-env": SLURM_ARRAY_TASK_ID minus SLURM_ARRAY_TASK_MIN plus
// one, of SLURM_ARRAY_TASK_COUNT (an array of consecutive ids). Throws InputError otherwise.
SweepShard parseSweepShard(const std::string& text);

}  // namespace scatterlab
