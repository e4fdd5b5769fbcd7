#include "app/fit_verdict.h"
#include "app/format_number.h"

namespace scatterlab {

FitVerdict judgeFit(const fitting::FitResult& result, const fitting::WrittenMaterial& written,
                    double maxRelativeError) {
  FitVerdict verdict;
  const auto fail = [&](std::string problem) {
    verdict.good = false;
    verdict.problems.push_back(std::move(problem));
  };
  // First: nothing else about such a fit means anything (fitting/brdf_fit.h).
  if (!result.finiteResiduals)
    fail(
        "the residuals at the fitted parameters are not finite (the model's values are not finite on the "
        "data): no cost, no error bars");
  if (!result.final.converged)
    fail("did not converge: " + result.final.termination + " after " +
         std::to_string(result.final.iterations) + " iterations (" + result.final.message + ")");
  for (int c = 0; c < 3; ++c)
    if (!(result.relativeError[c] <= maxRelativeError))
      fail(std::string("relative error of channel ") + "rgb"[c] + " " +
           formatNumber("%.3g", result.relativeError[c]) + " exceeds --max-relative-error " +
           formatNumber("%g", maxRelativeError));
  if (result.rankDeficient) {
    std::string directions;
    for (const std::string& d : result.unidentified) directions += (directions.empty() ? "" : "; ") + d;
    fail("rank deficient: the data cannot determine " +
         (directions.empty() ? "some parameters" : directions));
  }
  if (!written.material) fail("no registry material: " + written.problem);
  return verdict;
}

}  // namespace scatterlab
