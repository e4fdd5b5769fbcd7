// The BSDF's shape and energy, for analytic and measured materials: polar lobe plots in the
// plane of incidence at several incident angles (lobe_curves.h), f on a log scale in the same
// plane, and the directional albedo against the incident angle (albedo_curve.h).
#pragma once

#include "app/lab/lab_material.h"
#include "app/lab/lab_settings.h"
#include "app/lab/report_section.h"

namespace scatterlab {

ReportSection plotsSection(const LabMaterial& material, const LabSettings& settings);

}  // namespace scatterlab
