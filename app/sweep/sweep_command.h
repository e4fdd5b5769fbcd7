// `scatterlab sweep SPEC --out DIR [--shard K/N|from-env] [--list]` runs a declarative sweep
// of check, fit, render or profile (or one shard of it), resumably; `scatterlab merge DIR...
// --out OUT` gathers the results of every shard into one table. docs/sweeps.md has the spec
// format, the directory layout and the cluster path (scripts/slurm/).
//
// Exit codes: sweep: 0 every task of the shard has a result, 1 some task failed (recorded,
// the others ran), 2 bad input (nothing run or written). merge: 0 every task has a result,
// 1 some are missing or failed (the merge is written and says which), 2 bad input.
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace scatterlab {

struct SweepCommandOptions {
  std::string spec;
  std::string out;
  std::string shard = "1/1";
  bool list = false;
  bool json = false;
};

CLI::App* addSweepCommand(CLI::App& app, SweepCommandOptions& options);
int runSweepCommand(const SweepCommandOptions& options);

struct MergeCommandOptions {
  std::vector<std::string> directories;
  std::string out;
  bool json = false;
};

CLI::App* addMergeCommand(CLI::App& app, MergeCommandOptions& options);
int runMergeCommand(const MergeCommandOptions& options);

}  // namespace scatterlab
