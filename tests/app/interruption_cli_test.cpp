// An interrupted command (SIGINT, SIGTERM) removes its temporaries and leaves the previous
// outputs as they were; a temporary left by a killed run is removed by the next; two lab runs
// into one directory do not overwrite each other (materials/core/temporary_files.h,
// app/staged_outputs.h, app/lab/staged_directory.h).
#include <gtest/gtest.h>

#include <signal.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "app/measured_bundle.h"
#include "cli_runner.h"

namespace scatterlab {
namespace interruption_cli_test {

using namespace cli_runner;

const std::string Lambertian = R"({"type":"lambertian","albedo":0.5})";

fs::path writeText(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  std::ofstream(path) << text;
  return path;
}

// Entries of `directory` whose names hold `fragment`.
std::vector<std::string> entriesWith(const fs::path& directory, const std::string& fragment) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(directory))
    if (entry.path().filename().string().find(fragment) != std::string::npos)
      names.push_back(entry.path().filename().string());
  return names;
}

// A PID no process has (the highest free one below the kernel's limit).
pid_t deadPid() {
  for (pid_t pid = 4000000; pid > 1000; --pid)
    if (kill(pid, 0) == -1 && errno == ESRCH) return pid;
  return 0;
}

// Starts `args`, waits until `path` exists (the run is at work), sends `signal`, and returns
// the finished run.
ProcessResult interruptOnce(const std::vector<std::string>& args, const std::function<fs::path(pid_t)>& path,
                            int signal) {
  const RunningProcess process = startScatterlab(args);
  EXPECT_TRUE(waitUntil([&] { return fs::exists(path(process.pid)); })) << path(process.pid);
  kill(process.pid, signal);
  return finishScatterlab(process);
}

TEST(Interruption, RenderRemovesItsTemporariesAndKeepsThePreviousPair) {
  const fs::path prefix = uniquePath("interrupt-render") / "sphere";
  fs::create_directories(prefix.parent_path());
  writeText(prefix.string() + ".exr", "old exr");
  writeText(prefix.string() + ".png", "old png");
  const ProcessResult run = interruptOnce(
      {"render", Lambertian, "--res", "64", "--spp", "100000", "--out", prefix.string()},
      [&](pid_t pid) { return fs::path(prefix.string() + ".exr.tmp-" + std::to_string(pid)); }, SIGINT);
  EXPECT_EQ(run.exitCode, 128 + SIGINT) << describe(run);
  EXPECT_TRUE(entriesWith(prefix.parent_path(), ".tmp-").empty());
  EXPECT_EQ(readFile(prefix.string() + ".exr"), "old exr");
  EXPECT_EQ(readFile(prefix.string() + ".png"), "old png");
}

TEST(Interruption, SynthAndFitRemoveTheirTemporaries) {
  const fs::path dir = uniquePath("interrupt-synth");
  const fs::path table = writeText(dir / "t.binary", "old table");
  ProcessResult run = interruptOnce(
      {"synth", Lambertian, "--threads", "1", "--out", table.string()},
      [&](pid_t pid) { return fs::path(table.string() + ".tmp-" + std::to_string(pid)); }, SIGTERM);
  EXPECT_EQ(run.exitCode, 128 + SIGTERM) << describe(run);
  EXPECT_EQ(readFile(table), "old table");
  const fs::path fitted = writeText(dir / "fit.json", "old fit");
  run = interruptOnce(
      {"fit", Lambertian, "--model", "lambertian", "--metric", "l2", "--threads", "1", "--out",
       fitted.string()},
      [&](pid_t pid) { return fs::path(fitted.string() + ".tmp-" + std::to_string(pid)); }, SIGINT);
  EXPECT_EQ(run.exitCode, 128 + SIGINT) << describe(run);
  EXPECT_EQ(readFile(fitted), "old fit");
  EXPECT_TRUE(entriesWith(dir, ".tmp-").empty());
}

// The bundle writes its tables one after another: interrupted while writing the first, it leaves
// no temporary, and a table of an earlier run (another of the bundle's names) as it was.
TEST(Interruption, SynthBundleRemovesItsTemporaries) {
  const fs::path dir = uniquePath("interrupt-bundle");
  const auto bundle = measuredBundle();
  ASSERT_GE(bundle.size(), 2u);
  const fs::path first = dir / (std::string(bundle[0].name) + ".binary");
  const fs::path earlier = writeText(dir / (std::string(bundle[1].name) + ".binary"), "earlier table");
  const ProcessResult run = interruptOnce(
      {"synth", "--bundle", dir.string(), "--threads", "1"},
      [&](pid_t pid) { return fs::path(first.string() + ".tmp-" + std::to_string(pid)); }, SIGINT);
  EXPECT_EQ(run.exitCode, 128 + SIGINT) << describe(run);
  EXPECT_TRUE(entriesWith(dir, ".tmp-").empty());
  EXPECT_FALSE(fs::exists(first));
  EXPECT_EQ(readFile(earlier), "earlier table");
}

TEST(Interruption, CheckImagesLeaveTheDirectoryAsItWas) {
  const fs::path images = uniquePath("interrupt-images");
  writeText(images / "lambertian_wi0_observed.png", "old image");
  const ProcessResult run = interruptOnce(
      {"check", R"({"type":"lambertian"})", "--samples", "100000000", "--images", images.string()},
      [&](pid_t pid) { return images / (".scatterlab.partial-" + std::to_string(pid)); }, SIGINT);
  EXPECT_EQ(run.exitCode, 128 + SIGINT) << describe(run);
  EXPECT_TRUE(entriesWith(images, "partial").empty());
  EXPECT_EQ(readFile(images / "lambertian_wi0_observed.png"), "old image");
}

TEST(Interruption, LabRemovesItsStagingDirectoryAndLockAndKeepsTheOldReport) {
  const fs::path out = uniquePath("interrupt-lab") / "report";
  // A report of an earlier run, as its manifest describes it.
  writeText(out / "index.html", "old report");
  writeText(out / "manifest.json",
            R"({"generator":"scatterlab lab","files":["index.html"],"directories":[]})");
  const ProcessResult run = interruptOnce(
      {"lab", Lambertian, "--quick", "--out", out.string()},
      [&](pid_t pid) { return out.parent_path() / (".report.partial-" + std::to_string(pid) + "-0"); },
      SIGTERM);
  EXPECT_EQ(run.exitCode, 128 + SIGTERM) << describe(run);
  EXPECT_EQ(entriesWith(out.parent_path(), ".report."), std::vector<std::string>{});
  EXPECT_EQ(readFile(out / "index.html"), "old report");
}

TEST(Interruption, TemporariesOfDeadRunsAreRemovedAndLiveOnesKept) {
  const fs::path dir = uniquePath("stale");
  const pid_t dead = deadPid();
  ASSERT_GT(dead, 0);
  const fs::path stale = writeText(dir / ("t.binary.tmp-" + std::to_string(dead)), "left by a killed run");
  const fs::path live = writeText(dir / ("t.binary.tmp-" + std::to_string(getpid())), "another run's");
  const fs::path staleLab = dir / (".report.partial-" + std::to_string(dead) + "-0");
  writeText(staleLab / "index.html", "half a report");
  const fs::path unrelated = writeText(dir / "t.binary.tmp-notes", "a user's file");
  ASSERT_EQ(runScatterlab({"synth", Lambertian, "--out", (dir / "t.binary").string()}).exitCode, 0);
  EXPECT_FALSE(fs::exists(stale));
  EXPECT_TRUE(fs::exists(live));
  EXPECT_TRUE(fs::exists(unrelated));
  EXPECT_TRUE(fs::exists(staleLab));  // not beside this output: left for the lab run below
  expectBadInput({"lab", Lambertian, "--out", (dir / "report").string(), "--env", "missing.exr"}, {"--env"});
  EXPECT_TRUE(fs::exists(staleLab));  // bad input: nothing touched
}

TEST(Interruption, ASecondLabIntoTheSameDirectoryIsRefused) {
  const fs::path out = uniquePath("lab-twice") / "report";
  const RunningProcess first = startScatterlab({"lab", Lambertian, "--quick", "--out", out.string()});
  ASSERT_TRUE(waitUntil([&] { return fs::exists(out.parent_path() / ".report.lock"); }));
  expectBadInput({"lab", Lambertian, "--quick", "--out", out.string()},
                 {"--out", "is being written by another run", std::to_string(first.pid)});
  kill(first.pid, SIGTERM);
  const ProcessResult run = finishScatterlab(first);
  EXPECT_EQ(run.exitCode, 128 + SIGTERM) << describe(run);
  EXPECT_EQ(entriesWith(out.parent_path(), ".report."), std::vector<std::string>{});
}

}  // namespace interruption_cli_test
}  // namespace scatterlab
