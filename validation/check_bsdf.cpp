#include "validation/check_bsdf.h"

#include <filesystem>

#include "materials/core/temporary_files.h"

namespace scatterlab {

CheckReport checkBsdf(const BsdfModel& model, const CheckBsdfOptions& options) {
  if (options.kit.imageDir) createDirectoriesUninterrupted(*options.kit.imageDir);
  CheckReport report = runBsdfChecks(model, options.label, options.kit, options.progress);
  if (options.negativeControls)
    report.append(runNegativeControls(model, options.roughnessMismatchSampler, options.label, options.kit,
                                      options.progress));
  return report;
}

std::string formatVerdict(const CheckReport& report) {
  return formatTable(report) + "verdict: " + (report.passed() ? "PASS" : "FAIL") + "\n";
}

}  // namespace scatterlab
