// Two renders of the same image compared pixel block by pixel block (docs/validation.md
// section 7): what the renderer tests and `scatterlab check --render-agreement` share. Each
// render's variance layer gives the variance of a pixel's mean, so the statistic needs nothing
// but the two results.
#pragma once

#include <cmath>

#include <unsupported/Eigen/SpecialFunctions>

#include "integrator/render.h"

namespace scatterlab {

// z-score of a difference of two independent estimates.
inline double zScore(double a, double varianceA, double b, double varianceB) {
  const double variance = varianceA + varianceB;
  return variance > 0 ? (a - b) / std::sqrt(variance) : (a == b ? 0.0 : std::copysign(INFINITY, a - b));
}

// The renderer tests' block statistic (docs/validation.md section 7): two renders of the same
// image, A and B, cut into block x block pixel blocks; block b's mean has variance
// sum(pixel variances) / block^4 (pixels are independent), so z_b = (A_b - B_b) /
// sqrt(var A_b + var B_b) is standard normal when both are unbiased, and sum z_b^2 over the
// blocks compared is chi-square with one degree of freedom per block. `include(x, y)` says
// which pixels may be compared; a block is compared when all of its pixels may be and one of
// the two renders has a nonzero variance there (a block that is black in both tests nothing).
// One colour channel at a time (channels are correlated).
struct Agreement {
  double chi2 = 0.0;
  int dof = 0;
  double pValue = 1.0;
};

template <typename Include> Agreement compareBlocks(const RenderResult& a, const RenderResult& b, int channel,
                                                    int block, const Include& include) {
  Agreement out;
  const int width = a.color.width(), height = a.color.height();
  for (int by = 0; by + block <= height; by += block)
    for (int bx = 0; bx + block <= width; bx += block) {
      double meanA = 0, meanB = 0, varA = 0, varB = 0;
      bool compared = true;
      for (int y = by; y < by + block; ++y)
        for (int x = bx; x < bx + block; ++x) {
          compared &= include(x, y);
          meanA += a.color.pixel(x, y)[channel];
          meanB += b.color.pixel(x, y)[channel];
          varA += a.variance.pixel(x, y)[channel];
          varB += b.variance.pixel(x, y)[channel];
        }
      if (!compared || !(varA + varB > 0)) continue;
      const double n = double(block) * double(block);
      const double z = zScore(meanA / n, varA / (n * n), meanB / n, varB / (n * n));
      out.chi2 += z * z;
      ++out.dof;
    }
  out.pValue = out.dof > 0 ? Eigen::numext::igammac(0.5 * out.dof, 0.5 * out.chi2) : 1.0;
  return out;
}

// The same statistic with a single block of any shape: the pixels where include(x, y) holds,
// summed (one degree of freedom). For renders whose pixels are independent, it sees a bias that
// is the same sign over a region with the power of all its pixels together.
template <typename Include>
Agreement compareRegion(const RenderResult& a, const RenderResult& b, int channel, const Include& include) {
  double sumA = 0, sumB = 0, varA = 0, varB = 0;
  int pixels = 0;
  for (int y = 0; y < a.color.height(); ++y)
    for (int x = 0; x < a.color.width(); ++x) {
      if (!include(x, y)) continue;
      sumA += a.color.pixel(x, y)[channel];
      sumB += b.color.pixel(x, y)[channel];
      varA += a.variance.pixel(x, y)[channel];
      varB += b.variance.pixel(x, y)[channel];
      ++pixels;
    }
  Agreement out;
  if (pixels == 0 || !(varA + varB > 0)) return out;
  const double z = zScore(sumA, varA, sumB, varB);
  out.chi2 = z * z;
  out.dof = 1;
  out.pValue = Eigen::numext::igammac(0.5, 0.5 * out.chi2);
  return out;
}

}  // namespace scatterlab
