// What each part of a material's report produces: its HTML (charts appear in it as canvases
// that report.js fills), the charts' data, and the numbers behind it for data.json.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/lab/chart.h"

namespace scatterlab {

struct ReportSection {
  std::string id;  // "check", "plots", ... (the anchor is FOLDER-ID)
  std::string title;
  std::string html;
  std::vector<Chart> charts;
  nlohmann::json data = nlohmann::json::object();
};

// A chart's place in a section's HTML: a figure with the canvas report.js draws on.
std::string chartFigure(const Chart& chart);

// One material's whole report.
struct MaterialReport {
  std::string name, folder, kind, about;
  nlohmann::json description;
  bool passed = true;
  std::string verdict;  // "16 of 16 checks pass", "2 of 16 checks fail"
  // Label and value pairs (plain text) for the summary table at the top of the page.
  std::vector<std::pair<std::string, std::string>> keyNumbers;
  std::vector<ReportSection> sections;
};

}  // namespace scatterlab
