// A chart of the report as data: what report.js hands to Chart.js, and what each material's
// data.json keeps so that the chart can be re-plotted. No drawing happens in C++.
//
// Kinds: `line` (x-y curves and points, optional log axes) and `polar` (x-y with equal units
// on both axes, for lobes drawn in the plane of incidence). A series may carry a band (a
// lower and an upper curve, e.g. +- one standard error) that report.js fills.
//
// Points that cannot be drawn are left out when the chart is written: non-finite
// coordinates, and values <= 0 on a log axis. JSON therefore never holds NaN.
//
// A log axis without an explicit range spans the data: the drawable points of the series that
// set the range (not guides, and not a model's curve drawn over the data, which may fall to
// 1e-247 where the data ends and would flatten the data into one line), widened by
// LogAxisMargin at both ends. A curve beyond that range is clipped by the chart.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "materials/core/math.h"

namespace scatterlab {

enum class ChartKind { Line, Polar };
enum class SeriesStyle {
  Line,    // solid line, no markers
  Dashed,  // dashed line, no markers
  Points,  // markers only
  Guide,   // thin grey line, not in the legend (axes of a polar plot, reference circles)
};

struct ChartSeries {
  std::string label;
  std::string color;  // CSS colour
  SeriesStyle style = SeriesStyle::Line;
  std::vector<Vec2d> points;
  std::vector<Vec2d> bandLower, bandUpper;  // empty: no band
  // False for a model's curve over the data (a fit): it does not set a log axis's range.
  bool setsRange = true;
};

// The factor by which a log axis's automatic range extends beyond the data at either end.
inline constexpr double LogAxisMargin = 1.5;

struct Chart {
  std::string id;  // unique in the page (the canvas's id)
  std::string title, xLabel, yLabel;
  ChartKind kind = ChartKind::Line;
  bool logX = false, logY = false;
  std::optional<double> xMin, xMax, yMin, yMax;
  std::vector<ChartSeries> series;

  // Drawable points of every series that is not a guide.
  size_t dataPointCount() const;
  // The range of axis 0 (x) or 1 (y) as written: the explicit one where set; for a log axis
  // without one, the data's (see above); otherwise open (nullopt) ends.
  std::pair<std::optional<double>, std::optional<double>> axisRange(int axis) const;
  nlohmann::json toJson() const;
};

// Colours for the red, green and blue channels of a quantity, and a palette for curves that
// are told apart by position in a list (incident angles, fits).
const char* channelColor(int channel);
const char* paletteColor(size_t index);

}  // namespace scatterlab
