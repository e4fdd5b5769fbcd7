// RGL tensor files made from a known reflectance (a model, or any function), so that the reader
// can be tested on what no shipped file has: anisotropic grids (several incident azimuths,
// reductions 2 and 4), spectral colour, other resolutions, and exact expectations.
//
// Layout as the database's files (rgl_brdf.h, docs/references.md "RGL measured BRDFs"); the
// contents are chosen so that the reader reproduces the function EXACTLY at known points:
//  - ndf and sigma are positive functions of the unit coordinates, single-valued at the pole
//    and periodic in azimuth, piecewise bilinear on their grid so that interpolation
//    reproduces them everywhere (ndf = 0.5 + u_theta (1 + 0.5 tri(u_phi)), sigma = 0.3 +
//    u_theta (0.2 + 0.1 tri(u_phi)), tri the triangle wave that is 1 at phi = 0 and 0 at
//    +-pi; sigma without the azimuth term for isotropic files); the colour table absorbs them
//    (rgb = value * 4 sigma / ndf);
//  - the vndf of each incident direction is proportional to the luminance of the value times
//    d(omega_o) / d(u_h) (the density a perfect sampler would have), plus a floor of 1% of its
//    mean so that every half vector keeps a place on the square;
//  - the luminance warp is proportional to the luminance of the colour table plus the same
//    floor;
//  - every array is stored as float32, and the colour is computed through the warp the reader
//    will build from those float32 values: at an incident direction on the (phi_i, theta_i)
//    grid and a point s on the colour grid, the reader's value equals the function's at the
//    outgoing direction sampledOutgoing() returns, up to float32 rounding of the value itself.
//    (Except on the colour grid's first column, which the warp maps to the pole theta_h = 0,
//    where every row is the same direction pair and the reader reads one of them.)
#pragma once

#include <functional>
#include <span>
#include <string>
#include <vector>

#include "materials/bsdf/bsdf.h"
#include "materials/measured/tensor_file.h"

namespace scatterlab {

struct RglSynthesisOptions {
  // Incident grids in radians: theta_i in [0, pi/2]; phi_i with one entry (isotropic) or
  // covering [-pi, pi], [-pi, 0] or [-pi, -pi/2] (reductions 1, 2, 4).
  std::vector<double> thetaI{0.0, 0.35, 0.7, 1.0, 1.25, 1.45};
  std::vector<double> phiI{0.0};
  size_t ndfRows = 17, ndfColumns = 16;  // ndf and sigma grids (rows odd: u_phi = 0.5 a row)
  size_t vndfResolution = 48;
  size_t colourResolution = 24;
  // Empty: an RGB file ("rgb"); otherwise a spectral file ("spectra", "wavelengths") whose
  // channels are these wavelengths in nm.
  std::vector<double> wavelengths{};
  std::string description = "synthesised by scatterlab";
  bool jacobian = true;
};

// The value to tabulate at (wi, wo), both above the surface: f cos(theta_o) per channel (3
// for RGB, one per wavelength for a spectral file), and the luminance the warps follow.
struct RglChannelValues {
  std::function<void(const Vec3d& wi, const Vec3d& wo, std::span<double> channels)> value;
  std::function<double(std::span<const double> channels)> luminance;
};

// f cos(theta_o) of a model in RGB, luminance with Rec.709 weights.
RglChannelValues modelChannels(const BsdfModel& model);

TensorFile synthesizeRglFile(const RglChannelValues& values, const RglSynthesisOptions& options);

// For tests: the outgoing direction whose value the file stores at colour-grid point
// (row, column) for the incident direction at grid nodes (phiIndex, thetaIndex), found
// through the reader's own vndf warp of `file`; nullopt when it is below the horizon.
std::optional<Vec3d> sampledOutgoing(const TensorFile& file, size_t phiIndex, size_t thetaIndex, size_t row,
                                     size_t column);

// The incident direction at grid nodes (phiIndex, thetaIndex) of `file`.
Vec3d gridIncident(const TensorFile& file, size_t phiIndex, size_t thetaIndex);

}  // namespace scatterlab
