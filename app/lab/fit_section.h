// How well the classic models fit measured data, a MERL table or an RGL file (fitting/brdf_fit.h,
// the fitter behind `scatterlab fit`): each model family with Ngan et al. 2005's
// cosine-weighted L2 metric, its parameters with error bars (next to the ground truth when the
// table was synthesised from a published fit of the same family), how far it is from the data
// (the relative error in the metric per channel, and, once the renders exist, the renders'
// relative mean |material - fit|), a quality grade that a poor fit cannot pass (fitQuality),
// and its curve over the data on the theta_h slices of measured_section.h.
//
// Families: Lambert + Ngan's Cook-Torrance, Lambert + GGX (a white conductor with a fitted
// scale), Lambert + Ngan's Ward, Blinn-Phong, whose own kd is its diffuse term (a Lambertian
// beside it would be a second diffuse term that the data cannot tell apart from kd: a
// rank-deficient fit), and a GGX conductor alone whose complex index is fitted (f0 and edge
// tint, fitting/fit_model.h). Every family is identifiable, and a rank-deficient fit is POOR
// (fit_verdict.h). Quick mode fits them on a stratified subset of the data, the full report on
// all of it (lab_settings.h).
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/fit_verdict.h"
#include "app/lab/lab_material.h"
#include "app/lab/lab_settings.h"
#include "app/lab/report_section.h"
#include "fitting/fit_model.h"

namespace scatterlab {

struct FamilyFit {
  std::string name;  // "Lambert + Cook-Torrance (Ngan)"
  std::string spec;  // "lambertian+ngan-cook-torrance"
  std::unique_ptr<fitting::FitModel> model;
  fitting::FitResult result;
  fitting::WrittenMaterial written;
  FitVerdict verdict;
};

struct MaterialFits {
  std::vector<FamilyFit> families;
  size_t usableCells = 0, fittedSamples = 0;
  bool rglPairs = false;  // the samples are an RGL file's tabulated pairs, not MERL cells
  fitting::FitOptions options;
};

// How close a fit is, from its worst channel's relative error e in the metric (the rms
// residual over the rms data, so e^2 is the share of the data's metric energy the fit leaves
// unexplained): "close" for e <= 0.1 (1% left), "approximate" for e <= 0.3 (9% left), "poor"
// above, and "poor" whatever e when Ceres did not converge or the sum has no registry form.
// `scatterlab fit`'s GOOD (e <= 0.7 by default) is a bar for writing a material, not a
// judgement of closeness, so the report does not use it.
struct FitQuality {
  std::string grade;  // "close", "approximate", "poor"
  std::string reason;
};
FitQuality fitQuality(const FamilyFit& fit);

// The families of this mode fitted to the material's table.
MaterialFits fitMaterial(const LabMaterial& material, const LabSettings& settings,
                         const ProgressCallback& progress);

// The fitted model's value at (wi, wo), per channel.
Rgb evaluateFit(const FamilyFit& fit, const Vec3d& wi, const Vec3d& wo);

// `renderDifferences`: per family name, its renders' relative mean |material - fit| per map
// (renders_section.h fitRenderDifferences), shown beside the metric's error.
ReportSection fitSection(const LabMaterial& material, const LabSettings& settings, const MaterialFits& fits,
                         const std::map<std::string, std::string>& renderDifferences = {});

}  // namespace scatterlab
