// A measured BRDF of the RGL material database (Dupuy & Jakob 2018, "An Adaptive
// Parameterization for Efficient Material Acquisition and Rendering"; docs/references.md, "RGL
// measured BRDFs"), read from its tensor file (tensor_file.h), evaluated and sampled as the
// reference reader (rgl-epfl/brdf-loader) defines it, in double precision.
//
// Angles map to the unit square as u_theta = sqrt(theta / (pi/2)), u_phi = (phi + pi) / (2 pi).
// For an incident direction wi (polar theta_i, azimuth phi_i) and h = normalize(wi + wo):
//  - the file's vndf warp, conditioned on (phi_i, theta_i), maps a point s of the unit square
//    to the half vector's unit coordinates u_h (for isotropic files, phi_h relative to phi_i);
//  - the stored colour is tabulated over s: value_c = max(0, rgb_c(s)) * ndf(u_h) / (4
//    sigma(u_wi)), where s = vndf^-1(u_h) (the factor ndf / (4 sigma) only when the file's
//    "jacobian" flag is set, as in Mitsuba 3; the brdf-loader applies it always, and every file
//    seen sets it);
//  - that value is f cos(theta_o), the BRDF times the cosine of the outgoing (sampled)
//    direction: the reference reader's eval documents itself as "f_r * cos", its sampler's
//    weight is value / pdf with no further cosine, Mitsuba 3 (whose eval includes the cosine)
//    returns it as is and pbrt-v4 divides it by the cosine. So eval() here returns
//    value / cos(theta_o): f without the cosine, as every scatterlab model does, and the
//    directional albedo integral of f cos equals the reference's.
//  - sampling draws s from the luminance warp (conditioned likewise), maps it through the vndf
//    warp to h and reflects wi; pdf = vndf_pdf(u_h) * luminance_pdf(s) / (2 pi^2 u_theta(h)
//    sin(theta_h) * 4 (wi . h)), the densities' change of variables from the square to the
//    half vector's solid angle and from there to wo.
// Warps are ParametricBilinear2D (the paper's Marginal2D) over the (phi_i, theta_i) grid.
//
// Files: RGB ("rgb", (P, T, 3, M, M)) or spectral ("spectra", (P, T, L, M, M) with
// "wavelengths" (L) in nm), reduced at load to linear Rec.709 by the CIE method of the metals
// (metal_reduction.h reflectanceRgb: exact, because interpolation and reduction are both
// linear in the samples); RGB is clamped at 0 after interpolation, as the reference does for
// out-of-gamut colour. Isotropic files have P <= 2 incident azimuths; anisotropic files cover
// 2 pi / reduction of azimuth: reduction 1 (the full circle), or, as Mitsuba 3 reads them, 2
// (phi_i in [-pi, 0]; the other half by rotating both directions by pi) and 4 (phi_i in [-pi,
// -pi/2]; the rest by mirroring x and y); any other coverage is rejected.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "materials/bsdf/bsdf.h"
#include "materials/core/parametric_bilinear_2d.h"
#include "materials/measured/tensor_file.h"

namespace scatterlab {

class RglBrdf final : public BsdfModel {
 public:
  // Validates every field the model uses (names, dtypes, shapes, grids, signs); throws
  // TensorFileError naming `source`, the field and what is allowed.
  RglBrdf(const TensorFile& file, const std::string& source);

  Rgb eval(const Vec3d& wi, const Vec3d& wo, TransportMode = TransportMode::Radiance) const override;
  double pdf(const Vec3d& wi, const Vec3d& wo, TransportMode = TransportMode::Radiance) const override;
  std::optional<BsdfSample> sample(const Vec3d& wi, double uLobe, const Vec2d& u,
                                   TransportMode = TransportMode::Radiance) const override;
  LobeFlags flags() const override { return LobeFlags::GlossyReflection; }
  // Measurements are not reciprocal, and the file does not make them so.
  bool isReciprocal() const override { return false; }

  // The reference reader's value, f cos(theta_o) (see above), and its pdf: what the tests
  // compare with the reader's own numbers.
  Rgb referenceValue(const Vec3d& wi, const Vec3d& wo) const;

  // The direction pairs at which the file stores its data: every tabulated incident direction
  // above the surface (each (phi_i, theta_i) node with theta_i < 90 degrees) with every node
  // of the colour grid mapped through the vndf warp to a half vector and reflected. Pairs
  // whose wo is not above the surface are left out and counted in `belowHorizon`.
  struct TabulatedPair {
    Vec3d wi, wo;
    size_t incident;  // index of the (phi_i, theta_i) node, phi_i major
    size_t node;      // index of the colour-grid node, row major
  };
  std::vector<TabulatedPair> tabulatedPairs(size_t* belowHorizon = nullptr) const;

  const std::string& description() const { return description_; }
  bool isotropic() const { return isotropic_; }
  bool spectral() const { return wavelengthCount_ > 0; }
  size_t wavelengthCount() const { return wavelengthCount_; }
  int reduction() const { return reduction_; }
  bool jacobian() const { return jacobian_; }
  // The incident polar angles the file tabulates, in radians (first and last).
  double thetaMin() const { return thetaMin_; }
  double thetaMax() const { return thetaMax_; }
  size_t incidentAzimuths() const { return luminance_.parameterGrids()[0].size(); }
  size_t incidentElevations() const { return luminance_.parameterGrids()[1].size(); }
  // The grids of the vndf and of the colour tables: rows (azimuth) x columns (elevation).
  size_t vndfRows() const { return vndf_.rows(); }
  size_t vndfColumns() const { return vndf_.columns(); }
  size_t colourRows() const { return luminance_.rows(); }
  size_t colourColumns() const { return luminance_.columns(); }

 private:
  // wi and wo mirrored into the azimuth range the file covers (reduction 2 and 4).
  struct Fold {
    double x = 1, y = 1;
    Vec3d apply(const Vec3d& w) const { return {w.x * x, w.y * y, w.z}; }
  };
  Fold foldFor(const Vec3d& wi) const;

  struct Angles {
    double thetaI, phiI;
    Vec2d uWi, uH;
    double sinThetaH;
  };
  Angles anglesOf(const Vec3d& wi, const Vec3d& h) const;
  // value / f cos, before the division by cos(theta_o); wi and wo already folded.
  Rgb valueAt(const Vec2d& s, const Angles& a, const ParametricBilinear2D::Blend& blend) const;
  double jacobianOf(const Angles& a, const Vec3d& wi, const Vec3d& h) const;

  ParametricBilinear2D ndf_, sigma_;       // values over the half vector's / wi's unit square
  ParametricBilinear2D vndf_, luminance_;  // densities conditioned on (phi_i, theta_i)
  ParametricBilinear2D rgb_;               // 3 channels conditioned on (phi_i, theta_i)
  std::string description_;
  bool isotropic_ = true, jacobian_ = true;
  int reduction_ = 1;
  size_t wavelengthCount_ = 0;
  double thetaMin_ = 0, thetaMax_ = 0;
};

// Reads and validates an RGL .bsdf file; throws TensorFileError naming the file and field.
std::unique_ptr<RglBrdf> readRglBrdf(const std::filesystem::path& path);

}  // namespace scatterlab
