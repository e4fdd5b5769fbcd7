// Running the real `scatterlab` executable from the CLI tests: exit code, stdout and stderr
// of one run, and scratch paths that parallel test processes do not share.
#pragma once

#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

extern char** environ;

namespace scatterlab::cli_runner {

namespace fs = std::filesystem;

inline fs::path testOutputDir() {
  const fs::path dir = fs::path(SCATTERLAB_TEST_OUTPUT_DIR) / "cli";
  fs::create_directories(dir);
  return dir;
}

// A path under the test output directory that no other test process uses (CTest may run
// tests in parallel), and that does not exist yet.
inline fs::path uniquePath(const std::string& stem) {
  static std::atomic<int> counter{0};
  const fs::path path =
      testOutputDir() / (stem + "-" + std::to_string(getpid()) + "-" + std::to_string(counter++));
  fs::remove_all(path);
  return path;
}

// `text` written to a fresh file under the test output (uniquePath(stem)), for an input file.
inline fs::path writeInputFile(const std::string& stem, const std::string& text) {
  const fs::path path = uniquePath(stem);
  std::ofstream(path) << text;
  return path;
}

inline std::string readFile(const fs::path& path) {
  std::ifstream file(path);
  std::ostringstream contents;
  contents << file.rdbuf();
  return contents.str();
}

struct ProcessResult {
  int exitCode = -1;
  std::string out;
  std::string err;
};

// How a run is started: where stdout goes (a file of the runner by default; "/dev/full" to
// test write errors) and a file-size limit (RLIMIT_FSIZE, to make a write fail half-way as
// on a full disk).
struct RunOptions {
  std::string stdoutPath;
  std::optional<rlim_t> fileSizeLimit;
};

// A run started in the background (startScatterlab), to be interrupted or waited for.
struct RunningProcess {
  pid_t pid = -1;
  fs::path outPath, errPath;
};

inline RunningProcess startScatterlab(const std::vector<std::string>& args, const RunOptions& options = {}) {
  RunningProcess process{-1, uniquePath("stdout"), uniquePath("stderr")};
  const std::string out = options.stdoutPath.empty() ? process.outPath.string() : options.stdoutPath;
  std::vector<std::string> argvStrings{SCATTERLAB_EXE};
  argvStrings.insert(argvStrings.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& arg : argvStrings) argv.push_back(arg.data());
  argv.push_back(nullptr);
  const pid_t pid = fork();
  if (pid == 0) {  // the child: only async-signal-safe calls until exec
    const int outFd = open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int errFd = open(process.errPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (outFd < 0 || errFd < 0 || dup2(outFd, STDOUT_FILENO) < 0 || dup2(errFd, STDERR_FILENO) < 0)
      _exit(126);
    if (options.fileSizeLimit) {
      // A write past the limit then fails with EFBIG instead of killing the process.
      signal(SIGXFSZ, SIG_IGN);
      const rlimit limit{*options.fileSizeLimit, *options.fileSizeLimit};
      setrlimit(RLIMIT_FSIZE, &limit);
    }
    execv(SCATTERLAB_EXE, argv.data());
    _exit(127);
  }
  EXPECT_GT(pid, 0) << "cannot start " << SCATTERLAB_EXE;
  process.pid = pid;
  return process;
}

// Waits for the run; the exit code is 128 + the signal when a signal ended it, as in a shell.
inline ProcessResult finishScatterlab(const RunningProcess& process) {
  ProcessResult run;
  if (process.pid <= 0) return run;
  int status = 0;
  waitpid(process.pid, &status, 0);
  run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  run.out = readFile(process.outPath);
  run.err = readFile(process.errPath);
  fs::remove(process.outPath);
  fs::remove(process.errPath);
  return run;
}

// Waits (up to `seconds`) until `ready` holds, polling every 20 ms; false on time-out.
template <typename Ready> bool waitUntil(Ready ready, double seconds = 60.0) {
  for (int i = 0; i < int(seconds * 50); ++i) {
    if (ready()) return true;
    usleep(20000);
  }
  return ready();
}

inline ProcessResult runScatterlab(const std::vector<std::string>& args, const RunOptions& options) {
  return finishScatterlab(startScatterlab(args, options));
}

// Runs the real executable with stdout and stderr redirected to files (files, not pipes: a
// full pipe would block the child while the parent waits for it), in this process's environment
// plus `environment` ("NAME=VALUE" entries, which override).
inline ProcessResult runScatterlab(const std::vector<std::string>& args,
                                   const std::vector<std::string>& environment = {}) {
  const fs::path outPath = uniquePath("stdout"), errPath = uniquePath("stderr");
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, outPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                   0644);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, errPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                   0644);
  std::vector<std::string> argvStrings{SCATTERLAB_EXE};
  argvStrings.insert(argvStrings.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& arg : argvStrings) argv.push_back(arg.data());
  argv.push_back(nullptr);

  std::vector<std::string> environmentStrings = environment;
  for (char** entry = environ; *entry; ++entry) {
    const std::string text = *entry;
    const std::string name = text.substr(0, text.find('='));
    bool overridden = false;
    for (const std::string& extra : environment) overridden |= extra.rfind(name + "=", 0) == 0;
    if (!overridden) environmentStrings.push_back(text);
  }
  std::vector<char*> envp;
  for (std::string& entry : environmentStrings) envp.push_back(entry.data());
  envp.push_back(nullptr);

  ProcessResult run;
  pid_t pid = 0;
  const int spawnError = posix_spawn(&pid, SCATTERLAB_EXE, &actions, nullptr, argv.data(), envp.data());
  posix_spawn_file_actions_destroy(&actions);
  EXPECT_EQ(spawnError, 0) << "cannot start " << SCATTERLAB_EXE;
  if (spawnError != 0) return run;
  int status = 0;
  waitpid(pid, &status, 0);
  run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  run.out = readFile(outPath);
  run.err = readFile(errPath);
  fs::remove(outPath);
  fs::remove(errPath);
  return run;
}

inline std::string describe(const ProcessResult& run) {
  return "exit " + std::to_string(run.exitCode) + "\nstdout:\n" + run.out + "\nstderr:\n" + run.err;
}

// Command lines joined.
inline std::vector<std::string> operator+(std::vector<std::string> a, const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

inline void expectMentions(const std::string& text, const std::vector<std::string>& fragments) {
  for (const std::string& fragment : fragments)
    EXPECT_NE(text.find(fragment), std::string::npos) << "\"" << fragment << "\" missing from:\n" << text;
}

// A bad-input run: exit 2, one error message mentioning `fragments`, nothing on stdout.
inline void expectBadInput(const std::vector<std::string>& args, const std::vector<std::string>& fragments) {
  const ProcessResult run = runScatterlab(args);
  EXPECT_EQ(run.exitCode, 2) << describe(run);
  EXPECT_TRUE(run.out.empty()) << describe(run);
  EXPECT_EQ(run.err.rfind("scatterlab: error: ", 0), 0u) << describe(run);
  expectMentions(run.err, fragments);
}

}  // namespace scatterlab::cli_runner
