// The pieces the report is written with: HTML escaping, chart data, embedded assets, the
// phase timer and the page itself.
#include <gtest/gtest.h>

#include <cmath>
#include <regex>

#include <nlohmann/json.hpp>

#include "app/lab/chart.h"
#include "app/lab/embedded_assets.h"
#include "app/lab/html.h"
#include "app/lab/phase_timer.h"
#include "app/lab/report_page.h"

namespace scatterlab {
namespace lab_report_pieces_test {

using nlohmann::json;

TEST(Html, EscapesEveryMarkupCharacter) {
  EXPECT_EQ(html::escape(R"(<a href="x">&'</a>)"), "&lt;a href=&quot;x&quot;&gt;&amp;&#39;&lt;/a&gt;");
  EXPECT_EQ(html::textElement("td", "a<b", {{"class", "x\"y"}}), "<td class=\"x&quot;y\">a&lt;b</td>");
}

TEST(Html, JsonInAScriptElementCannotEndIt) {
  const std::string text = json{{"name", "</script><script>alert(1)</script><!--"}}.dump();
  const std::string safe = html::jsonForScript(text);
  EXPECT_EQ(safe.find('<'), std::string::npos) << safe;
  EXPECT_EQ(json::parse(safe), json::parse(text));  // \u003c is the same string to a JSON reader
}

TEST(Html, NumbersAreShortAndNeverNan) {
  EXPECT_EQ(html::number(0.031234567, 3), "0.0312");
  EXPECT_EQ(html::number(1.5e-5), "1.5e-05");
  EXPECT_EQ(html::number(NAN), "-");
  EXPECT_EQ(html::number(INFINITY), "inf");
}

TEST(Chart, LeavesOutPointsItCannotDraw) {
  Chart chart;
  chart.id = "c";
  chart.logY = true;
  chart.series.push_back({"data",
                          "#000000",
                          SeriesStyle::Points,
                          {{1, 2}, {2, NAN}, {3, 0}, {4, -1}, {INFINITY, 1}, {5, 3}},
                          {},
                          {}});
  chart.series.push_back({"guide", "#999999", SeriesStyle::Guide, {{0, 1}, {5, 1}}, {}, {}});
  EXPECT_EQ(chart.dataPointCount(), 2u);  // guides are not data
  const json j = chart.toJson();
  EXPECT_EQ(j["series"][0]["points"], json::parse("[[1.0, 2.0], [5.0, 3.0]]"));
  EXPECT_EQ(j["kind"], "line");
  EXPECT_TRUE(j["x_min"].is_null());
  EXPECT_EQ(j.dump().find("NaN"), std::string::npos);
}

TEST(Chart, KeepsBandsAndAxisLimits) {
  Chart chart;
  chart.id = "p";
  chart.kind = ChartKind::Polar;
  chart.xMin = -1;
  chart.yMax = 1;
  chart.series.push_back({"walk", "#ff0000", SeriesStyle::Points, {{1, 1}}, {{1, 0.9}}, {{1, 1.1}}});
  const json j = chart.toJson();
  EXPECT_EQ(j["kind"], "polar");
  EXPECT_EQ(j["x_min"], -1.0);
  EXPECT_EQ(j["series"][0]["band"]["lower"], json::parse("[[1.0, 0.9]]"));
  EXPECT_EQ(j["series"][0]["band"]["upper"], json::parse("[[1.0, 1.1]]"));
}

// A fit that falls to 1e-247 where the data ends must not set the log axis: the axis spans
// the data (1e-3 .. 10, widened by LogAxisMargin), and the curve is kept, to be clipped.
TEST(Chart, LogAxisSpansTheDataNotAModelCurveBelowIt) {
  Chart chart;
  chart.id = "fit";
  chart.logY = true;
  chart.series.push_back({"data", "#000000", SeriesStyle::Points, {{0, 1e-3}, {1, 10}, {2, 0.5}}, {}, {}});
  chart.series.push_back(
      {"fit", "#ff0000", SeriesStyle::Line, {{0, 2e-3}, {1, 8}, {2, 1e-247}}, {}, {}, /*setsRange=*/false});
  const json j = chart.toJson();
  EXPECT_DOUBLE_EQ(j["y_min"].get<double>(), 1e-3 / LogAxisMargin);
  EXPECT_DOUBLE_EQ(j["y_max"].get<double>(), 10 * LogAxisMargin);
  EXPECT_TRUE(j["x_min"].is_null());  // a linear axis keeps Chart.js's own range
  EXPECT_EQ(j["series"][1]["points"].size(), 3u);
  // An explicit limit wins over the data's.
  chart.yMin = 1e-6;
  EXPECT_DOUBLE_EQ(chart.toJson()["y_min"].get<double>(), 1e-6);
  // The negative control: were the fit allowed to set the range, the axis would reach 1e-247.
  chart.yMin.reset();
  chart.series[1].setsRange = true;
  EXPECT_LT(chart.toJson()["y_min"].get<double>(), 1e-246);
}

TEST(EmbeddedAssets, HoldChartJsItsLicenceAndTheReportFiles) {
  const std::string_view chart = embeddedAsset("report/chart.umd.min.js").text();
  EXPECT_NE(chart.find("Chart.js v" + std::string(chartJsVersion())), std::string_view::npos);
  EXPECT_NE(embeddedAsset("report/chart.js-LICENSE.md").text().find("MIT"), std::string_view::npos);
  EXPECT_NE(embeddedAsset("report/report.js").text().find("scatterlabCharts"), std::string_view::npos);
  EXPECT_NE(embeddedAsset("report/report.css").text().find(".badge.fail"), std::string_view::npos);
  EXPECT_THROW(embeddedAsset("missing.js"), std::logic_error);
}

TEST(PhaseTimer, RecordsEveryPhaseAndTotals) {
  PhaseTimer timer(/*log=*/false);
  const int value = timer.time("check", "a", [] { return 7; });
  EXPECT_EQ(value, 7);
  timer.time("check", "b", [] {});
  timer.time("plots", "a", [] {});
  ASSERT_EQ(timer.timings().size(), 3u);
  EXPECT_EQ(timer.phases(), (std::vector<std::string>{"check", "plots"}));
  const PhaseTiming total = timer.total("check");
  EXPECT_DOUBLE_EQ(total.wallSeconds, timer.timings()[0].wallSeconds + timer.timings()[1].wallSeconds);
  const json j = timer.toJson();
  EXPECT_EQ(j["phases"].size(), 3u);
  EXPECT_EQ(j["totals"].size(), 2u);
}

MaterialReport exampleReport(const std::string& name, bool passed) {
  MaterialReport m;
  m.name = name;
  m.folder = name;
  m.kind = "analytic";
  m.passed = passed;
  m.verdict = passed ? "3 of 3 checks pass" : "1 of 3 checks fail";
  m.keyNumbers = {{"albedo", "0.5 <b>"}};
  ReportSection section;
  section.id = "plots";
  section.title = "Plots";
  Chart chart;
  chart.id = name + "-chart";
  chart.series.push_back({"s", "#000000", SeriesStyle::Line, {{0, 0}, {1, 1}}, {}, {}});
  section.charts.push_back(chart);
  section.html = chartFigure(chart);
  m.sections.push_back(section);
  return m;
}

TEST(ReportPage, SummaryRowPerMaterialAndFailuresMarked) {
  ReportRun run;
  run.mode = "quick";
  const std::string page = reportHtml(run, {exampleReport("good", true), exampleReport("bad", false)});
  EXPECT_NE(page.find("<tr class=\"failed\"><td><a href=\"#bad\">bad</a>"), std::string::npos);
  EXPECT_NE(page.find("<article id=\"bad\" class=\"material failed\">"), std::string::npos);
  EXPECT_NE(page.find("<article id=\"good\" class=\"material passed\">"), std::string::npos);
  EXPECT_NE(page.find("0.5 &lt;b&gt;"), std::string::npos);  // key numbers are text
  // The chart data holds each chart, and its canvas is in the page.
  const std::smatch match = [&] {
    std::smatch m;
    std::regex_search(page, m,
                      std::regex(R"(<script id="chart-data" type="application/json">([^<]*)</script>)"));
    return m;
  }();
  ASSERT_EQ(match.size(), 2u);
  const json charts = json::parse(match[1].str());
  ASSERT_EQ(charts.size(), 2u);
  for (const json& chart : charts)
    EXPECT_NE(page.find("<canvas id=\"" + chart["id"].get<std::string>() + "\">"), std::string::npos);
  // Chart.js loads before the page's own script, both from assets/.
  EXPECT_LT(page.find("assets/chart.umd.min.js"), page.find("assets/report.js"));
}

}  // namespace lab_report_pieces_test
}  // namespace scatterlab
