// `scatterlab sweep` and `scatterlab merge` end to end (docs/sweeps.md): any sharding merges to
// the same bytes, a rerun resumes, a failed task is recorded without stopping the shard, and
// bad specs, shards and directories are refused before anything is written.
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/app/cli_runner.h"

namespace scatterlab {
namespace sweep_cli_test {

namespace fs = std::filesystem;
using cli_runner::describe;
using cli_runner::expectBadInput;
using cli_runner::readFile;
using cli_runner::runScatterlab;
using cli_runner::uniquePath;
using nlohmann::json;

// 6 materials x 2 azimuths = 12 check tasks of a few hundredths of a second each.
const std::string SmokeSpec = std::string(SCATTERLAB_DATA_DIR) + "/sweeps/smoke.json";
constexpr int SmokeTaskCount = 12;

fs::path writeSpec(const json& spec) {
  const fs::path directory = uniquePath("sweep-spec");
  fs::create_directories(directory);
  std::ofstream(directory / "spec.json") << spec.dump(2);
  return directory / "spec.json";
}

void runOk(const std::vector<std::string>& args) {
  const auto run = runScatterlab(args);
  ASSERT_EQ(run.exitCode, 0) << describe(run);
}

fs::path merged(const std::vector<fs::path>& directories) {
  const fs::path out = uniquePath("sweep-merged");
  std::vector<std::string> args{"merge"};
  for (const fs::path& directory : directories) args.push_back(directory.string());
  args.insert(args.end(), {"--out", out.string()});
  runOk(args);
  return out;
}

void expectSameMerge(const fs::path& a, const fs::path& b) {
  for (const char* file : {"results.json", "results.csv", "summary.html"}) {
    ASSERT_TRUE(fs::exists(a / file)) << a / file;
    EXPECT_EQ(readFile(a / file), readFile(b / file)) << file << " differs between " << a << " and " << b;
  }
}

json jsonOf(const std::string& text) { return json::parse(text); }

TEST(SweepCli, OneThreeAndFourShardsMergeToTheSameBytes) {
  const fs::path one = uniquePath("sweep-one");
  runOk({"sweep", SmokeSpec, "--out", one.string()});

  // Three shards in three directories, run out of order.
  std::vector<fs::path> three;
  for (int k : {3, 1, 2}) {
    three.push_back(uniquePath("sweep-three"));
    runOk({"sweep", SmokeSpec, "--out", three.back().string(), "--shard", std::to_string(k) + "/3"});
  }
  // Four shards sharing one directory.
  const fs::path four = uniquePath("sweep-four");
  for (int k = 1; k <= 4; ++k)
    runOk({"sweep", SmokeSpec, "--out", four.string(), "--shard", std::to_string(k) + "/4"});

  const fs::path mergedOne = merged({one});
  expectSameMerge(mergedOne, merged(three));
  expectSameMerge(mergedOne, merged({four}));
  const json results = jsonOf(readFile(mergedOne / "results.json"));
  EXPECT_EQ(results["task_count"], SmokeTaskCount);
  EXPECT_EQ(results["complete"], true);
  EXPECT_EQ(results["tasks"][0]["status"], "ok");
}

TEST(SweepCli, ARerunSkipsCompleteTasksAndReplacesInterruptedOnes) {
  const fs::path directory = uniquePath("sweep-resume");
  runOk({"sweep", SmokeSpec, "--out", directory.string()});
  // An interruption: one task never completed, and a dead run's partial directory is left.
  const std::string firstRecord = readFile(directory / "tasks" / "000005" / "task.json");
  fs::remove_all(directory / "tasks" / "000005");
  const pid_t dead = fork();
  if (dead == 0) _exit(0);
  waitpid(dead, nullptr, 0);
  char host[256] = {};
  gethostname(host, sizeof host - 1);
  const fs::path partial =
      directory / "tasks" / (".000005.partial-" + std::string(host) + "-" + std::to_string(dead));
  fs::create_directories(partial);

  const auto rerun = runScatterlab({"sweep", SmokeSpec, "--out", directory.string(), "--json"});
  ASSERT_EQ(rerun.exitCode, 0) << describe(rerun);
  const json summary = jsonOf(rerun.out);
  EXPECT_EQ(summary["succeeded"], 1);
  EXPECT_EQ(summary["skipped_complete"], SmokeTaskCount - 1);
  EXPECT_EQ(summary["removed_partials"], 1);
  EXPECT_FALSE(fs::exists(partial));
  // The rerun task gives the same record, byte for byte: its seed is the spec's, not the run's.
  EXPECT_EQ(readFile(directory / "tasks" / "000005" / "task.json"), firstRecord);
}

TEST(SweepCli, AFailedTaskIsRecordedAndTheOthersStillRun) {
  const fs::path spec = writeSpec(
      {{"command", "fit"},
       {"materials", {{{"type", "lambertian"}, {"albedo", {0.3, 0.5, 0.2}}}, "broken.binary"}},
       {"options",
        {{"model", "lambertian"}, {"metric", "l2"}, {"samples", 2000}, {"starts", 1}, {"grid-points", 4}}}});
  std::ofstream(spec.parent_path() / "broken.binary") << "not a MERL table";
  const fs::path directory = uniquePath("sweep-failed");
  const auto run = runScatterlab({"sweep", spec.string(), "--out", directory.string()});
  EXPECT_EQ(run.exitCode, 1) << describe(run);
  const json ok = jsonOf(readFile(directory / "tasks/000000/task.json"));
  const json failed = jsonOf(readFile(directory / "tasks/000001/task.json"));
  EXPECT_EQ(ok["status"], "ok");
  EXPECT_EQ(ok["result"]["verdict"], "good");
  EXPECT_EQ(failed["status"], "failed");
  EXPECT_NE(failed["error"].get<std::string>().find("broken.binary"), std::string::npos) << failed.dump(2);

  const fs::path out = uniquePath("sweep-failed-merged");
  const auto merge = runScatterlab({"merge", directory.string(), "--out", out.string()});
  EXPECT_EQ(merge.exitCode, 1) << describe(merge);
  EXPECT_NE(merge.err.find("1 failed: 1"), std::string::npos) << describe(merge);
  EXPECT_EQ(jsonOf(readFile(out / "results.json"))["failed"], json::array({1}));
  EXPECT_NE(readFile(out / "summary.html").find("error: exit 2"), std::string::npos);
}

TEST(SweepCli, MergingSomeShardsWritesTheMergeAndNamesTheMissingTasks) {
  const fs::path shard = uniquePath("sweep-part");
  runOk({"sweep", SmokeSpec, "--out", shard.string(), "--shard", "1/3"});
  const fs::path out = uniquePath("sweep-part-merged");
  const auto merge = runScatterlab({"merge", shard.string(), "--out", out.string()});
  EXPECT_EQ(merge.exitCode, 1) << describe(merge);
  EXPECT_NE(merge.err.find("8 missing (not run yet): 1, 2, 4, 5"), std::string::npos) << describe(merge);
  const json results = jsonOf(readFile(out / "results.json"));
  EXPECT_EQ(results["complete"], false);
  EXPECT_EQ(results["missing"].size(), 8u);
  EXPECT_EQ(results["tasks"][1]["status"], "missing");
}

TEST(SweepCli, TaskSeedsComeFromTheSpecAndIndexNotTheShard) {
  const auto all = runScatterlab({"sweep", SmokeSpec, "--list", "--json"});
  const auto second = runScatterlab({"sweep", SmokeSpec, "--list", "--json", "--shard", "2/3"});
  ASSERT_EQ(all.exitCode, 0) << describe(all);
  ASSERT_EQ(second.exitCode, 0) << describe(second);
  const json allTasks = jsonOf(all.out)["tasks"], shardTasks = jsonOf(second.out)["tasks"];
  ASSERT_EQ(allTasks.size(), static_cast<std::size_t>(SmokeTaskCount));
  ASSERT_EQ(shardTasks.size(), 4u);  // indices 1, 4, 7, 10
  for (const json& task : shardTasks) {
    const std::size_t index = task["index"];
    EXPECT_EQ(index % 3, 1u);
    EXPECT_EQ(task["seed"], allTasks[index]["seed"]);
    EXPECT_EQ(task["arguments"], allTasks[index]["arguments"]);
  }
  EXPECT_NE(allTasks[0]["seed"], allTasks[1]["seed"]);
}

TEST(SweepCli, FromEnvTakesTheShardFromSlurmArrayVariables) {
  setenv("SLURM_ARRAY_TASK_ID", "3", 1);
  setenv("SLURM_ARRAY_TASK_MIN", "1", 1);
  setenv("SLURM_ARRAY_TASK_COUNT", "4", 1);
  const auto run = runScatterlab({"sweep", SmokeSpec, "--list", "--json", "--shard", "from-env"});
  unsetenv("SLURM_ARRAY_TASK_ID");
  unsetenv("SLURM_ARRAY_TASK_MIN");
  unsetenv("SLURM_ARRAY_TASK_COUNT");
  ASSERT_EQ(run.exitCode, 0) << describe(run);
  EXPECT_EQ(jsonOf(run.out)["shard"], "3/4");
  expectBadInput({"sweep", SmokeSpec, "--list", "--shard", "from-env"}, {"SLURM_ARRAY_TASK_ID is not set"});
}

TEST(SweepCli, ShardsOutsideOneToNAreRefused) {
  expectBadInput({"sweep", SmokeSpec, "--list", "--shard", "0/3"},
                 {"--shard", "does not exist", "1 <= K <= N"});
  expectBadInput({"sweep", SmokeSpec, "--list", "--shard", "4/3"}, {"shard 4 of 3 does not exist"});
  expectBadInput({"sweep", SmokeSpec, "--list", "--shard", "two"}, {"\"two\" is not K/N"});
}

TEST(SweepCli, BadSpecsAreRefusedBeforeAnythingIsWritten) {
  const json lambertian = {{"type", "lambertian"}};
  struct Case {
    json spec;
    std::vector<std::string> message;
  };
  const std::vector<Case> cases = {
      {{{"command", "synth"}, {"materials", {lambertian}}}, {"\"command\"", "allowed: \"check\", \"fit\""}},
      {{{"command", "check"}, {"materials", {lambertian}}, {"shards", 3}}, {"unknown key \"shards\""}},
      {{{"command", "check"}, {"materials", json::array()}}, {"\"materials\" must be a non-empty array"}},
      {{{"command", "check"}, {"materials", {"nothing-here/*.json"}}}, {"matches no file"}},
      {{{"command", "check"}, {"materials", {lambertian}}, {"vary", {{"wi-phi", json::array()}}}},
       {"vary.wi-phi", "non-empty list"}},
      {{{"command", "check"}, {"materials", {lambertian}}, {"options", {{"seed", 4}}}},
       {"\"seed\" is set by the sweep"}},
      {{{"command", "check"}, {"materials", {{{"type", "lambertian"}, {"albedo", {{"$range", {0, 1}}}}}}}},
       {"unknown sweep operator \"$range\""}},
      {{{"command", "check"}, {"materials", {lambertian}}, {"options", {{"samples", 5}}}},
       {"--samples", "5"}},
      {{{"command", "check"}, {"materials", {{{"type", "lambertian"}, {"albedo", 7}}}}}, {"albedo", "7"}},
  };
  for (const Case& c : cases) {
    const fs::path spec = writeSpec(c.spec);
    const fs::path out = uniquePath("sweep-bad");
    expectBadInput({"sweep", spec.string(), "--out", out.string()}, c.message);
    EXPECT_FALSE(fs::exists(out)) << c.spec.dump();
  }
}

TEST(SweepCli, ADeeplyNestedSpecIsRefusedWithoutACrash) {
  const fs::path directory = uniquePath("sweep-deep");
  fs::create_directories(directory);
  const int depth = 100000;
  std::ofstream(directory / "spec.json") << "{\"command\": \"check\", \"materials\": ["
                                         << std::string(depth, '[') << std::string(depth, ']') << "]}";
  expectBadInput({"sweep", (directory / "spec.json").string(), "--list"}, {"spec.json", "deep"});
}

TEST(SweepCli, ADirectoryHoldingSomethingElseIsRefusedAndLeftAlone) {
  // Another sweep's results.
  const fs::path other = uniquePath("sweep-other");
  runOk({"sweep", SmokeSpec, "--out", other.string(), "--shard", "1/12"});
  const std::string manifest = readFile(other / "sweep.json");
  const fs::path spec = writeSpec({{"command", "check"},
                                   {"materials", {{{"type", "lambertian"}}}},
                                   {"options", {{"samples", 2000}, {"grid", "8x16"}}}});
  expectBadInput({"sweep", spec.string(), "--out", other.string()}, {"holds the results of another sweep"});
  EXPECT_EQ(readFile(other / "sweep.json"), manifest);
  EXPECT_FALSE(fs::exists(other / "tasks" / "000001"));
  // A directory of someone's files.
  const fs::path files = uniquePath("sweep-files");
  fs::create_directories(files);
  std::ofstream(files / "notes.txt") << "mine";
  expectBadInput({"sweep", spec.string(), "--out", files.string()}, {"holds no sweep.json"});
  EXPECT_EQ(readFile(files / "notes.txt"), "mine");
  // merge: not a sweep directory, and two different sweeps.
  const fs::path mergeOut = uniquePath("sweep-merge-bad");
  expectBadInput({"merge", files.string(), "--out", mergeOut.string()}, {"is not a sweep directory"});
  const fs::path mine = uniquePath("sweep-mine");
  runOk({"sweep", spec.string(), "--out", mine.string()});
  expectBadInput({"merge", other.string(), mine.string(), "--out", mergeOut.string()},
                 {"holds another sweep"});
  EXPECT_FALSE(fs::exists(mergeOut));
}

TEST(SweepCli, ARenderSweepKeepsEachTasksImagesInItsDirectory) {
  const fs::path spec =
      writeSpec({{"command", "render"},
                 {"materials", {{{"type", "conductor"}, {"alpha", {{"$values", {0.1, 0.4}}}}}}},
                 {"options", {{"res", "16x16"}, {"spp", 2}}}});
  const fs::path directory = uniquePath("sweep-render");
  runOk({"sweep", spec.string(), "--out", directory.string()});
  for (const char* task : {"000000", "000001"}) {
    EXPECT_TRUE(fs::exists(directory / "tasks" / task / "render.exr"));
    EXPECT_TRUE(fs::exists(directory / "tasks" / task / "render.png"));
    const json record = jsonOf(readFile(directory / "tasks" / task / "task.json"));
    EXPECT_EQ(record["result"]["exr"], "render.exr");
    EXPECT_FALSE(record["result"]["renders"][0].contains("seconds")) << "timings belong in timing.json";
    EXPECT_TRUE(jsonOf(readFile(directory / "tasks" / task / "timing.json"))["reported"].contains(
        "/renders/0/seconds"));
  }
  const json results = jsonOf(readFile(merged({directory}) / "results.json"));
  EXPECT_EQ(results["tasks"][1]["files"][0], "tasks/000001/render.exr");
}

}  // namespace sweep_cli_test
}  // namespace scatterlab
