// A chart of the report as data: what report.js hands to Chart.js, and what each material's
// data.json keeps so that the chart can be re-plotted. No drawing happens in C++.
//
// Kinds: `line` (x-y curves and points, optional log axes) and `polar` (x-y with equal units
// on both axes, for lobes drawn in the plane of incidence). A series may carry a band (a
// lower and an upper curve, e.g. +- one standard error) that report.js fills.
//
// Points that cannot be drawn are left out when the chart is written: non-finite
// coordinates, and values <= 0 on a log axis. JSON therefore never holds NaN.
#pragma once

#include <optional>
#include <string>
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
};

struct Chart {
  std::string id;  // unique in the page (the canvas's id)
  std::string title, xLabel, yLabel;
  ChartKind kind = ChartKind::Line;
  bool logX = false, logY = false;
  std::optional<double> xMin, xMax, yMin, yMax;
  std::vector<ChartSeries> series;

  // Drawable points of every series that is not a guide.
  size_t dataPointCount() const;
  nlohmann::json toJson() const;
};

// Colours for the red, green and blue channels of a quantity, and a palette for curves that
// are told apart by position in a list (incident angles, fits).
const char* channelColor(int channel);
const char* paletteColor(size_t index);

}  // namespace scatterlab
