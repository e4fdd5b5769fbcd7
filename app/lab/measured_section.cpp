#include "app/lab/measured_section.h"

#include "app/lab/html.h"
#include "app/lab/lobe_curves.h"
#include "materials/core/atomic_file.h"
#include "materials/measured/merl_format.h"

namespace scatterlab {

namespace {

using nlohmann::json;

// The slice image's numbers: f per channel for every cell, null where missing.
void writeSliceJson(const std::filesystem::path& path, const MeasuredSlice& slice) {
  json thetaHalf = json::array(), thetaDiff = json::array(), rows = json::array();
  for (int h = 0; h < merl::ThetaHalfCells; ++h) thetaHalf.push_back(thetaHalfCentreDeg(h));
  for (int d = 0; d < merl::ThetaDiffCells; ++d) thetaDiff.push_back(thetaDiffCentreDeg(d));
  for (int h = 0; h < merl::ThetaHalfCells; ++h) {
    json row = json::array();
    for (int d = 0; d < merl::ThetaDiffCells; ++d) {
      const Rgb& f = slice.at(h, d);
      row.push_back(slice.stateAt(h, d) == CellState::Missing ? json() : json{f.x, f.y, f.z});
    }
    rows.push_back(std::move(row));
  }
  const json document{
      {"phi_d_deg", slice.phiDiffDeg},
      {"theta_h_deg", thetaHalf},
      {"theta_d_deg", thetaDiff},
      {"f_rgb", rows},
      {"layout", "f_rgb[theta_h cell][theta_d cell] = [r, g, b] in 1/sr, null where missing"}};
  writeTextFileAtomically(path, document.dump());
}

}  // namespace

std::vector<Vec2d> sliceAlongThetaHalf(const MeasuredSlice& slice, int thetaDiffCell) {
  std::vector<Vec2d> points;
  for (int h = 0; h < merl::ThetaHalfCells; ++h)
    if (slice.stateAt(h, thetaDiffCell) == CellState::Measured)
      points.push_back({thetaHalfCentreDeg(h), rec709Luminance(slice.at(h, thetaDiffCell))});
  return points;
}

ReportSection measuredSection(const LabMaterial& material, const LabSettings& settings,
                              const std::filesystem::path& materialDir) {
  ReportSection section;
  section.id = "measured";
  section.title = "Measured data";
  // A MERL table shows its cells as stored; an RGL file, evaluated at the same cell centres.
  const MeasuredSlice slice = material.table ? sliceAtPhiDiff(*material.table, settings.slicePhiDiffDeg)
                                             : sliceAtPhiDiff(*material.bsdf, settings.slicePhiDiffDeg);
  const std::string cells = material.table ? "table cells" : "the file at MERL cell centres";
  const SliceImageScale scale = writeSliceImage(materialDir / "slice.png", slice);
  writeColourBar(materialDir / "slice_scale.png");

  Chart chart;
  chart.id = material.folder + "-slices";
  chart.title =
      "f along theta_h at phi_d = " + html::degrees(slice.phiDiffDeg) + " (luminance, " + cells + ")";
  chart.xLabel = "theta_h (deg)";
  chart.yLabel = "f (1/sr)";
  chart.logY = true;
  chart.xMin = 0;
  chart.xMax = 90;
  json slicesJson = json::array();
  for (size_t i = 0; i < std::size(SliceThetaDiffDeg); ++i) {
    const int cell = thetaDiffCellAt(SliceThetaDiffDeg[i]);
    const std::vector<Vec2d> points = sliceAlongThetaHalf(slice, cell);
    chart.series.push_back({"theta_d " + html::degrees(thetaDiffCentreDeg(cell)),
                            paletteColor(i),
                            SeriesStyle::Points,
                            points,
                            {},
                            {}});
    json pointsJson = json::array();
    for (const Vec2d& p : points) pointsJson.push_back({p.x, p.y});
    slicesJson.push_back({{"theta_d_deg", thetaDiffCentreDeg(cell)}, {"theta_h_deg_and_f", pointsJson}});
  }
  section.charts.push_back(chart);
  writeSliceJson(materialDir / "slice.json", slice);

  size_t missing = 0;
  for (const CellState state : slice.state) missing += state == CellState::Missing ? 1 : 0;
  const std::string base = material.folder + "/";
  const std::string image = html::element(
      "figure",
      html::voidElement(
          "img", {{"src", base + "slice.png"}, {"alt", "theta_h / theta_d slice"}, {"class", "slice"}}) +
          html::element(
              "figcaption",
              "log<sub>10</sub> f (luminance) at phi_d = " + html::escape(html::degrees(slice.phiDiffDeg)) +
                  ": theta_h cells across (non-linear, the highlight on the left), theta_d down "
                  "from 0 to 90\u00b0" +
                  html::element("div",
                                html::textElement("span", html::number(scale.log10Min, 3)) +
                                    html::voidElement(
                                        "img", {{"src", base + "slice_scale.png"}, {"alt", "colour scale"}}) +
                                    html::textElement("span", html::number(scale.log10Max, 3)),
                                {{"class", "colour-bar"}}) +
                  html::escape(missing ? std::to_string(missing) + " missing cells in this slice, in magenta"
                                       : "no missing cells in this slice")),
      {{"class", "slice-figure"}});
  // What both formats show and record; each adds its own summary and facts below.
  const std::string sliceHtml = html::element("div", image + chartFigure(chart), {{"class", "chart-grid"}});
  const json sliceData = {{"phi_d_cell", slice.phiDiffCell},
                          {"phi_d_deg", slice.phiDiffDeg},
                          {"slice_image", "slice.png"},
                          {"slice_data", "slice.json"},
                          {"slice_log10_range", {scale.log10Min, scale.log10Max}},
                          {"slices_along_theta_h", slicesJson}};
  if (material.rgl) {
    const RglBrdf& rgl = *material.rgl;
    size_t belowHorizon = 0;
    const size_t pairs = rgl.tabulatedPairs(&belowHorizon).size();
    const std::string summary = html::textElement(
        "p",
        "RGL tensor file" + (rgl.description().empty() ? std::string() : " \"" + rgl.description() + "\"") +
            ": " +
            (rgl.isotropic() ? "isotropic"
                             : "anisotropic (reduction " + std::to_string(rgl.reduction()) + ")") +
            ", " +
            (rgl.spectral() ? std::to_string(rgl.wavelengthCount()) + " wavelengths reduced to RGB" : "RGB") +
            ", " + std::to_string(rgl.incidentAzimuths()) + " x " + std::to_string(rgl.incidentElevations()) +
            " incident directions (theta_i " + html::degrees(degrees(rgl.thetaMin())) + " to " +
            html::degrees(degrees(rgl.thetaMax())) + "), vndf " + std::to_string(rgl.vndfRows()) + " x " +
            std::to_string(rgl.vndfColumns()) + ", colour " + std::to_string(rgl.colourRows()) + " x " +
            std::to_string(rgl.colourColumns()) + ": " + std::to_string(pairs) +
            " tabulated direction pairs above the horizon (" + std::to_string(belowHorizon) +
            " more below it). The image and the curves evaluate the file at the MERL cell centres "
            "(materials/measured/rgl_brdf.h); nothing is missing.",
        {{"class", "small"}});
    section.html = summary + sliceHtml;
    section.data = sliceData;
    section.data.update(json{{"format", "rgl"},
                             {"description", rgl.description()},
                             {"isotropic", rgl.isotropic()},
                             {"spectral", rgl.spectral()},
                             {"incident_grid", {rgl.incidentAzimuths(), rgl.incidentElevations()}},
                             {"tabulated_pairs", pairs},
                             {"pairs_below_horizon", belowHorizon}});
    return section;
  }
  const TableCoverage coverage = tableCoverage(*material.table);
  const std::string summary = html::textElement(
      "p",
      std::to_string(coverage.missingReachable) + " of the " + std::to_string(coverage.reachable) +
          " cells that a reflection above the surface reaches are missing (stored negative), " +
          html::number(
              100.0 * double(coverage.missingReachable) / double(std::max<size_t>(coverage.reachable, 1)),
              3) +
          "%; the model fills them from the nearest measured cell along theta_d "
          "(materials/measured/tabulated_brdf.h).",
      {{"class", "small"}});
  section.html = summary + sliceHtml;
  section.data = sliceData;
  section.data.update(json{{"format", "merl"},
                           {"cells", merl::CellCount},
                           {"reachable_cells", coverage.reachable},
                           {"missing_reachable_cells", coverage.missingReachable},
                           {"missing_cells", coverage.missing}});
  return section;
}

}  // namespace scatterlab
