#include "app/lab/plots_section.h"

#include <algorithm>
#include <cmath>

#include "app/lab/albedo_curve.h"
#include "app/lab/html.h"
#include "app/lab/lobe_curves.h"

namespace scatterlab {

namespace {

using nlohmann::json;

// Guides of a polar plot: the surface (and the normal), and circles at half and full radius.
void addPolarGuides(Chart& chart, bool fullCircle) {
  const double lowest = fullCircle ? -1.0 : 0.0;
  chart.series.push_back({"surface", "#999999", SeriesStyle::Guide, {{-1.0, 0.0}, {1.0, 0.0}}, {}, {}});
  chart.series.push_back({"normal", "#999999", SeriesStyle::Guide, {{0.0, lowest}, {0.0, 1.0}}, {}, {}});
  for (const double radius : {0.5, 1.0}) {
    ChartSeries circle{"r = " + html::number(radius), "#cccccc", SeriesStyle::Guide, {}, {}, {}};
    const int steps = fullCircle ? 120 : 60;
    for (int k = 0; k <= steps; ++k) {
      const double a = (fullCircle ? 2.0 : 1.0) * Pi * k / steps;
      circle.points.push_back({radius * std::cos(a), radius * std::sin(a)});
    }
    chart.series.push_back(std::move(circle));
  }
}

Chart polarLobeChart(const std::string& id, const std::vector<LobeCurve>& curves, bool fullCircle) {
  Chart chart;
  chart.id = id;
  chart.kind = ChartKind::Polar;
  chart.title = "Lobes in the plane of incidence: f |cos theta_o| (luminance), each scaled to its peak";
  chart.xLabel = "along the surface (wi on the left)";
  chart.yLabel = "along the normal";
  chart.xMin = -1.0;
  chart.xMax = 1.0;
  chart.yMin = fullCircle ? -1.0 : 0.0;
  chart.yMax = 1.0;
  addPolarGuides(chart, fullCircle);
  for (size_t i = 0; i < curves.size(); ++i) {
    const LobeCurve& curve = curves[i];
    std::vector<double> radius;
    double peak = 0;
    for (size_t k = 0; k < curve.value.size(); ++k) {
      const double t = curve.thetaOutDeg[k] * Pi / 180.0;
      radius.push_back(rec709Luminance(curve.value[k]) * std::abs(std::cos(t)));
      if (std::isfinite(radius.back())) peak = std::max(peak, radius.back());
    }
    ChartSeries lobe{"theta_i " + html::degrees(curve.thetaInDeg) + " (peak " + html::number(peak, 3) + ")",
                     paletteColor(i),
                     SeriesStyle::Line,
                     {},
                     {},
                     {}};
    for (size_t k = 0; k < radius.size() && peak > 0; ++k) {
      const double t = curve.thetaOutDeg[k] * Pi / 180.0;
      lobe.points.push_back({radius[k] / peak * std::sin(t), radius[k] / peak * std::cos(t)});
    }
    chart.series.push_back(std::move(lobe));
    // The incident direction, drawn from the centre toward wi (on the left, t < 0).
    const double ti = curve.thetaInDeg * Pi / 180.0;
    chart.series.push_back(
        {"", paletteColor(i), SeriesStyle::Dashed, {{0, 0}, {-std::sin(ti), std::cos(ti)}}, {}, {}});
  }
  return chart;
}

Chart lobeValueChart(const std::string& id, const std::vector<LobeCurve>& curves, bool fullCircle) {
  Chart chart;
  chart.id = id;
  chart.title = "f in the plane of incidence (luminance, log scale)";
  chart.xLabel = "theta_o (deg; > 0 on the far side from wi, |theta_o| > 90 below the surface)";
  chart.yLabel = "f (1/sr)";
  chart.logY = true;
  chart.xMin = fullCircle ? -180.0 : -90.0;
  chart.xMax = fullCircle ? 180.0 : 90.0;
  for (size_t i = 0; i < curves.size(); ++i) {
    ChartSeries series{
        "theta_i " + html::degrees(curves[i].thetaInDeg), paletteColor(i), SeriesStyle::Line, {}, {}, {}};
    for (size_t k = 0; k < curves[i].value.size(); ++k)
      series.points.push_back({curves[i].thetaOutDeg[k], rec709Luminance(curves[i].value[k])});
    chart.series.push_back(std::move(series));
  }
  return chart;
}

Chart albedoChart(const std::string& id, const std::vector<AlbedoPoint>& curve) {
  Chart chart;
  chart.id = id;
  chart.title = "Directional albedo (quadrature)";
  chart.xLabel = "theta_i (deg)";
  chart.yLabel = "albedo";
  chart.xMin = 0;
  chart.xMax = 90;
  chart.yMin = 0;
  // Ticks every 0.2 and room above 1, so that the energy-conservation line is clear of the top.
  double top = 1.0;
  for (const AlbedoPoint& p : curve) top = std::max({top, p.albedo.x, p.albedo.y, p.albedo.z});
  chart.yMax = std::ceil(top * 5.0 + 1e-9) / 5.0 + 0.2;
  static const char* names[3] = {"red", "green", "blue"};
  for (int c = 0; c < 3; ++c) {
    ChartSeries series{names[c], channelColor(c), SeriesStyle::Line, {}, {}, {}};
    for (const AlbedoPoint& p : curve) series.points.push_back({p.thetaDeg, p.albedo[c]});
    chart.series.push_back(std::move(series));
  }
  chart.series.push_back(
      {"energy conservation (1)", "#999999", SeriesStyle::Guide, {{0, 1}, {90, 1}}, {}, {}});
  return chart;
}

json curvesJson(const std::vector<LobeCurve>& curves) {
  json out = json::array();
  for (const LobeCurve& curve : curves) {
    json values = json::array();
    for (const Rgb& f : curve.value)
      values.push_back(
          {std::isfinite(f.x) ? f.x : 0.0, std::isfinite(f.y) ? f.y : 0.0, std::isfinite(f.z) ? f.z : 0.0});
    out.push_back({{"theta_i_deg", curve.thetaInDeg}, {"theta_o_deg", curve.thetaOutDeg}, {"f_rgb", values}});
  }
  return out;
}

}  // namespace

ReportSection plotsSection(const LabMaterial& material, const LabSettings& settings) {
  ReportSection section;
  section.id = "plots";
  section.title = "Lobes and energy";
  const BsdfModel& model = *material.bsdf;
  const bool fullCircle = hasAny(model.flags(), LobeFlags::Transmission);
  const int directions = fullCircle ? 2 * settings.lobeDirections - 1 : settings.lobeDirections;
  std::vector<LobeCurve> curves;
  for (const double theta : settings.lobeAnglesDeg)
    curves.push_back(lobeInPlaneOfIncidence(model, theta, settings.kit.wiPhiDeg, directions));

  AlbedoCurveOptions albedoOptions;
  albedoOptions.phiDeg = settings.kit.wiPhiDeg;
  albedoOptions.cosThetaCells = settings.albedoCosThetaCells;
  albedoOptions.phiCells = settings.albedoPhiCells;
  albedoOptions.probeSamples = settings.albedoProbeSamples;
  albedoOptions.seed = settings.seed;
  const std::vector<AlbedoPoint> albedo =
      directionalAlbedoCurve(model, settings.albedoAnglesDeg, albedoOptions);

  const std::string prefix = material.folder + "-";
  const bool deltaOnly = !hasAny(model.flags(), LobeFlags::Diffuse | LobeFlags::Glossy);
  std::string body;
  if (deltaOnly) {
    body += html::textElement("p",
                              "This model has only delta (mirror-like) lobes: f is zero for every pair of "
                              "directions, so there is no lobe to draw.",
                              {{"class", "note"}});
  } else {
    section.charts.push_back(polarLobeChart(prefix + "lobe-polar", curves, fullCircle));
    section.charts.push_back(lobeValueChart(prefix + "lobe-log", curves, fullCircle));
  }
  section.charts.push_back(albedoChart(prefix + "albedo", albedo));
  body +=
      html::textElement("p",
                        "The plane of incidence is at azimuth " + html::degrees(settings.kit.wiPhiDeg) +
                            " from the tangent, as in the checks. The albedo is the kit's quadrature (" +
                            std::to_string(settings.albedoCosThetaCells) + " x " +
                            std::to_string(settings.albedoPhiCells) + " cells split at sample centroids, " +
                            (fullCircle ? "importance transport, " : "") + "delta lobes included).",
                        {{"class", "small"}});
  std::string charts;
  for (const Chart& chart : section.charts) charts += chartFigure(chart);
  body += html::element("div", charts, {{"class", "chart-grid"}});
  section.html = std::move(body);

  json albedoJson = json::array();
  for (const AlbedoPoint& p : albedo)
    albedoJson.push_back({{"theta_i_deg", p.thetaDeg}, {"albedo_rgb", {p.albedo.x, p.albedo.y, p.albedo.z}}});
  section.data = {{"lobes", curvesJson(curves)},
                  {"directional_albedo", albedoJson},
                  {"plane_of_incidence_phi_deg", settings.kit.wiPhiDeg}};
  return section;
}

}  // namespace scatterlab
