// Merging a sweep's results (docs/sweeps.md): every task's result from one or more sweep
// directories (one per shard, or one shared by all) gathered in index order into one table.
//
// OUT/results.json   the sweep's spec and hash, the counts, the missing and failed indices and
//                    every task's record (material, varied options, seed, status, result);
//                    byte-identical whatever the shard count or order, since no record holds
//                    a timing or the directory it came from
// OUT/results.csv    one row per task: the varied options and the command's headline numbers
// OUT/summary.html   check and fit sweeps: a verdict matrix, materials x varied options
// OUT/timings.json   the side file that is allowed to differ: per task its wall time, peak
//                    memory and the command's own timings, and the directory it came from
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace scatterlab {

struct SweepMerge {
  nlohmann::json results;  // results.json
  nlohmann::json timings;  // timings.json
  std::string csv;
  std::string html;  // empty for render and profile sweeps
  std::vector<std::size_t> missing, failed;
};

// Reads every directory's sweep.json (they must name the same sweep) and its completed tasks.
// Throws InputError naming the directory when one is not a sweep directory or holds another
// sweep.
SweepMerge mergeSweepDirectories(const std::vector<std::filesystem::path>& directories);

// The CSV table and the HTML summary of a merged results document.
std::string sweepResultsCsv(const nlohmann::json& results);
std::string sweepSummaryHtml(const nlohmann::json& results);

}  // namespace scatterlab
