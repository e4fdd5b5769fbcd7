#include "app/sweep/sweep_runner.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "app/exit_code.h"
#include "materials/core/atomic_file.h"
#include "materials/core/temporary_files.h"

extern char** environ;

namespace scatterlab {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

constexpr const char* SweepManifestName = "sweep.json";
constexpr const char* Generator = "scatterlab sweep";

std::string hostName() {
  char name[256] = {};
  if (gethostname(name, sizeof name - 1) != 0) return "host";
  return name;
}

std::string readText(const fs::path& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

fs::path selfExecutable() {
  std::error_code error;
  const fs::path path = fs::read_symlink("/proc/self/exe", error);
  if (error)
    throw std::runtime_error("cannot find the scatterlab executable (/proc/self/exe): " + error.message());
  return path;
}

// The last lines of a child's stderr: enough to say why it failed, short enough for a table.
std::string lastLines(const std::string& text, int lines) {
  std::size_t end = text.size();
  while (end > 0 && (text[end - 1] == '\n' || text[end - 1] == ' ')) --end;
  std::size_t start = end;
  for (int seen = 0; start > 0; --start)
    if (text[start - 1] == '\n' && ++seen == lines) break;
  return text.substr(start, end - start);
}

struct ChildRun {
  int exitCode = -1;        // the exit status, or 128 + signal
  double wallSeconds = 0;   // from start to exit
  long maxResidentKiB = 0;  // the child's peak resident memory
};

// Runs this executable with `arguments` in `workingDirectory`, stdout and stderr into files.
ChildRun runChild(const std::vector<std::string>& arguments, const fs::path& workingDirectory,
                  const fs::path& stdoutFile, const fs::path& stderrFile) {
  static const fs::path executable = selfExecutable();
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, stdoutFile.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                   0644);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, stderrFile.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                   0644);
  posix_spawn_file_actions_addchdir_np(&actions, workingDirectory.c_str());
  std::vector<std::string> words{executable.string()};
  words.insert(words.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for (std::string& word : words) argv.push_back(word.data());
  argv.push_back(nullptr);

  const auto start = std::chrono::steady_clock::now();
  pid_t pid = 0;
  const int spawnError = posix_spawn(&pid, executable.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawnError != 0)
    throw std::runtime_error("cannot start " + executable.string() + ": " + std::strerror(spawnError));
  int status = 0;
  rusage usage{};
  while (wait4(pid, &status, 0, &usage) < 0 && errno == EINTR) {}
  ChildRun run;
  run.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  run.maxResidentKiB = usage.ru_maxrss;
  return run;
}

bool isTimingKey(const std::string& key) {
  auto endsWith = [&](const std::string& suffix) {
    return key.size() >= suffix.size() && key.compare(key.size() - suffix.size(), suffix.size(), suffix) == 0;
  };
  return key == "seconds" || endsWith("_seconds") || endsWith("_per_second");
}

void extractTimingsAt(json& value, const std::string& pointer, json& timings) {
  if (value.is_object()) {
    for (auto it = value.begin(); it != value.end();) {
      if (isTimingKey(it.key()) && it.value().is_number()) {
        timings[pointer + "/" + it.key()] = it.value();
        it = value.erase(it);
      } else {
        extractTimingsAt(it.value(), pointer + "/" + it.key(), timings);
        ++it;
      }
    }
  } else if (value.is_array()) {
    for (std::size_t i = 0; i < value.size(); ++i)
      extractTimingsAt(value[i], pointer + "/" + std::to_string(i), timings);
  }
}

bool isCompleteTask(const fs::path& taskDirectory) {
  std::error_code error;
  if (!fs::is_regular_file(taskDirectory / "task.json", error)) return false;
  try {
    return json::parse(readText(taskDirectory / "task.json")).value("status", "") == "ok";
  } catch (const json::exception&) {
    return false;
  }
}

// Runs one task into `staging` and writes its task.json and timing.json there.
bool runTask(const SweepSpec& sweep, const SweepTask& task, const fs::path& staging) {
  std::vector<std::string> arguments = task.arguments;
  if (sweep.command == "render") arguments.insert(arguments.end(), {"--out", (staging / "render").string()});
  const ChildRun run =
      runChild(arguments, sweep.baseDirectory, staging / "stdout.json", staging / "stderr.txt");

  json record = {{"index", task.index}, {"material", task.material},   {"vary", task.vary},
                 {"seed", task.seed},   {"arguments", task.arguments}, {"exit_code", run.exitCode}};
  json timing = {
      {"index", task.index}, {"wall_seconds", run.wallSeconds}, {"max_resident_kib", run.maxResidentKiB}};
  // Exit 0 and 1 are results (a check that fails, a fit that is poor); 2 and 3 are errors.
  const bool finished = run.exitCode == static_cast<int>(ExitCode::Success) ||
                        run.exitCode == static_cast<int>(ExitCode::CheckFailed);
  json report;
  std::string error;
  if (finished) {
    try {
      report = json::parse(readText(staging / "stdout.json"));
    } catch (const json::exception& parseError) {
      error = std::string("the command's report is not JSON: ") + parseError.what();
    }
  } else {
    error = run.exitCode > 128 ? "killed by signal " + std::to_string(run.exitCode - 128)
                               : "exit " + std::to_string(run.exitCode);
    const std::string messages = lastLines(readText(staging / "stderr.txt"), 5);
    if (!messages.empty()) error += ": " + messages;
  }
  fs::remove(staging / "stdout.json");
  if (error.empty()) {
    timing["reported"] = extractTimings(report);
    if (sweep.command == "render") {
      // Paths inside the task directory, not the staging name it was written under.
      if (report.contains("exr")) report["exr"] = "render.exr";
      if (report.contains("png")) report["png"] = "render.png";
    }
    record["status"] = "ok";
    record["result"] = std::move(report);
  } else {
    record["status"] = "failed";
    record["error"] = error;
  }
  writeTextFileAtomically(staging / "timing.json", timing.dump(2) + "\n");
  writeTextFileAtomically(staging / "task.json", record.dump(2) + "\n");
  return error.empty();
}

}  // namespace

fs::path sweepTaskDirectory(const fs::path& sweepDirectory, std::size_t index) {
  char name[32];
  std::snprintf(name, sizeof name, "%06zu", index);
  return sweepDirectory / "tasks" / name;
}

json sweepManifest(const SweepSpec& sweep) {
  json tasks = json::array();
  for (const SweepTask& task : sweep.tasks)
    tasks.push_back(
        {{"index", task.index}, {"material", task.material}, {"vary", task.vary}, {"seed", task.seed}});
  return {{"generator", Generator},           {"hash", sweep.hash},
          {"command", sweep.command},         {"spec", sweep.spec},
          {"task_count", sweep.tasks.size()}, {"tasks", tasks}};
}

void prepareSweepDirectory(const SweepSpec& sweep, const fs::path& directory) {
  std::error_code error;
  const fs::path manifest = directory / SweepManifestName;
  if (fs::exists(directory, error)) {
    if (!fs::is_directory(directory, error))
      throw InputError("--out " + directory.string() + ": exists and is not a directory");
    if (fs::exists(manifest, error)) {
      json existing;
      try {
        existing = json::parse(readText(manifest));
      } catch (const json::exception&) {
        throw InputError("--out " + directory.string() +
                         ": its sweep.json is not readable JSON; refusing to touch it");
      }
      if (existing.value("generator", "") != Generator || existing.value("hash", "") != sweep.hash)
        throw InputError("--out " + directory.string() + ": holds the results of another sweep (hash " +
                         existing.value("hash", std::string("?")) + ", this spec's is " + sweep.hash +
                         "); refusing to mix them: choose another directory");
    } else if (!fs::is_empty(directory, error)) {
      throw InputError("--out " + directory.string() +
                       ": exists, is not empty and holds no sweep.json; refusing to write into it");
    }
  }
  createDirectoriesUninterrupted(directory / "tasks");
  // Shards of a job array may start together: each writes the same bytes atomically.
  if (!fs::exists(manifest, error)) writeTextFileAtomically(manifest, sweepManifest(sweep).dump(2) + "\n");
}

std::size_t removeStalePartialTasks(const fs::path& directory) {
  const std::string prefix = ".partial-" + hostName() + "-";
  std::size_t removed = 0;
  std::error_code error;
  for (fs::directory_iterator it(directory / "tasks", error), end; !error && it != end; it.increment(error)) {
    const std::string name = it->path().filename().string();
    const std::size_t at = name.find(prefix);
    if (name.empty() || name[0] != '.' || at == std::string::npos) continue;
    const pid_t pid = static_cast<pid_t>(std::atol(name.c_str() + at + prefix.size()));
    if (pid > 0 && kill(pid, 0) != 0 && errno == ESRCH) {
      std::error_code removeError;
      fs::remove_all(it->path(), removeError);
      if (!removeError) ++removed;
    }
  }
  return removed;
}

json extractTimings(json& report) {
  json timings = json::object();
  extractTimingsAt(report, "", timings);
  return timings;
}

SweepRunSummary runSweepShard(const SweepSpec& sweep, const fs::path& directory, const SweepShard& shard,
                              std::ostream& log) {
  SweepRunSummary summary;
  summary.stalePartials = removeStalePartialTasks(directory);
  if (summary.stalePartials > 0)
    log << "sweep: removed " << summary.stalePartials
        << " partial task(s) of interrupted runs on this host\n";
  std::vector<const SweepTask*> pending;
  for (const SweepTask& task : sweep.tasks) {
    if (!shard.contains(task.index)) continue;
    ++summary.inShard;
    if (isCompleteTask(sweepTaskDirectory(directory, task.index)))
      ++summary.skipped;
    else
      pending.push_back(&task);
  }
  log << "sweep " << sweep.hash << ": shard " << shard.number << "/" << shard.count << ", " << summary.inShard
      << " of " << sweep.tasks.size() << " tasks, " << summary.skipped << " already complete, "
      << pending.size() << " to run\n";
  const std::string suffix = ".partial-" + hostName() + "-" + std::to_string(getpid());
  for (std::size_t n = 0; n < pending.size(); ++n) {
    const SweepTask& task = *pending[n];
    const fs::path final = sweepTaskDirectory(directory, task.index);
    const fs::path staging = final.parent_path() / ("." + final.filename().string() + suffix);
    std::error_code error;
    TemporaryPath stagingGuard = createTemporaryDirectory(staging, error);  // temporary_files.h
    if (error) throw fs::filesystem_error("cannot create the task's staging directory", staging, error);
    const auto start = std::chrono::steady_clock::now();
    const bool ok = runTask(sweep, task, staging);
    {
      const auto deferred = deferInterruptions();
      // A failed record of an earlier run is replaced by this one.
      fs::remove_all(final);
      fs::rename(staging, final);
      stagingGuard.keep();
    }
    ok ? ++summary.succeeded : ++summary.failed;
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    log << "sweep: [" << (n + 1) << "/" << pending.size() << "] task " << task.index << " "
        << (ok ? "done" : "FAILED") << " in " << std::fixed << std::setprecision(2) << seconds << " s"
        << std::defaultfloat << "\n";
    log.flush();
  }
  return summary;
}

}  // namespace scatterlab
