// Running a sweep's tasks (docs/sweeps.md): each task is the real subcommand, started as a child
// process of this executable in the spec's directory, its JSON report kept as the task's result.
// A child is isolated: a task that fails (bad input, a crash) is recorded with its error and
// the shard goes on.
//
// The sweep directory DIR:
//   DIR/sweep.json            the spec, its hash and the expanded task list (written once)
//   DIR/tasks/NNNNNN/         one complete task: task.json (the result, deterministic),
//                             timing.json (wall time, peak memory, the command's own timings),
//                             stderr.txt, and the command's files (render.exr, render.png)
//   DIR/tasks/.NNNNNN.partial-HOST-PID   a task being run; renamed into place when complete
// A task directory exists only when complete, so a shard that is killed or preempted loses
// only the task it was running; run again, it skips the completed ones.
#pragma once

#include <cstdint>
#include <filesystem>
#include <iosfwd>

#include <nlohmann/json.hpp>

#include "app/sweep/sweep_spec.h"

namespace scatterlab {

// DIR/tasks/NNNNNN (six digits; more for indices past a million).
std::filesystem::path sweepTaskDirectory(const std::filesystem::path& sweepDirectory, std::size_t index);

// The deterministic description of the sweep stored as DIR/sweep.json.
nlohmann::json sweepManifest(const SweepSpec& sweep);

// Makes `directory` the sweep's: creates it and writes sweep.json, or accepts it when it
// already holds this sweep (same hash). Refuses, with InputError and nothing written, a
// directory holding another sweep's results or anything that is not a sweep's.
void prepareSweepDirectory(const SweepSpec& sweep, const std::filesystem::path& directory);

// Removes this host's partial task directories whose process is gone; returns how many.
std::size_t removeStalePartialTasks(const std::filesystem::path& directory);

// Moves every timing out of a command's JSON report: keys named "seconds" or ending in
// "_seconds" or "_per_second" (what a rerun changes). Returns them by JSON pointer.
nlohmann::json extractTimings(nlohmann::json& report);

struct SweepRunSummary {
  std::size_t inShard = 0;    // tasks this shard owns
  std::size_t skipped = 0;    // already complete
  std::size_t succeeded = 0;  // run now, a result recorded
  std::size_t failed = 0;     // run now, an error recorded
  std::size_t stalePartials = 0;
};

// Runs the shard's tasks that are not complete, in index order, one line of progress per
// task on `log`. Failed tasks are retried on a later run.
SweepRunSummary runSweepShard(const SweepSpec& sweep, const std::filesystem::path& directory,
                              const SweepShard& shard, std::ostream& log);

}  // namespace scatterlab
