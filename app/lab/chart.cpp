#include "app/lab/chart.h"

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
  return {{"id", id},
          {"kind", kindName(kind)},
          {"title", title},
          {"x_label", xLabel},
          {"y_label", yLabel},
          {"log_x", logX},
          {"log_y", logY},
          {"x_min", optionalJson(xMin)},
          {"x_max", optionalJson(xMax)},
          {"y_min", optionalJson(yMin)},
          {"y_max", optionalJson(yMax)},
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
