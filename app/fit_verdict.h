// When a fit is good enough to use: `scatterlab fit` writes only good fits, and the lab
// report marks each model family's fit GOOD or POOR by the same rule.
#pragma once

#include <string>
#include <vector>

#include "fitting/brdf_fit.h"
#include "fitting/material_writer.h"

namespace scatterlab {

// 0.7^2 ~ 1/2: the fit leaves half of the data's metric energy unexplained.
inline constexpr double DefaultMaxRelativeError = 0.7;

struct FitVerdict {
  bool good = true;
  std::vector<std::string> problems;  // why not, in words
};

// Poor when the residuals at the result are not finite, Ceres did not converge, a channel's relative error
// exceeds maxRelativeError, the fit is rank deficient (a direction of parameters the data cannot determine:
// its values are arbitrary along it, so the written material means nothing there), or the fitted sum has no
// registry form.
FitVerdict judgeFit(const fitting::FitResult& result, const fitting::WrittenMaterial& written,
                    double maxRelativeError);

}  // namespace scatterlab
