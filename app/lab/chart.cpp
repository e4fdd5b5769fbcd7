#include "app/lab/chart.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace scatterlab {

namespace {

using nlohmann::json;

const char* kindName(ChartKind kind) { return kind == ChartKind::Polar ? "polar" : "line"; }

const char* styleName(SeriesStyle style) {
  switch (style) {
    case SeriesStyle::Line: return "line";
    case SeriesStyle::Dashed: return "dashed";
    case SeriesStyle::Points: return "points";
    case SeriesStyle::Guide: return "guide";
  }
  return "line";
}

bool drawable(const Chart& chart, const Vec2d& p) {
  return std::isfinite(p.x) && std::isfinite(p.y) && (!chart.logX || p.x > 0) && (!chart.logY || p.y > 0);
}

json pointsJson(const Chart& chart, const std::vector<Vec2d>& points) {
  json out = json::array();
  for (const Vec2d& p : points)
    if (drawable(chart, p)) out.push_back({p.x, p.y});
  return out;
}

json optionalJson(const std::optional<double>& value) {
  return value && std::isfinite(*value) ? json(*value) : json();
}

}  // namespace

size_t Chart::dataPointCount() const {
  size_t count = 0;
  for (const ChartSeries& s : series)
    if (s.style != SeriesStyle::Guide)
      for (const Vec2d& p : s.points) count += drawable(*this, p) ? 1 : 0;
  return count;
}

std::pair<std::optional<double>, std::optional<double>> Chart::axisRange(int axis) const {
  const bool logAxis = axis == 0 ? logX : logY;
  std::optional<double> lo = axis == 0 ? xMin : yMin, hi = axis == 0 ? xMax : yMax;
  if (!logAxis || (lo && hi)) return {lo, hi};
  double dataLo = INFINITY, dataHi = -INFINITY;
  for (const ChartSeries& s : series) {
    if (s.style == SeriesStyle::Guide || !s.setsRange) continue;
    for (const std::vector<Vec2d>* points : {&s.points, &s.bandLower, &s.bandUpper})
      for (const Vec2d& p : *points)
        if (drawable(*this, p)) {
          dataLo = std::min(dataLo, p[axis]);
          dataHi = std::max(dataHi, p[axis]);
        }
  }
  if (dataLo > dataHi) return {lo, hi};  // no data: Chart.js finds its own range
  if (!lo) lo = dataLo / LogAxisMargin;
  if (!hi) hi = dataHi * LogAxisMargin;
  return {lo, hi};
}

json Chart::toJson() const {
  json seriesJson = json::array();
  for (const ChartSeries& s : series) {
    json entry{{"label", s.label},
               {"color", s.color},
               {"style", styleName(s.style)},
               {"points", pointsJson(*this, s.points)}};
    if (!s.bandLower.empty())
      entry["band"] = {{"lower", pointsJson(*this, s.bandLower)}, {"upper", pointsJson(*this, s.bandUpper)}};
    seriesJson.push_back(std::move(entry));
  }
  const auto [x0, x1] = axisRange(0);
  const auto [y0, y1] = axisRange(1);
  return {{"id", id},
          {"kind", kindName(kind)},
          {"title", title},
          {"x_label", xLabel},
          {"y_label", yLabel},
          {"log_x", logX},
          {"log_y", logY},
          {"x_min", optionalJson(x0)},
          {"x_max", optionalJson(x1)},
          {"y_min", optionalJson(y0)},
          {"y_max", optionalJson(y1)},
          {"series", std::move(seriesJson)}};
}

const char* channelColor(int channel) {
  static constexpr std::array<const char*, 3> colors{"#d62728", "#2ca02c", "#1f77b4"};
  return colors[size_t(channel) % 3];
}

const char* paletteColor(size_t index) {
  // Matplotlib's tab10 without its red, green and blue, which stand for channels, plus black.
  static constexpr std::array<const char*, 8> palette{"#ff7f0e", "#9467bd", "#17becf", "#8c564b",
                                                      "#e377c2", "#bcbd22", "#7f7f7f", "#111111"};
  return palette[index % palette.size()];
}

}  // namespace scatterlab
