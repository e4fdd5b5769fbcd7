// Writes a finished report into a directory: index.html (summary table, one section per
// material, the timings), assets/ (Chart.js with its licence, report.js, report.css, copied
// from the executable), FOLDER/data.json per material (its sections' numbers and charts), and
// report.json (the whole run: settings, verdicts, key numbers, timings), which also marks the
// directory as a lab report (staged_directory.h).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/lab/report_section.h"

namespace scatterlab {

inline constexpr const char* ReportMarkerFile = "report.json";
inline constexpr const char* ReportGenerator = "scatterlab lab";
// The explorer preloaded with the report's materials (app/explorer/explorer_page.h): each
// material's section links to LabExplorerFolder/index.html#FOLDER.
inline constexpr const char* LabExplorerFolder = "explorer";

struct ReportRun {
  std::string title = "scatterlab lab report";
  std::string mode;       // "quick" or "full"
  std::string createdAt;  // ISO 8601, UTC
  nlohmann::json settings = nlohmann::json::object();
  nlohmann::json timings = nlohmann::json::object();  // PhaseTimer::toJson()
  std::string command;                                // the command line
};

void writeReport(const std::filesystem::path& dir, const ReportRun& run,
                 const std::vector<MaterialReport>& materials);

// The page alone (for tests).
std::string reportHtml(const ReportRun& run, const std::vector<MaterialReport>& materials);

}  // namespace scatterlab
