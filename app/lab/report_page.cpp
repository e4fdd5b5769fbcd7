#include "app/lab/report_page.h"

#include <fstream>

#include "app/json_output.h"
#include "app/lab/embedded_assets.h"
#include "app/lab/html.h"
#include "materials/core/atomic_file.h"
#include "materials/core/temporary_files.h"

namespace scatterlab {

namespace {

using nlohmann::json;
namespace fs = std::filesystem;

std::string badge(bool passed) {
  return html::textElement("span", passed ? "PASS" : "FAIL",
                           {{"class", passed ? "badge pass" : "badge fail"}});
}

std::string summaryTable(const std::vector<MaterialReport>& materials) {
  std::string head;
  for (const char* column : {"material", "kind", "verdict", "checks", "key numbers"})
    head += html::textElement("th", column);
  std::string body;
  for (const MaterialReport& m : materials) {
    std::string numbers;
    for (const auto& [label, value] : m.keyNumbers)
      numbers += html::element(
          "div", html::textElement("span", label, {{"class", "key"}}) + " " + html::escape(value));
    body += html::element("tr",
                          html::element("td", html::textElement("a", m.name, {{"href", "#" + m.folder}})) +
                              html::textElement("td", m.kind) +
                              html::element("td", badge(m.passed), {{"class", "verdict-cell"}}) +
                              html::textElement("td", m.verdict) +
                              html::element("td", numbers, {{"class", "key-numbers"}}),
                          {{"class", m.passed ? "" : "failed"}});
  }
  return html::element("table",
                       html::element("thead", html::element("tr", head)) + html::element("tbody", body),
                       {{"class", "summary"}});
}

std::string materialHtml(const MaterialReport& m) {
  std::string sections;
  for (const ReportSection& s : m.sections)
    sections += html::element("section", html::textElement("h3", s.title) + s.html,
                              {{"id", m.folder + "-" + s.id}, {"class", "part part-" + s.id}});
  std::string toc;
  for (const ReportSection& s : m.sections)
    toc += html::element("li", html::textElement("a", s.title, {{"href", "#" + m.folder + "-" + s.id}}));
  const std::string header =
      html::element("h2", html::escape(m.name) + " " + badge(m.passed)) +
      html::textElement("p", m.about, {{"class", "about"}}) +
      html::element(
          "p",
          html::textElement("a", "Open it in the explorer",
                            {{"href", std::string(LabExplorerFolder) + "/index.html#" + m.folder},
                             {"class", "explorer-link"}}) +
              ": its lobe, f cos, albedo and samples live, computed by the same code in the browser",
          {{"class", "small"}}) +
      html::element("details",
                    html::textElement("summary", "material description (every default filled in)") +
                        html::textElement("pre", jsonText(m.description))) +
      html::element("ul", toc, {{"class", "toc"}});
  return html::element("article", header + sections,
                       {{"id", m.folder}, {"class", m.passed ? "material passed" : "material failed"}});
}

std::string timingsTable(const json& timings) {
  std::string head;
  for (const char* column : {"phase", "material", "wall (s)", "cpu (s)"})
    head += html::textElement("th", column);
  std::string body;
  for (const json& t : timings.value("phases", json::array()))
    body += html::element(
        "tr", html::textElement("td", t.value("phase", "")) +
                  html::textElement("td", t.value("material", "")) +
                  html::textElement("td", html::number(t.value("wall_seconds", 0.0), 3), {{"class", "num"}}) +
                  html::textElement("td", html::number(t.value("cpu_seconds", 0.0), 3), {{"class", "num"}}));
  for (const json& t : timings.value("totals", json::array()))
    body += html::element(
        "tr",
        html::textElement("td", t.value("phase", "")) + html::textElement("td", "all materials") +
            html::textElement("td", html::number(t.value("wall_seconds", 0.0), 3), {{"class", "num"}}) +
            html::textElement("td", html::number(t.value("cpu_seconds", 0.0), 3), {{"class", "num"}}),
        {{"class", "total"}});
  return html::element("table",
                       html::element("thead", html::element("tr", head)) + html::element("tbody", body),
                       {{"class", "rows timings"}});
}

json chartsJson(const std::vector<MaterialReport>& materials) {
  json charts = json::array();
  for (const MaterialReport& m : materials)
    for (const ReportSection& s : m.sections)
      for (const Chart& chart : s.charts) charts.push_back(chart.toJson());
  return charts;
}

json materialDataJson(const MaterialReport& m) {
  json sections = json::object();
  for (const ReportSection& s : m.sections) {
    json charts = json::array();
    for (const Chart& chart : s.charts) charts.push_back(chart.toJson());
    sections[s.id] = {{"title", s.title}, {"data", s.data}, {"charts", charts}};
  }
  return {{"name", m.name},     {"kind", m.kind},       {"about", m.about},    {"material", m.description},
          {"passed", m.passed}, {"verdict", m.verdict}, {"sections", sections}};
}

}  // namespace

std::string reportHtml(const ReportRun& run, const std::vector<MaterialReport>& materials) {
  bool allPassed = true;
  for (const MaterialReport& m : materials) allPassed = allPassed && m.passed;
  std::string body =
      html::element("header",
                    html::textElement("h1", run.title) +
                        html::element("p",
                                      badge(allPassed) + " " +
                                          html::escape(std::to_string(materials.size()) + " materials, " +
                                                       run.mode + " mode, made " + run.createdAt) +
                                          html::element("br", "") + html::textElement("code", run.command),
                                      {{"class", "meta"}})) +
      html::element("nav", html::textElement("h2", "Summary") + summaryTable(materials), {{"id", "summary"}});
  for (const MaterialReport& m : materials) body += materialHtml(m);
  body += html::element(
      "section",
      html::textElement("h2", "What each phase cost") +
          html::textElement("p", "Wall and CPU time of every phase on this machine (also in report.json).",
                            {{"class", "small"}}) +
          timingsTable(run.timings),
      {{"id", "timings"}});
  body +=
      html::element("footer", "Charts drawn by " +
                                  html::textElement("a", "Chart.js " + std::string(chartJsVersion()),
                                                    {{"href", "assets/chart.js-LICENSE.md"}}) +
                                  " (MIT licence, copied beside it). The numbers behind every chart are in "
                                  "each material's data.json and in report.json.");
  const std::string head =
      html::voidElement("meta", {{"charset", "utf-8"}}) +
      html::voidElement("meta", {{"name", "viewport"}, {"content", "width=device-width, initial-scale=1"}}) +
      html::textElement("title", run.title) +
      html::voidElement("link", {{"rel", "stylesheet"}, {"href", "assets/report.css"}}) +
      html::element("script", "", {{"src", "assets/chart.umd.min.js"}});
  const std::string data = html::element("script", html::jsonForScript(jsonText(chartsJson(materials), -1)),
                                         {{"id", "chart-data"}, {"type", "application/json"}});
  return "<!doctype html>\n" +
         html::element(
             "html",
             html::element("head", head) +
                 html::element("body",
                               body + data + html::element("script", "", {{"src", "assets/report.js"}})),
             {{"lang", "en"}}) +
         "\n";
}

void writeReport(const fs::path& dir, const ReportRun& run, const std::vector<MaterialReport>& materials) {
  createDirectoriesUninterrupted(dir / "assets");
  constexpr std::string_view ReportAsset = "report/";
  for (const EmbeddedAsset& asset : embeddedAssets())
    if (asset.name.substr(0, ReportAsset.size()) == ReportAsset)
      writeTextFileAtomically(dir / "assets" / std::string(asset.name.substr(ReportAsset.size())),
                              asset.text());
  json summary = json::array();
  bool allPassed = true;
  for (const MaterialReport& m : materials) {
    createDirectoriesUninterrupted(dir / m.folder);
    writeTextFileAtomically(dir / m.folder / "data.json", jsonText(materialDataJson(m), 1) + "\n");
    json numbers = json::object();
    for (const auto& [label, value] : m.keyNumbers) numbers[label] = value;
    summary.push_back({{"name", m.name},
                       {"kind", m.kind},
                       {"passed", m.passed},
                       {"verdict", m.verdict},
                       {"key_numbers", numbers},
                       {"folder", m.folder},
                       {"data", m.folder + "/data.json"}});
    allPassed = allPassed && m.passed;
  }
  writeTextFileAtomically(dir / "index.html", reportHtml(run, materials));
  const json report{{"generator", ReportGenerator}, {"mode", run.mode},       {"created_at", run.createdAt},
                    {"command", run.command},       {"passed", allPassed},    {"settings", run.settings},
                    {"materials", summary},         {"timings", run.timings}, {"chart_js", chartJsVersion()}};
  writeTextFileAtomically(dir / ReportMarkerFile, jsonText(report, 1) + "\n");
}

}  // namespace scatterlab
