// A subsurface material against its ground truth: the radial profile R(r) per channel,
// averaged over annuli (profile_annuli.h), next to the half-space random walk in the same
// medium with its standard errors, on a log-log chart and as the ratio profile / walk; and the
// total diffuse reflectance of both, per channel, with the difference in standard errors.
#pragma once

#include "app/lab/lab_material.h"
#include "app/lab/lab_settings.h"
#include "app/lab/report_section.h"
#include "materials/bssrdf/half_space_walk.h"
#include "validation/bsdf_check.h"

namespace scatterlab {

struct SubsurfaceComparison {
  std::vector<double> edges;                 // annuli, mm
  std::vector<std::vector<double>> profile;  // per channel, per annulus, mm^-2
  std::vector<HalfSpaceWalkResult> walk;     // per channel
  Rgb profileTotal{0.0};
};

SubsurfaceComparison compareWithWalk(const SubsurfaceMaterial& material, const LabSettings& settings,
                                     const ProgressCallback& progress);

ReportSection subsurfaceSection(const LabMaterial& material, const SubsurfaceComparison& comparison);

}  // namespace scatterlab
