// How well the classic models fit a measured table (fitting/brdf_fit.h, the fitter behind
// `scatterlab fit`): each model family with Ngan et al. 2005's cosine-weighted L2 metric, its
// parameters with error bars (next to the ground truth when the table was synthesised from a
// published fit of the same family), its errors, GOOD or POOR by `scatterlab fit`'s rule
// (fit_verdict.h), and its curve over the data on the theta_h slices of measured_section.h.
//
// Families: Lambert + Ngan's Cook-Torrance, Lambert + GGX (a white conductor), Lambert +
// Ngan's Ward, and Blinn-Phong, whose own kd is its diffuse term (a Lambertian beside it would
// be a second diffuse term that the data cannot tell apart from kd: a rank-deficient fit).
// Every family is identifiable, and a rank-deficient fit is POOR (fit_verdict.h). Quick mode
// fits them on a stratified subset of the table, the full report on every usable cell
// (lab_settings.h).
#pragma once

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
  fitting::FitOptions options;
};

// The families of this mode fitted to the material's table.
MaterialFits fitMaterial(const LabMaterial& material, const LabSettings& settings,
                         const ProgressCallback& progress);

// The fitted model's value at (wi, wo), per channel.
Rgb evaluateFit(const FamilyFit& fit, const Vec3d& wi, const Vec3d& wo);

ReportSection fitSection(const LabMaterial& material, const LabSettings& settings, const MaterialFits& fits);

}  // namespace scatterlab
