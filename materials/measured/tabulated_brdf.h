// A measured isotropic BRDF in the MERL layout (merl_format.h), as a BsdfModel.
//
// Evaluation: trilinear interpolation between cell centres in the cells' own index
// coordinates, (sqrt(theta_h / (pi/2)) * 90, theta_d / (pi/2) * 90, phi_d / pi * 180), so the
// non-linear theta_h axis is interpolated where its cells are, not in theta_h itself. phi_d is
// periodic with period pi (reciprocity: swapping wi and wo moves phi_d by pi), which makes
// eval exactly reciprocal; the table knows nothing of phi_h, which makes it isotropic. Past
// the first and last centre of theta_h and theta_d the value is held constant.
//
// Missing and unreachable cells (the fill rule). A cell is usable when it is measured (no
// channel negative) and its centre is a reflection above the surface (both wi and wo there
// have z > 0). Every other cell takes, for interpolation only, the value of the nearest
// usable cell along theta_d in the same (theta_h, phi_d) column (ties: the smaller theta_d);
// when the column has none, the nearest filled cell along theta_h in the same
// (theta_d, phi_d) row; when that fails too, 0. Values therefore never go negative, missing
// grazing measurements are extended from the last measured theta_d (an underestimate where
// Fresnel rises), and cells that no reflection pair reaches do not pull the interpolation
// toward whatever the file stores there (0 in scatterlab's tables).
//
// Sampling: HalfVectorSampler (half_vector_sampler.h) built from this model's own eval.
#pragma once

#include <array>
#include <vector>

#include "materials/bsdf/bsdf.h"
#include "materials/measured/half_diff.h"
#include "materials/measured/half_vector_sampler.h"
#include "materials/measured/merl_io.h"

namespace scatterlab {

class TabulatedBrdf final : public BsdfModel {
 public:
  explicit TabulatedBrdf(const MerlTable& table, const HalfVectorSamplerOptions& sampling = {});

  Rgb eval(const Vec3d& wi, const Vec3d& wo, TransportMode = TransportMode::Radiance) const override {
    if (!(wi.z > 0) || !(wo.z > 0)) return Rgb(0.0);
    return interpolate(halfDiffFromDirections(wi, wo, /*withPhiHalf=*/false));
  }
  double pdf(const Vec3d& wi, const Vec3d& wo, TransportMode = TransportMode::Radiance) const override {
    return sampler_.pdf(wi, wo);
  }
  std::optional<BsdfSample> sample(const Vec3d& wi, double uLobe, const Vec2d& u,
                                   TransportMode = TransportMode::Radiance) const override;
  LobeFlags flags() const override { return LobeFlags::GlossyReflection | LobeFlags::DiffuseReflection; }

  // The interpolated table at half/diff angles (phi_h ignored), without the horizon test.
  Rgb interpolate(const HalfDiff& angles) const;
  // The value the fill rule gives a cell (the table's value for usable cells).
  Rgb cellValue(size_t cell) const {
    const auto& v = grid_[cell];
    return {v[0], v[1], v[2]};
  }

  // Cells the file marks missing (negative), and cells the fill rule replaced (missing or
  // unreachable).
  size_t missingCells() const { return missingCells_; }
  size_t filledCells() const { return filledCells_; }

 private:
  struct FilledGrid {
    std::vector<std::array<float, 3>> values;
    size_t missing = 0, filled = 0;
  };
  static FilledGrid fill(const MerlTable& table);
  TabulatedBrdf(FilledGrid grid, const HalfVectorSamplerOptions& sampling);

  // Filled values, RGB interleaved (one cache line per cell's channels), in sr^-1. float:
  // 17.5 MB instead of 35, and its 6e-8 relative rounding is far below any table's own error.
  using Grid = std::vector<std::array<float, 3>>;
  Grid grid_;
  size_t missingCells_ = 0, filledCells_ = 0;
  HalfVectorSampler sampler_;
};

// Whether a cell's centre is a reflection above the surface (wi.z > 0 and wo.z > 0 there).
bool isReachableCell(size_t cell);

}  // namespace scatterlab
