#include "app/lab/check_section.h"

#include <algorithm>
#include <cctype>
#include <map>

#include "app/check_command.h"
#include "app/lab/html.h"
#include "materials/core/bounded_file.h"
#include "materials/core/json_text.h"
#include "materials/core/temporary_files.h"
#include "materials/registry/spec_validation.h"
#include "validation/bsdf_check.h"
#include "validation/subsurface_check.h"

namespace scatterlab {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// "a10b" < "a9b" is wrong for angles: compare runs of digits by value.
bool naturalLess(const std::string& a, const std::string& b) {
  size_t i = 0, j = 0;
  while (i < a.size() && j < b.size()) {
    if (std::isdigit((unsigned char)a[i]) && std::isdigit((unsigned char)b[j])) {
      size_t iEnd = i, jEnd = j;
      while (iEnd < a.size() && std::isdigit((unsigned char)a[iEnd])) ++iEnd;
      while (jEnd < b.size() && std::isdigit((unsigned char)b[jEnd])) ++jEnd;
      const unsigned long long x = std::stoull(a.substr(i, std::min<size_t>(iEnd - i, 18)));
      const unsigned long long y = std::stoull(b.substr(j, std::min<size_t>(jEnd - j, 18)));
      if (x != y) return x < y;
      i = iEnd;
      j = jEnd;
    } else {
      if (a[i] != b[j]) return a[i] < b[j];
      ++i;
      ++j;
    }
  }
  return a.size() - i < b.size() - j;
}

struct MapSet {
  std::string stem;
  std::string layout;  // from STEM_tables.json
  bool consistency = false;
};

// Every chi-square test's maps in `dir` (STEM_observed.png and its companions), in natural order.
std::vector<MapSet> findMaps(const fs::path& dir) {
  std::vector<MapSet> maps;
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(dir, error)) {
    const std::string name = entry.path().filename().string();
    const std::string suffix = "_observed.png";
    if (name.size() <= suffix.size() || name.compare(name.size() - suffix.size(), suffix.size(), suffix) != 0)
      continue;
    MapSet set;
    set.stem = name.substr(0, name.size() - suffix.size());
    set.consistency = fs::exists(dir / (set.stem + "_consistency.png"));
    // Written by this run; read with the limits of every JSON input all the same. Its layout
    // only labels the maps, so an unreadable one leaves the label empty.
    json parsed;
    try {
      const fs::path tables = dir / (set.stem + "_tables.json");
      parsed = parseJsonText(readFileBounded(tables, MaxJsonFileBytes, "chi-square tables"), tables.string());
    } catch (const std::exception&) {}
    if (parsed.is_object()) set.layout = parsed.value("layout", std::string());
    maps.push_back(std::move(set));
  }
  std::sort(maps.begin(), maps.end(),
            [](const MapSet& a, const MapSet& b) { return naturalLess(a.stem, b.stem); });
  return maps;
}

std::string verdictCell(bool passed) {
  return html::textElement("td", passed ? "PASS" : "FAIL",
                           {{"class", passed ? "verdict pass" : "verdict fail"}});
}

std::string rowsTable(const CheckReport& report, bool controls) {
  std::string head;
  for (const char* column :
       {"test", "wi (deg)", "statistic", "dof", "p-value", "threshold", "verdict", "note"})
    head += html::textElement("th", column);
  std::string body;
  for (const CheckRow& row : report.rows) {
    std::string cells =
        html::textElement("td", row.test) +
        html::textElement("td", row.wiThetaDeg ? html::number(*row.wiThetaDeg) : "-", {{"class", "num"}}) +
        html::textElement("td", html::number(row.statistic), {{"class", "num"}}) +
        html::textElement("td", row.dof ? std::to_string(*row.dof) : "-", {{"class", "num"}}) +
        html::textElement("td", row.pValue ? html::number(*row.pValue) : "-", {{"class", "num"}}) +
        html::textElement("td", html::number(row.threshold), {{"class", "num"}}) + verdictCell(row.passed) +
        html::textElement("td", row.note, {{"class", "note"}});
    body += html::element("tr", cells, {{"class", row.passed ? "" : "failed"}});
  }
  return html::element("table",
                       html::element("thead", html::element("tr", head)) + html::element("tbody", body),
                       {{"class", controls ? "rows controls" : "rows"}});
}

std::string mapFigure(const std::string& src, const std::string& caption) {
  return html::element(
      "figure",
      html::voidElement("img", {{"src", src}, {"alt", caption}}) + html::textElement("figcaption", caption),
      {{"class", "map"}});
}

std::string mapsHtml(const LabMaterial& material, const fs::path& checkDir, bool open) {
  const std::vector<MapSet> maps = findMaps(checkDir);
  if (maps.empty()) return "";
  std::string body;
  for (const MapSet& set : maps) {
    const std::string base = material.folder + "/check/" + set.stem;
    std::string figures = mapFigure(base + "_observed.png", "observed") +
                          mapFigure(base + "_expected.png", "expected") +
                          mapFigure(base + "_residual.png", "residual (O - E) / sqrt(E)");
    if (set.consistency) figures += mapFigure(base + "_consistency.png", "consistency error");
    body += html::element(
        "div",
        html::textElement("h4", set.stem) + html::element("div", figures, {{"class", "maps"}}) +
            (set.layout.empty() ? "" : html::textElement("p", "cells: " + set.layout, {{"class", "small"}})),
        {{"class", "map-set"}});
  }
  const std::string summary =
      "Chi-square maps: " + std::to_string(maps.size()) +
      " tests (observed and expected counts share a viridis scale; residuals blue below, red "
      "above the expectation, clamped at 5 sigma; magenta: a cell that must be empty but is not)";
  return html::element("details", html::textElement("summary", summary) + body,
                       open ? html::Attributes{{"open", "open"}} : html::Attributes{});
}

}  // namespace

CheckOutcome runLabChecks(const LabMaterial& material, const LabSettings& settings,
                          const fs::path& materialDir, const ProgressCallback& progress) {
  BsdfCheckOptions kit = settings.kit;
  kit.imageDir = materialDir / "check";
  kit.chiSquareTestCount = 0;  // this material's tests only (see the header)
  createDirectoriesUninterrupted(*kit.imageDir);
  CheckOutcome outcome;
  if (material.subsurface) {
    const SubsurfaceCheckOptions options = subsurfaceCheckOptions(kit);
    outcome.report = runSubsurfaceChecks(material.subsurface->bssrdf(), material.name, options, progress);
    if (settings.negativeControls)
      outcome.controls =
          runSubsurfaceNegativeControls(*material.subsurface->profile, material.name, options, progress);
    return outcome;
  }
  outcome.report = runBsdfChecks(*material.bsdf, material.name, kit, progress);
  if (settings.negativeControls) {
    // Measured materials have no lobe width, so no roughness-mismatch control.
    const std::unique_ptr<BsdfModel> altered =
        material.validated ? makeRoughnessMismatchSampler(*material.validated) : nullptr;
    outcome.controls = runNegativeControls(*material.bsdf, altered.get(), material.name, kit, progress);
  }
  return outcome;
}

std::string verdictText(const CheckOutcome& outcome) {
  size_t total = 0, failed = 0;
  for (const CheckReport* report : {&outcome.report, &outcome.controls})
    for (const CheckRow& row : report->rows) {
      ++total;
      failed += row.passed ? 0 : 1;
    }
  return failed == 0 ? std::to_string(total) + " of " + std::to_string(total) + " checks pass"
                     : std::to_string(failed) + " of " + std::to_string(total) + " checks fail";
}

ReportSection checkSection(const LabMaterial& material, const CheckOutcome& outcome,
                           const fs::path& materialDir) {
  ReportSection section;
  section.id = "check";
  section.title = "Verdict of the statistical kit";
  const bool passed = outcome.passed();
  std::string html = html::element("p", html::textElement("span", passed ? "PASS" : "FAIL",
                                                          {{"class", passed ? "badge pass" : "badge fail"}}) +
                                            " " + html::escape(verdictText(outcome)));
  if (!passed) {
    CheckReport failing;
    for (const CheckReport* report : {&outcome.report, &outcome.controls})
      for (const CheckRow& row : report->rows)
        if (!row.passed) failing.rows.push_back(row);
    html += html::element("div", html::textElement("h4", "What failed") + rowsTable(failing, false),
                          {{"class", "failures"}});
  }
  html += rowsTable(outcome.report, false);
  if (!outcome.controls.rows.empty())
    html += html::textElement("h4",
                              "Negative controls: deliberately broken samplers, which the kit must reject "
                              "(a row passes when its chi-square test rejects)") +
            rowsTable(outcome.controls, true);
  html += mapsHtml(material, materialDir / "check", !passed);
  section.html = std::move(html);
  section.data = {{"passed", passed}, {"report", toJson(outcome.report)}};
  if (!outcome.controls.rows.empty()) section.data["negative_controls"] = toJson(outcome.controls);
  return section;
}

}  // namespace scatterlab
