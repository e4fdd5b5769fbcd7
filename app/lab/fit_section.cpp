#include "app/lab/fit_section.h"

#include <algorithm>
#include <cmath>

#include "app/lab/html.h"
#include "app/lab/lobe_curves.h"
#include "app/lab/measured_section.h"
#include "app/lab/measured_slice.h"
#include "fitting/brdf_fit.h"
#include "fitting/brdf_samples.h"
#include "fitting/material_writer.h"
#include "materials/measured/half_diff.h"
#include "materials/measured/merl_format.h"

namespace scatterlab {

namespace {

using nlohmann::json;
using namespace fitting;

// The ground truth's value of a fitted parameter, when the table was made from the same family.
std::optional<double> truthOf(const LabMaterial& material, const FitModel& model, const FitParameter& p) {
  const auto& components = model.components();
  if (material.groundTruth.size() != components.size()) return std::nullopt;
  const json& truth = material.groundTruth[p.component];
  if (truth.value("type", std::string()) != components[p.component].type || !truth.contains(p.key))
    return std::nullopt;
  const json& value = truth[p.key];
  if (value.is_number()) return value.get<double>();
  if (value.is_array() && p.channel >= 0 && size_t(p.channel) < value.size())
    return value[size_t(p.channel)].get<double>();
  return std::nullopt;
}

std::string relativeErrorText(const FitResult& r) { return html::rgb(r.relativeError); }

std::string summaryTable(const MaterialFits& fits,
                         const std::map<std::string, std::string>& renderDifferences) {
  std::string head;
  for (const char* column : {"model family", "parameters", "relative error (r, g, b)", "rms (r, g, b)",
                             "renders: mean |material - fit|", "iterations", "seconds", "fit"})
    head += html::textElement("th", column);
  std::string body;
  for (const FamilyFit& f : fits.families) {
    const FitResult& r = f.result;
    const FitQuality quality = fitQuality(f);
    const auto rendered = renderDifferences.find(f.name);
    const bool poor = quality.grade == "poor";
    body += html::element(
        "tr",
        html::element("td", html::textElement("b", f.name) + html::element("br", "") +
                                html::textElement("code", f.spec)) +
            html::textElement("td", std::to_string(r.parameters.size()), {{"class", "num"}}) +
            html::textElement("td", relativeErrorText(r), {{"class", "num"}}) +
            html::textElement("td", html::rgb(r.rms), {{"class", "num"}}) +
            html::textElement("td", rendered == renderDifferences.end() ? "-" : rendered->second,
                              {{"class", "num"}}) +
            html::textElement("td", std::to_string(r.final.iterations), {{"class", "num"}}) +
            html::textElement("td", html::number(r.seconds, 3), {{"class", "num"}}) +
            html::element("td",
                          html::textElement("b", quality.grade) + html::element("br", "") +
                              html::textElement("span", quality.reason, {{"class", "small"}}),
                          {{"class", poor                       ? "verdict fail"
                                     : quality.grade == "close" ? "verdict pass"
                                                                : "verdict"}}),
        {{"class", poor ? "failed" : ""}});
  }
  return html::element("table",
                       html::element("thead", html::element("tr", head)) + html::element("tbody", body),
                       {{"class", "rows fits"}});
}

std::string parameterTable(const LabMaterial& material, const FamilyFit& f) {
  bool anyTruth = false;
  for (const FitParameter& p : f.model->parameters())
    anyTruth = anyTruth || truthOf(material, *f.model, p).has_value();
  std::string head;
  for (const char* column : {"parameter", "value", "+- std dev", "range"})
    head += html::textElement("th", column);
  if (anyTruth)
    head += html::textElement("th", "ground truth") + html::textElement("th", "(value - truth) / std dev");
  std::string body;
  for (size_t k = 0; k < f.result.parameters.size(); ++k) {
    const ParameterEstimate& e = f.result.parameters[k];
    const auto bound = [](double x) {
      return std::abs(x) >= 1e300 ? std::string("inf") : html::number(x, 3);
    };
    std::string cells =
        html::textElement("td", e.name + (e.atBound ? " (at bound)" : "")) +
        html::textElement("td", html::number(e.value, 5), {{"class", "num"}}) +
        html::textElement("td", html::number(e.standardDeviation, 2), {{"class", "num"}}) +
        html::textElement("td", "[" + bound(e.lower) + ", " + bound(e.upper) + "]", {{"class", "num"}});
    if (anyTruth) {
      const auto truth = truthOf(material, *f.model, f.model->parameters()[k]);
      cells += html::textElement("td", truth ? html::number(*truth, 5) : "-", {{"class", "num"}});
      cells += html::textElement(
          "td",
          truth && e.standardDeviation > 0 ? html::number((e.value - *truth) / e.standardDeviation, 3) : "-",
          {{"class", "num"}});
    }
    body += html::element("tr", cells);
  }
  std::string notes;
  if (!f.result.covarianceAvailable) notes += "The covariance is not available: no error bars. ";
  for (const std::string& direction : f.result.unidentified)
    notes += "Rank deficient: " + direction + " cannot be determined from the data. ";
  const FitQuality quality = fitQuality(f);
  if (quality.grade != "close") notes += quality.grade + ": " + quality.reason + ". ";
  for (const std::string& problem : f.verdict.problems)
    notes += "Not written by `scatterlab fit`: " + problem + ". ";
  return html::element("table",
                       html::element("thead", html::element("tr", head)) + html::element("tbody", body),
                       {{"class", "rows parameters"}}) +
         (notes.empty() ? "" : html::textElement("p", notes, {{"class", "note"}}));
}

// The data on the theta_h slices (points) and the fit's curve at the same cells (lines).
Chart sliceChart(const std::string& id, const MeasuredSlice& slice, const FamilyFit& f) {
  Chart chart;
  chart.id = id;
  chart.title = f.name + " over the data, phi_d = " + html::degrees(slice.phiDiffDeg);
  chart.xLabel = "theta_h (deg)";
  chart.yLabel = "f (1/sr, luminance)";
  chart.logY = true;
  chart.xMin = 0;
  chart.xMax = 90;
  const double phiDiff = merl::phiDiffAt(slice.phiDiffCell + 0.5);
  for (size_t i = 0; i < std::size(SliceThetaDiffDeg); ++i) {
    const int d = thetaDiffCellAt(SliceThetaDiffDeg[i]);
    const std::string label = "theta_d " + html::degrees(thetaDiffCentreDeg(d));
    chart.series.push_back(
        {label + " data", paletteColor(i), SeriesStyle::Points, sliceAlongThetaHalf(slice, d), {}, {}});
    ChartSeries curve{label + " fit", paletteColor(i), SeriesStyle::Line, {}, {}, {}, /*setsRange=*/false};
    for (int h = 0; h < merl::ThetaHalfCells; ++h) {
      const auto [wi, wo] =
          directionsFromHalfDiff(merl::thetaHalfAt(h + 0.5), 0.0, merl::thetaDiffAt(d + 0.5), phiDiff);
      if (wi.z > 0 && wo.z > 0)
        curve.points.push_back({thetaHalfCentreDeg(h), rec709Luminance(evaluateFit(f, wi, wo))});
    }
    chart.series.push_back(std::move(curve));
  }
  return chart;
}

}  // namespace

FitQuality fitQuality(const FamilyFit& fit) {
  const FitResult& r = fit.result;
  if (r.x.empty()) return {"poor", "not fitted: no data"};
  if (!r.final.converged) return {"poor", "did not converge (" + r.final.termination + ")"};
  if (!fit.written.material) return {"poor", "no registry form: " + fit.written.problem};
  const double worst = std::max({r.relativeError.x, r.relativeError.y, r.relativeError.z});
  const std::string error = "worst channel's relative error " + html::number(worst, 3);
  if (!(worst <= 0.3)) return {"poor", error + " > 0.3"};
  if (!(worst <= 0.1)) return {"approximate", error + " in (0.1, 0.3]"};
  return {"close", error + " <= 0.1"};
}

Rgb evaluateFit(const FamilyFit& fit, const Vec3d& wi, const Vec3d& wo) {
  double value[3];
  fit.model->evaluate<false>(fit.result.x.data(), wi, wo, value, nullptr);
  return {value[0], value[1], value[2]};
}

MaterialFits fitMaterial(const LabMaterial& material, const LabSettings& settings,
                         const ProgressCallback& progress) {
  MaterialFits fits;
  BrdfSamples all;
  if (material.table) {
    MerlSampleCounts counts;
    all = samplesFromMerl(*material.table, &counts);
    fits.usableCells = counts.usable;
  } else {
    RglSampleCounts counts;
    all = samplesFromRgl(*material.rgl, &counts);
    fits.usableCells = counts.usable;
    fits.rglPairs = true;
  }
  const BrdfSamples samples = stratifiedSubset(all, settings.fitSamples, settings.seed);
  fits.fittedSamples = samples.size();
  fits.options.metric = Metric::Ngan;
  fits.options.gridBudget = settings.fitGridPoints;
  fits.options.starts = settings.fitStarts;
  fits.options.gridSamples = settings.fitGridSamples;
  fits.options.startSamples = settings.fitStartSamples;
  fits.options.seed = settings.seed;
  for (size_t i = 0; i < settings.fitFamilies.size(); ++i) {
    // Named, not a structured binding: the progress lambda captures spec (clang 14 cannot
    // capture bindings).
    const std::string& name = settings.fitFamilies[i].first;
    const std::string& spec = settings.fitFamilies[i].second;
    FamilyFit f;
    f.name = name;
    f.spec = spec;
    f.model = std::make_unique<FitModel>(parseModelSpec(spec), false);
    FitOptions options = fits.options;
    if (progress)
      options.progress = [&, i](const std::string& stage, double fraction) {
        progress("fit " + spec + " " + stage, (double(i) + fraction) / double(settings.fitFamilies.size()));
      };
    if (samples.empty()) {
      // Nothing to fit: no parameters to write (fittedParts would read them).
      f.written = {std::nullopt, "the table has no usable cells"};
      f.verdict = FitVerdict{false, {"the table has no usable cells"}};
    } else {
      f.result = fitBrdf(*f.model, samples, options);
      f.written = writeMaterial(f.model->fittedParts(f.result.x.data()));
      f.verdict = judgeFit(f.result, f.written, DefaultMaxRelativeError);
    }
    fits.families.push_back(std::move(f));
  }
  return fits;
}

ReportSection fitSection(const LabMaterial& material, const LabSettings& settings, const MaterialFits& fits,
                         const std::map<std::string, std::string>& renderDifferences) {
  ReportSection section;
  section.id = "fits";
  section.title = "Fits of the classic models";
  const MeasuredSlice slice = material.table ? sliceAtPhiDiff(*material.table, settings.slicePhiDiffDeg)
                                             : sliceAtPhiDiff(*material.bsdf, settings.slicePhiDiffDeg);
  const std::string unit = fits.rglPairs ? "direction pairs the file tabulates" : "usable cells";
  std::string html = html::textElement(
      "p",
      "Metric " + describe(fits.options.metric) + ", per sample and channel, both orderings of each " +
          (fits.rglPairs ? "pair" : "cell") + ". Fitted on " +
          (fits.fittedSamples == fits.usableCells
               ? "all " + std::to_string(fits.usableCells) + " " + unit
               : "a stratified subset of " + std::to_string(fits.fittedSamples) + " of the " +
                     std::to_string(fits.usableCells) + " " + unit) +
          (fits.rglPairs
               ? " (every node of the file's colour grid at every tabulated incident direction, mapped "
                 "through its vndf warp, weight 1 each)"
               : " (missing cells are left out)") +
          ". How far each family is from the data: the relative error in the metric per channel (rms "
          "residual "
          "over rms data) and the renders' relative mean |material - fit| on the sphere. Grade: close when "
          "the "
          "worst channel's relative error is at most 0.1, approximate up to 0.3, poor above, or when Ceres "
          "did "
          "not converge or the sum has no registry form. Error bars: standard deviations from "
          "ceres::Covariance scaled by cost / (N - p).",
      {{"class", "small"}});
  html += summaryTable(fits, renderDifferences);
  std::string charts;
  json familiesJson = json::array();
  for (size_t i = 0; i < fits.families.size(); ++i) {
    const FamilyFit& f = fits.families[i];
    html += html::element(
        "details", html::textElement("summary", "Parameters of " + f.name) + parameterTable(material, f),
        {{"open", "open"}});
    if (f.result.x.empty()) continue;
    section.charts.push_back(sliceChart(material.folder + "-fit-" + std::to_string(i), slice, f));
    charts += chartFigure(section.charts.back());
    familiesJson.push_back({{"name", f.name},
                            {"spec", f.spec},
                            {"fit", toJson(f.result, *f.model, fits.options)},
                            {"material", f.written.material ? *f.written.material : json()},
                            {"quality", fitQuality(f).grade},
                            {"quality_reason", fitQuality(f).reason},
                            {"render_differences",
                             renderDifferences.count(f.name) ? json(renderDifferences.at(f.name)) : json()},
                            {"written_by_fit_command", f.verdict.good},
                            {"problems", f.verdict.problems}});
  }
  html += html::element("div", charts, {{"class", "chart-grid"}});
  section.html = std::move(html);
  section.data = {{"metric", toString(fits.options.metric)},
                  {"data", fits.rglPairs ? "rgl tabulated pairs" : "merl cells"},
                  {"usable_cells", fits.usableCells},
                  {"fitted_samples", fits.fittedSamples},
                  {"families", familiesJson}};
  return section;
}

}  // namespace scatterlab
