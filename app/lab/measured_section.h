// The measured data itself: the theta_h / theta_d image slice at the chosen phi_d
// (measured_slice.h) with its colour scale, and f along theta_h at three theta_d on a log
// scale, so that the highlight, the Fresnel rise toward grazing theta_d and any missing
// measurements can be seen. A MERL table shows its stored cells and how many are missing; an
// RGL file is evaluated at the same cell centres, with what its grids hold.
#pragma once

#include <filesystem>

#include "app/lab/lab_material.h"
#include "app/lab/lab_settings.h"
#include "app/lab/measured_slice.h"
#include "app/lab/report_section.h"

namespace scatterlab {

// The theta_d (degrees) at which the slices along theta_h are drawn, here and in the fits.
inline constexpr double SliceThetaDiffDeg[3] = {10.0, 45.0, 75.0};

// Data of one slice along theta_h: (theta_h centre in degrees, luminance of f) for every
// measured cell of theta_d cell `thetaDiffCell`.
std::vector<Vec2d> sliceAlongThetaHalf(const MeasuredSlice& slice, int thetaDiffCell);

ReportSection measuredSection(const LabMaterial& material, const LabSettings& settings,
                              const std::filesystem::path& materialDir);

}  // namespace scatterlab
