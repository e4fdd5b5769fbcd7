#include "app/sweep/sweep_merge.h"

#include <algorithm>
#include <fstream>
#include <sstream>

#include "app/exit_code.h"
#include "app/lab/html.h"
#include "app/sweep/sweep_runner.h"
#include "materials/core/bounded_file.h"
#include "materials/core/json_text.h"

namespace scatterlab {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

json readJsonFile(const fs::path& path, const std::string& what) {
  try {
    return parseJsonText(readFileBounded(path, MaxJsonFileBytes, "sweep file"), path.string());
  } catch (const std::runtime_error& error) {  // InputFileError, JsonTextError
    throw InputError(what + ": " + error.what());
  }
}

std::string label(const json& material) {
  return material.is_string() ? material.get<std::string>() : material.dump();
}

std::string cell(const json& value) {
  if (value.is_null()) return "";
  if (value.is_string()) return value.get<std::string>();
  return value.dump();
}

// The command's headline numbers, the same columns for every task of a sweep.
std::vector<std::string> headlineColumns(const std::string& command) {
  if (command == "check") return {"passed", "rows", "failed_rows"};
  if (command == "fit") return {"verdict", "max_relative_error", "relative_error", "cost", "fitted_material"};
  if (command == "render") return {"sphere_mean_rgb", "non_finite_samples", "exr", "png"};
  return {"total_reflectance", "walk_total_reflectance"};  // profile
}

int failedRows(const json& report) {
  int failed = 0;
  for (const json& row : report.value("report", json::object()).value("rows", json::array()))
    if (!row.value("passed", true)) ++failed;
  return failed;
}

double maxRelativeError(const json& fit) {
  double worst = 0;
  for (const json& e : fit.value("relative_error", json::array()))
    if (e.is_number()) worst = std::max(worst, e.get<double>());
  return worst;
}

std::vector<json> headline(const std::string& command, const json& result, const fs::path& taskPath) {
  if (command == "check") {
    const json rows = result.value("report", json::object()).value("rows", json::array());
    return {result.value("passed", false), rows.size(), failedRows(result)};
  }
  if (command == "fit") {
    const json fit = result.value("fit", json::object());
    return {result.value("verdict", ""), maxRelativeError(fit), fit.value("relative_error", json()),
            fit.value("cost", json()),
            result.contains("material") ? json(result["material"].dump()) : json()};
  }
  if (command == "render") {
    const json render =
        result.value("renders", json::array()).empty() ? json::object() : result["renders"][0];
    return {render.value("sphere", json::object()).value("mean_rgb", json()),
            render.value("non_finite_samples", json()), (taskPath / "render.exr").string(),
            (taskPath / "render.png").string()};
  }
  json total = json::array(), walk = json::array();
  for (const json& channel : result.value("channels", json::array())) {
    total.push_back(channel.value("total_reflectance", json()));
    if (channel.contains("walk")) walk.push_back(channel["walk"].value("total_reflectance", json()));
  }
  return {total, walk.empty() ? json() : walk};
}

std::string csvField(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

std::vector<std::string> varyKeys(const json& results) {
  std::vector<std::string> keys;
  const json vary = results["spec"].value("vary", json::object());
  for (const auto& [key, value] : vary.items()) keys.push_back(key);
  return keys;
}

}  // namespace

SweepMerge mergeSweepDirectories(const std::vector<fs::path>& directories) {
  if (directories.empty()) throw InputError("merge: name at least one sweep directory");
  json manifest;
  for (const fs::path& directory : directories) {
    const fs::path file = directory / "sweep.json";
    if (!fs::is_regular_file(file))
      throw InputError("merge: " + directory.string() + " is not a sweep directory (it has no sweep.json)");
    const json read = readJsonFile(file, "merge");
    if (read.value("generator", "") != "scatterlab sweep" || !read.contains("tasks") ||
        !read["tasks"].is_array())
      throw InputError("merge: " + file.string() + " was not written by scatterlab sweep");
    if (manifest.is_null()) {
      manifest = read;
    } else if (read.value("hash", "") != manifest.value("hash", "")) {
      throw InputError("merge: " + directory.string() + " holds another sweep (hash " +
                       read.value("hash", "") + ") than " + directories.front().string() + " (hash " +
                       manifest.value("hash", "") + "); merge only the shards of one sweep");
    }
  }

  SweepMerge merge;
  json records = json::array(), timings = json::array();
  const std::size_t taskCount = manifest["tasks"].size();
  for (std::size_t index = 0; index < taskCount; ++index) {
    const json& expected = manifest["tasks"][index];
    json found, foundTiming;
    for (const fs::path& directory : directories) {
      const fs::path taskDirectory = sweepTaskDirectory(directory, index);
      if (!fs::is_regular_file(taskDirectory / "task.json")) continue;
      json record = readJsonFile(taskDirectory / "task.json", "merge");
      if (record.value("index", json()) != json(index) || record.value("seed", json()) != expected["seed"])
        throw InputError("merge: " + (taskDirectory / "task.json").string() + " is not task " +
                         std::to_string(index) + " of this sweep");
      const bool ok = record.value("status", "") == "ok";
      // A result beats an error (a shard that failed may have been rerun into another directory).
      if (found.is_null() || (ok && found.value("status", "") != "ok")) {
        record.erase("arguments");
        found = std::move(record);
        foundTiming = fs::is_regular_file(taskDirectory / "timing.json")
                          ? readJsonFile(taskDirectory / "timing.json", "merge")
                          : json::object();
        foundTiming["directory"] = directory.string();
      }
      if (ok) break;
    }
    if (found.is_null()) {
      merge.missing.push_back(index);
      found = expected;
      found["status"] = "missing";
    } else if (found.value("status", "") != "ok") {
      merge.failed.push_back(index);
    }
    if (manifest["command"] == "render" && found.value("status", "") == "ok") {
      const fs::path taskPath = sweepTaskDirectory("", index);
      found["files"] = {(taskPath / "render.exr").string(), (taskPath / "render.png").string()};
    }
    records.push_back(std::move(found));
    if (!foundTiming.is_null()) timings.push_back(std::move(foundTiming));
  }
  merge.results = {{"generator", "scatterlab merge"},
                   {"hash", manifest["hash"]},
                   {"command", manifest["command"]},
                   {"spec", manifest["spec"]},
                   {"task_count", taskCount},
                   {"complete", merge.missing.empty() && merge.failed.empty()},
                   {"missing", merge.missing},
                   {"failed", merge.failed},
                   {"tasks", records}};
  merge.timings = {{"hash", manifest["hash"]}, {"tasks", timings}};
  merge.csv = sweepResultsCsv(merge.results);
  const std::string command = manifest["command"];
  if (command == "check" || command == "fit") merge.html = sweepSummaryHtml(merge.results);
  return merge;
}

std::string sweepResultsCsv(const json& results) {
  const std::string command = results["command"];
  const std::vector<std::string> keys = varyKeys(results);
  const std::vector<std::string> columns = headlineColumns(command);
  std::ostringstream csv;
  csv << "index,status,material";
  for (const std::string& key : keys) csv << "," << csvField(key);
  csv << ",seed";
  for (const std::string& column : columns) csv << "," << column;
  csv << ",error\n";
  for (const json& task : results["tasks"]) {
    const std::size_t index = task["index"];
    csv << index << "," << task.value("status", "") << "," << csvField(label(task["material"]));
    for (const std::string& key : keys) csv << "," << csvField(cell(task["vary"].value(key, json())));
    csv << "," << cell(task["seed"]);
    const bool ok = task.value("status", "") == "ok";
    const std::vector<json> values = ok ? headline(command, task["result"], sweepTaskDirectory("", index))
                                        : std::vector<json>(columns.size());
    for (const json& value : values) csv << "," << csvField(cell(value));
    csv << "," << csvField(task.value("error", "")) << "\n";
  }
  return csv.str();
}

std::string sweepSummaryHtml(const json& results) {
  const std::string command = results["command"];
  const json& tasks = results["tasks"];
  // Tasks are materials x vary combinations, the combination fastest (sweep_spec.h).
  // The row length is where the first combination comes round again.
  std::size_t columns = std::max<std::size_t>(tasks.size(), 1);
  for (std::size_t k = 1; k < tasks.size(); ++k)
    if (tasks[k]["vary"] == tasks[0]["vary"]) {
      columns = k;
      break;
    }
  std::string head = html::element("th", "material");
  for (std::size_t c = 0; c < columns && c < tasks.size(); ++c) {
    std::string name;
    for (const auto& [key, value] : tasks[c]["vary"].items())
      name += (name.empty() ? "" : ", ") + key + " " + cell(value);
    head += html::textElement("th", name.empty() ? command : name);
  }
  std::string body;
  for (std::size_t row = 0; row * columns < tasks.size(); ++row) {
    std::string cells =
        html::element("td", html::element("code", html::escape(label(tasks[row * columns]["material"]))));
    for (std::size_t c = 0; c < columns; ++c) {
      const json& task = tasks[row * columns + c];
      const std::string status = task.value("status", "");
      std::string text, css;
      if (status != "ok") {
        text = status == "missing" ? "missing" : "error: " + task.value("error", "");
        css = "error";
      } else if (command == "check") {
        const int failed = failedRows(task["result"]);
        text = failed == 0 ? "pass" : "fail (" + std::to_string(failed) + " rows)";
        css = failed == 0 ? "pass" : "fail";
      } else {
        const std::string verdict = task["result"].value("verdict", "");
        text = verdict + ", max rel. error " +
               html::number(maxRelativeError(task["result"].value("fit", json::object())), 3);
        css = verdict == "good" ? "pass" : "fail";
      }
      cells += html::textElement("td", text, {{"class", css}, {"title", "task " + cell(task["index"])}});
    }
    body += html::element("tr", cells);
  }
  const std::string summary = std::to_string(results["task_count"].get<std::size_t>()) + " tasks, " +
                              std::to_string(results["missing"].size()) + " missing, " +
                              std::to_string(results["failed"].size()) + " failed; sweep " +
                              results["hash"].get<std::string>();
  const std::string style =
      "body{font:14px system-ui,sans-serif;margin:2em}table{border-collapse:collapse}"
      "td,th{border:1px solid #ccc;padding:4px 8px;text-align:left}"
      ".pass{background:#e3f4e1}.fail{background:#fbe3e0}.error{background:#eee;color:#a00}";
  const std::string title = "scatterlab sweep: " + command;
  return "<!DOCTYPE html>\n" +
         html::element(
             "html",
             html::element("head", html::voidElement("meta", {{"charset", "utf-8"}}) +
                                       html::textElement("title", title) + html::element("style", style)) +
                 html::element("body", html::textElement("h1", title) + html::textElement("p", summary) +
                                           html::element("table", html::element("tr", head) + body)),
             {{"lang", "en"}}) +
         "\n";
}

}  // namespace scatterlab
