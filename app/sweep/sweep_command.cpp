#include "app/sweep/sweep_command.h"

#include <iostream>
#include <set>

#include "app/check_command.h"
#include "app/exit_code.h"
#include "app/fit_command.h"
#include "app/lab/staged_directory.h"
#include "app/profile_command.h"
#include "app/render_command.h"
#include "app/sweep/sweep_merge.h"
#include "app/sweep/sweep_runner.h"
#include "app/sweep/sweep_spec.h"
#include "materials/core/atomic_file.h"
#include "materials/registry/material_file.h"
#include "materials/registry/parameter_spec.h"
#include "materials/registry/spec_validation.h"

namespace scatterlab {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// The task's command line parsed by the command's own parser (ranges, choices, unknown
// options), without running it: a bad value is reported before any task runs.
void parseTaskArguments(const SweepSpec& sweep, std::vector<std::string> arguments) {
  CLI::App app{"scatterlab", "scatterlab"};
  app.require_subcommand(1);
  CheckCommandOptions check;
  FitCommandOptions fit;
  RenderCommandOptions render;
  ProfileCommandOptions profile;
  if (sweep.command == "check") addCheckCommand(app, check);
  if (sweep.command == "fit") addFitCommand(app, fit);
  if (sweep.command == "render") {
    addRenderCommand(app, render);
    arguments.insert(arguments.end(), {"--out", (sweep.baseDirectory / "render").string()});
  }
  if (sweep.command == "profile") addProfileCommand(app, profile);
  std::vector<std::string> reversed(arguments.rbegin(), arguments.rend());  // CLI11 parses from the back
  try {
    app.parse(reversed);
  } catch (const CLI::ParseError& error) {
    std::string words;
    for (std::size_t i = 2; i < arguments.size(); ++i) words += " " + arguments[i];
    throw InputError("sweep spec " + sweep.source + ": the options of " + sweep.command + " (" +
                     words.substr(1) + "): " + error.what());
  }
}

// Every material once: registry objects and .json files through the registry's validation;
// other files (MERL .binary, RGL .bsdf) are read by the command itself.
void validateMaterials(const SweepSpec& sweep) {
  std::set<std::string> seen;
  for (const SweepTask& task : sweep.tasks) {
    const std::string name =
        task.material.is_string() ? task.material.get<std::string>() : task.material.dump();
    if (!seen.insert(name).second) continue;
    try {
      if (task.material.is_object()) {
        validateMaterial(task.material);
      } else if (fs::path(name).extension() == ".json") {
        validateMaterial(loadMaterialArgument((sweep.baseDirectory / name).string()));
      }
    } catch (const MaterialError& error) {
      throw InputError("sweep spec " + sweep.source + ": material " + name + ": " + error.what());
    }
  }
}

void validateTasks(const SweepSpec& sweep) {
  validateMaterials(sweep);
  // The options depend only on the varied values: one parse per combination.
  std::set<std::string> seen;
  for (const SweepTask& task : sweep.tasks)
    if (seen.insert(task.vary.dump()).second) parseTaskArguments(sweep, task.arguments);
}

void printTaskList(const SweepSpec& sweep, const SweepShard& shard, bool asJson) {
  if (asJson) {
    json tasks = json::array();
    for (const SweepTask& task : sweep.tasks)
      if (shard.contains(task.index))
        tasks.push_back({{"index", task.index},
                         {"material", task.material},
                         {"vary", task.vary},
                         {"seed", task.seed},
                         {"arguments", task.arguments}});
    std::cout << json{{"hash", sweep.hash},
                      {"command", sweep.command},
                      {"task_count", sweep.tasks.size()},
                      {"shard", std::to_string(shard.number) + "/" + std::to_string(shard.count)},
                      {"tasks", tasks}}
                     .dump(2)
              << "\n";
    return;
  }
  std::cout << "sweep " << sweep.hash << ": " << sweep.command << ", " << sweep.tasks.size() << " tasks";
  if (shard.count > 1) std::cout << " (shard " << shard.number << "/" << shard.count << " listed)";
  std::cout << "\n";
  for (const SweepTask& task : sweep.tasks) {
    if (!shard.contains(task.index)) continue;
    std::cout << task.index << "  seed " << task.seed << "  ";
    for (std::size_t i = 1; i < task.arguments.size(); ++i)
      std::cout << (i > 1 ? " " : "") << task.arguments[i];
    std::cout << "\n";
  }
}

}  // namespace

CLI::App* addSweepCommand(CLI::App& app, SweepCommandOptions& options) {
  CLI::App* command = app.add_subcommand("sweep",
                                         "Run a declarative sweep of check, fit, render or profile (or one "
                                         "shard of it) into a directory, resumably; "
                                         "see docs/sweeps.md");
  command->add_option("spec", options.spec, "Sweep spec (JSON): command, materials, options, vary")
      ->required();
  command->add_option("--out", options.out, "Sweep directory; a rerun skips the tasks it already holds");
  command
      ->add_option("--shard", options.shard,
                   "Run only shard K of N: tasks whose index mod N is K-1; \"from-env\" reads Slurm's "
                   "SLURM_ARRAY_TASK_ID, SLURM_ARRAY_TASK_MIN and SLURM_ARRAY_TASK_COUNT")
      ->capture_default_str();
  command->add_flag("--list", options.list, "Print the (shard's) tasks and their command lines; run nothing");
  command->add_flag("--json", options.json, "Print the task list or the run's summary as JSON");
  return command;
}

int runSweepCommand(const SweepCommandOptions& options) {
  const SweepSpec sweep = loadSweepSpec(options.spec);
  const SweepShard shard = parseSweepShard(options.shard);
  validateTasks(sweep);
  if (options.list) {
    printTaskList(sweep, shard, options.json);
    return static_cast<int>(ExitCode::Success);
  }
  if (options.out.empty())
    throw InputError("--out DIR is required to run a sweep (or --list to see its tasks)");
  prepareSweepDirectory(sweep, options.out);
  const SweepRunSummary summary = runSweepShard(sweep, options.out, shard, std::cerr);
  if (options.json) {
    std::cout << json{{"hash", sweep.hash},
                      {"shard", std::to_string(shard.number) + "/" + std::to_string(shard.count)},
                      {"tasks_in_shard", summary.inShard},
                      {"skipped_complete", summary.skipped},
                      {"succeeded", summary.succeeded},
                      {"failed", summary.failed},
                      {"removed_partials", summary.stalePartials}}
                     .dump(2)
              << "\n";
  } else {
    std::cout << "sweep " << sweep.hash << " shard " << shard.number << "/" << shard.count << ": "
              << summary.succeeded << " run, " << summary.failed << " failed, " << summary.skipped
              << " already complete, of " << summary.inShard << " tasks\n";
  }
  if (summary.failed > 0) {
    std::cerr << "sweep: " << summary.failed
              << " task(s) failed; their errors are in DIR/tasks/*/task.json, and a rerun retries them\n";
    return static_cast<int>(ExitCode::CheckFailed);
  }
  return static_cast<int>(ExitCode::Success);
}

CLI::App* addMergeCommand(CLI::App& app, MergeCommandOptions& options) {
  CLI::App* command = app.add_subcommand(
      "merge", "Gather the results of a sweep's shards into one table (JSON, CSV) and an HTML summary");
  command->add_option("directories", options.directories, "Sweep directories (one per shard, or one shared)")
      ->required();
  command
      ->add_option("--out", options.out,
                   "Output directory: results.json, results.csv, summary.html, timings.json")
      ->required();
  command->add_flag("--json", options.json, "Print the merged results.json on stdout as well");
  return command;
}

int runMergeCommand(const MergeCommandOptions& options) {
  std::vector<fs::path> directories(options.directories.begin(), options.directories.end());
  for (const fs::path& directory : directories) {
    std::error_code error;
    if (fs::exists(options.out, error) && fs::equivalent(options.out, directory, error))
      throw InputError("--out " + options.out +
                       " is one of the sweep directories being merged; choose another");
  }
  const SweepMerge merge = mergeSweepDirectories(directories);
  std::vector<InputPath> inputs;
  for (const fs::path& directory : directories) inputs.push_back({"sweep directory", directory});
  StagedDirectory staged(options.out, "scatterlab merge", "--out", inputs);
  writeTextFileAtomically(staged.path() / "results.json", merge.results.dump(2) + "\n");
  writeTextFileAtomically(staged.path() / "results.csv", merge.csv);
  writeTextFileAtomically(staged.path() / "timings.json", merge.timings.dump(2) + "\n");
  if (!merge.html.empty()) writeTextFileAtomically(staged.path() / "summary.html", merge.html);
  staged.commit();
  if (options.json) std::cout << merge.results.dump(2) << "\n";

  auto list = [](const std::vector<std::size_t>& indices) {
    std::string text;
    for (std::size_t i = 0; i < indices.size() && i < 20; ++i)
      text += (i ? ", " : "") + std::to_string(indices[i]);
    return indices.size() > 20 ? text + ", ..." : text;
  };
  const std::size_t total = merge.results["task_count"];
  std::cerr << "merge: " << (total - merge.missing.size() - merge.failed.size()) << " of " << total
            << " tasks have a result; written to " << options.out << "\n";
  if (!merge.missing.empty())
    std::cerr << "merge: " << merge.missing.size() << " missing (not run yet): " << list(merge.missing)
              << "\n";
  if (!merge.failed.empty())
    std::cerr << "merge: " << merge.failed.size() << " failed: " << list(merge.failed) << "\n";
  return static_cast<int>(merge.missing.empty() && merge.failed.empty() ? ExitCode::Success
                                                                        : ExitCode::CheckFailed);
}

}  // namespace scatterlab
