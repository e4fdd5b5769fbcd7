#include "app/lab/subsurface_section.h"

#include <cmath>

#include "app/lab/html.h"
#include "app/profile_annuli.h"
#include "validation/half_space_reference.h"

namespace scatterlab {

namespace {

using nlohmann::json;

constexpr const char* ChannelNames[3] = {"red", "green", "blue"};

double annulusCentre(const std::vector<double>& edges, size_t k) {
  // The first annulus starts at 0: its centre is half its outer radius.
  return edges[k] > 0 ? std::sqrt(edges[k] * edges[k + 1]) : 0.5 * edges[k + 1];
}

Chart profileChart(const std::string& id, const SubsurfaceComparison& c) {
  Chart chart;
  chart.id = id;
  chart.title = "R(r) averaged over annuli: the profile (lines) and the random walk (points, band +- 2 se)";
  chart.xLabel = "r (mm)";
  chart.yLabel = "R (1/mm^2)";
  chart.logX = chart.logY = true;
  for (int ch = 0; ch < 3; ++ch) {
    // The walk is the data; the profile, a model, may fall far below it where the walk ends.
    ChartSeries profile{std::string(ChannelNames[ch]) + " profile",
                        channelColor(ch),
                        SeriesStyle::Line,
                        {},
                        {},
                        {},
                        /*setsRange=*/false};
    ChartSeries walk{
        std::string(ChannelNames[ch]) + " walk", channelColor(ch), SeriesStyle::Points, {}, {}, {}};
    const HalfSpaceWalkResult& w = c.walk[size_t(ch)];
    for (size_t k = 0; k + 1 < c.edges.size(); ++k) {
      const double r = annulusCentre(c.edges, k);
      profile.points.push_back({r, c.profile[size_t(ch)][k]});
      walk.points.push_back({r, w.profile[k]});
      walk.bandLower.push_back({r, w.profile[k] - 2 * w.profileStdError[k]});
      walk.bandUpper.push_back({r, w.profile[k] + 2 * w.profileStdError[k]});
    }
    chart.series.push_back(std::move(profile));
    chart.series.push_back(std::move(walk));
  }
  return chart;
}

Chart ratioChart(const std::string& id, const SubsurfaceComparison& c) {
  Chart chart;
  chart.id = id;
  chart.title = "Profile / walk per annulus (band: the walk's +- 2 se)";
  chart.xLabel = "r (mm)";
  chart.yLabel = "ratio";
  chart.logX = true;
  for (int ch = 0; ch < 3; ++ch) {
    ChartSeries ratio{ChannelNames[ch], channelColor(ch), SeriesStyle::Line, {}, {}, {}};
    const HalfSpaceWalkResult& w = c.walk[size_t(ch)];
    for (size_t k = 0; k + 1 < c.edges.size(); ++k) {
      // Annuli the walk barely reaches say nothing about the ratio.
      if (!(w.profile[k] > 0) || w.counts[k] < 25) continue;
      const double r = annulusCentre(c.edges, k);
      const double relative = w.profileStdError[k] / w.profile[k];
      ratio.points.push_back({r, c.profile[size_t(ch)][k] / w.profile[k]});
      ratio.bandLower.push_back({r, 1 - 2 * relative});
      ratio.bandUpper.push_back({r, 1 + 2 * relative});
    }
    chart.series.push_back(std::move(ratio));
  }
  chart.series.push_back(
      {"equal", "#999999", SeriesStyle::Guide, {{c.edges[1], 1}, {c.edges.back(), 1}}, {}, {}});
  return chart;
}

std::string totalsTable(const SubsurfaceComparison& c) {
  std::string head;
  for (const char* column : {"channel", "profile Rd", "random walk Rd", "+- se", "profile - walk",
                             "in walk se", "paths per channel"})
    head += html::textElement("th", column);
  std::string body;
  for (int ch = 0; ch < 3; ++ch) {
    const HalfSpaceWalkResult& w = c.walk[size_t(ch)];
    const double difference = c.profileTotal[ch] - w.totalReflectance;
    const double sigmas = w.totalStdError > 0 ? difference / w.totalStdError : NAN;
    body += html::element(
        "tr", html::textElement("td", ChannelNames[ch]) +
                  html::textElement("td", html::number(c.profileTotal[ch], 5), {{"class", "num"}}) +
                  html::textElement("td", html::number(w.totalReflectance, 5), {{"class", "num"}}) +
                  html::textElement("td", html::number(w.totalStdError, 2), {{"class", "num"}}) +
                  html::textElement("td", html::number(difference, 3), {{"class", "num"}}) +
                  html::textElement("td", html::number(sigmas, 3), {{"class", "num"}}) +
                  html::textElement("td", std::to_string(w.settings.paths), {{"class", "num"}}));
  }
  return html::element("table",
                       html::element("thead", html::element("tr", head)) + html::element("tbody", body),
                       {{"class", "rows totals"}});
}

}  // namespace

SubsurfaceComparison compareWithWalk(const SubsurfaceMaterial& material, const LabSettings& settings,
                                     const ProgressCallback& progress) {
  SubsurfaceComparison c;
  const RadialProfile& profile = *material.profile;
  const double extent = profileExtent(profile);
  c.edges = logRadiusEdges(1e-3 * extent, extent, settings.profileBins);
  c.profileTotal = profile.totalReflectance();
  for (int ch = 0; ch < 3; ++ch) {
    c.profile.push_back(annulusMeans(profile, ch, c.edges));
    const HalfSpaceWalkSettings walk =
        mediumWalkSettings(material.medium, ch, c.edges, settings.walkPaths, settings.seed, 0);
    const std::string stage = std::string("walk ") + ChannelNames[ch];
    c.walk.push_back(simulateHalfSpace(
        walk, progress ? WalkProgress([&](double f) { progress(stage, (ch + f) / 3.0); }) : WalkProgress()));
  }
  return c;
}

ReportSection subsurfaceSection(const LabMaterial& material, const SubsurfaceComparison& c) {
  ReportSection section;
  section.id = "subsurface";
  section.title = "Profile against the random walk";
  const SubsurfaceMaterial& s = *material.subsurface;
  section.charts.push_back(profileChart(material.folder + "-profile", c));
  section.charts.push_back(ratioChart(material.folder + "-profile-ratio", c));
  const ScatteringMedium& m = s.medium;
  const std::string medium = "sigma_s (" + html::number(m.sigmaS.x) + ", " + html::number(m.sigmaS.y) + ", " +
                             html::number(m.sigmaS.z) + ") mm^-1, sigma_a (" + html::number(m.sigmaA.x) +
                             ", " + html::number(m.sigmaA.y) + ", " + html::number(m.sigmaA.z) +
                             ") mm^-1, g " + html::number(m.g) + ", eta " + html::number(m.eta);
  std::string charts;
  for (const Chart& chart : section.charts) charts += chartFigure(chart);
  section.html = html::textElement(
                     "p",
                     "Profile " + s.profile->name() + " in the medium " + medium +
                         ". The ground truth is the volumetric random walk in the half-space (searchlight at "
                         "normal incidence, Henyey-Greenstein phase function, Fresnel boundary), tallied on "
                         "the same annuli; its standard errors are exact (binomial).",
                     {{"class", "small"}}) +
                 html::textElement("h4", "Total diffuse reflectance") + totalsTable(c) +
                 html::element("div", charts, {{"class", "chart-grid"}});

  json channels = json::array();
  for (int ch = 0; ch < 3; ++ch) {
    const HalfSpaceWalkResult& w = c.walk[size_t(ch)];
    channels.push_back({{"channel", ChannelNames[ch]},
                        {"profile_total_reflectance", c.profileTotal[ch]},
                        {"profile", c.profile[size_t(ch)]},
                        {"walk",
                         {{"albedo", w.settings.albedo},
                          {"extinction", w.settings.extinction},
                          {"paths", w.settings.paths},
                          {"total_reflectance", w.totalReflectance},
                          {"std_error", w.totalStdError},
                          {"profile", w.profile},
                          {"profile_std_error", w.profileStdError},
                          {"non_finite_paths", w.nonFinite}}}});
  }
  // Walk paths whose position stopped being finite (half_space_walk.h): a red box, and the lab
  // fails the material.
  uint64_t nonFinite = 0, paths = 0;
  for (const HalfSpaceWalkResult& w : c.walk) {
    nonFinite += w.nonFinite;
    paths += w.settings.paths;
  }
  if (nonFinite > 0)
    section.html =
        html::element("div",
                      html::textElement("b", "Random walk: " + std::to_string(nonFinite) + " of " +
                                                 std::to_string(paths) + " paths stopped being finite") +
                          html::element("br", "") +
                          html::textElement("span", "They are left out of every tally below."),
                      {{"class", "failures"}}) +
        section.html;
  section.data = {{"profile_model", s.profile->name()},
                  {"units", "lengths mm, R mm^-2 averaged over each annulus"},
                  {"radius_edges", c.edges},
                  {"channels", channels},
                  {"non_finite_paths", nonFinite}};
  return section;
}

}  // namespace scatterlab
