// The verdict part of a material's report: the statistical kit (validation/bsdf_check.h or
// subsurface_check.h) run with the lab's settings, every row in a table with PASS / FAIL,
// failing rows repeated at the top, and the observed / expected / residual (and consistency)
// maps the kit writes for every chi-square test. The Sidak correction counts this material's
// chi-square tests only, so a material's verdict does not depend on what else is in the report.
#pragma once

#include <filesystem>
#include <string>

#include "app/lab/lab_material.h"
#include "app/lab/lab_settings.h"
#include "app/lab/report_section.h"
#include "validation/check_report.h"

namespace scatterlab {

struct CheckOutcome {
  CheckReport report;  // the kit's rows
  CheckReport
      controls;  // negative controls (full mode): a row passes when the kit rejects the broken sampler
  bool passed() const { return report.passed() && controls.passed(); }
};

// Runs the kit; the maps go to materialDir/check.
CheckOutcome runLabChecks(const LabMaterial& material, const LabSettings& settings,
                          const std::filesystem::path& materialDir, const ProgressCallback& progress);

// The section; image paths relative to the report's root (folder/check/...).
ReportSection checkSection(const LabMaterial& material, const CheckOutcome& outcome,
                           const std::filesystem::path& materialDir);

// "16 of 16 checks pass" / "2 of 16 checks fail".
std::string verdictText(const CheckOutcome& outcome);

}  // namespace scatterlab
