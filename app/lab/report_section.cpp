#include "app/lab/report_section.h"

#include "app/lab/html.h"

namespace scatterlab {

std::string chartFigure(const Chart& chart) {
  return html::element(
      "figure",
      html::element("div", html::voidElement("canvas", {{"id", chart.id}}), {{"class", "canvas-box"}}),
      {{"class", chart.kind == ChartKind::Polar ? "chart polar" : "chart"}});
}

}  // namespace scatterlab
