// The RGL reader on files the writer makes (rgl_synthesis.h): what no shipped file exercises.
// At the grid's nodes such a file reproduces its function exactly, so these tests pin the
// index conventions (phi_i before theta_i, rows = azimuth, columns = elevation, the channel
// axis, the isotropic relative azimuth), anisotropic files (reductions 1, 2 and 4) and spectral
// colour reduced by the CIE method (docs/references.md, "RGL measured BRDFs").
#include <gtest/gtest.h>

#include <cmath>

#include "materials/bsdf/metal_reduction.h"
#include "materials/measured/rgl_brdf.h"
#include "materials/measured/rgl_synthesis.h"
#include "materials/registry/spec_validation.h"
#include "measured_test_support.h"

namespace scatterlab {
namespace rgl_synthesised_test {

using nlohmann::json;

// float32 storage of the colour (relative rounding 6e-8), and of the node angles that the
// reader recomputes from the direction, through a value that changes by a few per cent per
// degree: 1e-5 relative bounds both with a wide margin.
constexpr double NodeTolerance = 1e-5;

const json AnisotropicGgx = {
    {"type", "conductor"}, {"metal", "Au"}, {"distribution", "ggx"}, {"alpha", {0.15, 0.4}}};

RglBrdf read(const TensorFile& file) { return RglBrdf(file, "synthesised"); }

// Every colour-grid node of every incident node whose direction is above the horizon: the
// reader's f cos equals the function's, channel by channel.
template <typename Expected> void expectNodesReproduced(const TensorFile& file, const RglBrdf& brdf,
                                                        const Expected& expected, size_t stride) {
  const size_t P = file.find("phi_i")->shape[0], T = file.find("theta_i")->shape[0];
  const size_t M = file.find("luminance")->shape[2];
  int compared = 0;
  for (size_t p = 0; p < P; ++p)
    for (size_t t = 0; t < T; ++t) {
      const Vec3d wi = gridIncident(file, p, t);
      if (!(wi.z > 1e-3)) continue;
      for (size_t r = 0; r < M; r += stride)
        for (size_t c = 1; c < M; c += stride) {  // column 0 is the pole (rgl_synthesis.h)
          const auto wo = sampledOutgoing(file, p, t, r, c);
          if (!wo) continue;
          const Rgb want = expected(wi, *wo), got = brdf.eval(wi, *wo) * wo->z;
          const double scale = std::max({want.x, want.y, want.z, 1e-12});
          for (int k = 0; k < 3; ++k)
            ASSERT_NEAR(got[k], want[k], NodeTolerance * scale)
                << "phi_i node " << p << " theta_i node " << t << " colour node (" << r << ", " << c
                << ") channel " << k;
          ++compared;
        }
    }
  EXPECT_GT(compared, 50);
}

TEST(RglSynthesised, IsotropicFileReproducesItsModelAtTheNodes) {
  const auto model = makeBsdf({{"type", "conductor"}, {"metal", "Cu"}, {"alpha", 0.3}});
  const TensorFile file = synthesizeRglFile(modelChannels(*model), {});
  const RglBrdf brdf = read(file);
  EXPECT_TRUE(brdf.isotropic());
  expectNodesReproduced(
      file, brdf, [&](const Vec3d& wi, const Vec3d& wo) { return model->eval(wi, wo) * wo.z; }, 1);
}

// Away from the nodes, interpolation: a smooth lobe stays within a few per cent of its model
// (the value is the warp's interpolation of the product of colour and ndf / sigma; the bound
// is an interpolation error, loose on purpose, checking that nothing is off by a cell).
TEST(RglSynthesised, IsotropicFileInterpolatesBetweenNodes) {
  const auto model = makeBsdf({{"type", "conductor"}, {"metal", "Cu"}, {"alpha", 0.3}});
  const RglBrdf brdf = read(synthesizeRglFile(modelChannels(*model), {}));
  for (const auto& [wi, wo] : {std::pair{directionFromDegrees(20, 40), directionFromDegrees(25, 215)},
                               std::pair{directionFromDegrees(50, -70), directionFromDegrees(45, 120)}}) {
    const Rgb want = model->eval(wi, wo), got = brdf.eval(wi, wo);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(got[k], want[k], 0.1 * want[k]) << k;
  }
}

RglSynthesisOptions anisotropicGrid(std::vector<double> phi) {
  RglSynthesisOptions o;
  o.phiI = std::move(phi);
  o.thetaI = {0.0, 0.5, 0.9, 1.2};
  o.vndfResolution = 32;
  o.colourResolution = 12;
  return o;
}

std::vector<double> evenGrid(double lo, double hi, int n) {
  std::vector<double> grid;
  for (int i = 0; i < n; ++i) grid.push_back(lo + (hi - lo) * i / (n - 1));
  return grid;
}

TEST(RglSynthesised, AnisotropicFileReproducesItsModelAtTheNodes) {
  const auto model = makeBsdf(AnisotropicGgx);
  const TensorFile file = synthesizeRglFile(modelChannels(*model), anisotropicGrid(evenGrid(-Pi, Pi, 9)));
  const RglBrdf brdf = read(file);
  EXPECT_FALSE(brdf.isotropic());
  EXPECT_EQ(brdf.reduction(), 1);
  EXPECT_EQ(brdf.incidentAzimuths(), 9u);
  expectNodesReproduced(
      file, brdf, [&](const Vec3d& wi, const Vec3d& wo) { return model->eval(wi, wo) * wo.z; }, 2);
}

// Rotating both directions about the normal changes an anisotropic file's value as it changes
// the model's, and leaves an isotropic file's alone: the reader uses absolute azimuths for the
// one and relative for the other.
TEST(RglSynthesised, AnisotropyFollowsTheIncidentAzimuth) {
  const auto model = makeBsdf(AnisotropicGgx);
  const RglBrdf brdf = read(synthesizeRglFile(modelChannels(*model), anisotropicGrid(evenGrid(-Pi, Pi, 9))));
  // wo 25 degrees of azimuth off the mirror direction: the half vector leaves the plane of
  // incidence across it, along y (alpha 0.4, a wide lobe) for wi in the x-z plane and along x
  // (alpha 0.15, narrow) for wi in the y-z plane.
  const double theta = degrees(0.5);  // on the file's theta_i grid
  const Vec3d wi0 = directionFromDegrees(theta, 0), wo0 = directionFromDegrees(theta, 155);
  const Vec3d wi1 = directionFromDegrees(theta, 90), wo1 = directionFromDegrees(theta, 245);
  const double modelRatio = model->eval(wi0, wo0).y / model->eval(wi1, wo1).y;
  const double fileRatio = brdf.eval(wi0, wo0).y / brdf.eval(wi1, wo1).y;
  EXPECT_GT(modelRatio, 2.0);
  EXPECT_NEAR(fileRatio, modelRatio, 0.05 * modelRatio);  // interpolation error between nodes

  const auto isotropicModel = makeBsdf({{"type", "conductor"}, {"metal", "Au"}, {"alpha", 0.3}});
  const RglBrdf isotropic = read(synthesizeRglFile(modelChannels(*isotropicModel), {}));
  const Rgb a = isotropic.eval(wi0, wo0), b = isotropic.eval(wi1, wo1);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(a[k], b[k], 1e-12 * a[k]);
}

// Reductions 2 and 4 store a half or a quarter of the incident azimuths; the reader rotates or
// mirrors the rest into them. An aligned anisotropic GGX has both symmetries, so at mirrored
// nodes the reduced file reproduces the model everywhere.
TEST(RglSynthesised, ReducedAzimuthRangesUnfoldBySymmetry) {
  const auto model = makeBsdf(AnisotropicGgx);
  for (const auto& [reduction, hi] : {std::pair{2, 0.0}, std::pair{4, -PiOver2}}) {
    const TensorFile file = synthesizeRglFile(modelChannels(*model), anisotropicGrid(evenGrid(-Pi, hi, 5)));
    const RglBrdf brdf = read(file);
    EXPECT_EQ(brdf.reduction(), reduction);
    const size_t P = file.find("phi_i")->shape[0];
    int compared = 0;
    // Interior azimuth nodes: float32 rounding puts the end nodes' directions a hair outside
    // the sector (-pi rounds to y = +4e-8), where the fold sends them to the other end.
    for (size_t p = 1; p + 1 < P; ++p)
      for (size_t t = 1; t < 4; ++t)
        for (size_t r = 0; r < 12; r += 3)
          for (size_t c = 1; c < 12; c += 3) {
            const Vec3d wi = gridIncident(file, p, t);
            const auto wo = sampledOutgoing(file, p, t, r, c);
            if (!wo) continue;
            // The stored node seen from the other quadrants: mirrored in x, in y, and both.
            for (const Vec2d& mirror : {Vec2d(-1, 1), Vec2d(1, -1), Vec2d(-1, -1)}) {
              const Vec3d wiM(wi.x * mirror.x, wi.y * mirror.y, wi.z),
                  woM(wo->x * mirror.x, wo->y * mirror.y, wo->z);
              const Rgb want = model->eval(wiM, woM) * woM.z, got = brdf.eval(wiM, woM) * woM.z;
              if (reduction == 2 && mirror.x * mirror.y < 0) continue;  // rotations only
              for (int k = 0; k < 3; ++k)
                ASSERT_NEAR(got[k], want[k], NodeTolerance * want[k] + 1e-12)
                    << "reduction " << reduction << " mirror " << mirror.x << " " << mirror.y << " node " << p
                    << " " << t << " " << r << " " << c << " wi " << wi.x << " " << wi.y << " " << wi.z;
              EXPECT_NEAR(brdf.pdf(wiM, woM), brdf.pdf(wi, *wo), 1e-9 * brdf.pdf(wi, *wo));
              ++compared;
            }
          }
    EXPECT_GT(compared, 40) << "reduction " << reduction;
  }
}

// A spectral file: each channel is a wavelength. The value at every node is a known spectrum
// times the model's luminance, so the reader's RGB must be that spectrum's CIE RGB
// (metal_reduction.h) times the luminance; a flat spectrum of 0.5 must give exactly grey 0.5.
TEST(RglSynthesised, SpectralFileIsReducedToRgbByTheCieMethod) {
  const auto model = makeBsdf({{"type", "conductor"}, {"metal", "Cu"}, {"alpha", 0.3}});
  const std::vector<double> wavelengths = evenGrid(360, 830, 48);
  // A reddish reflectance, smooth in wavelength.
  const auto reflectance = [](double lambda) { return 0.2 + 0.6 / (1 + std::exp(-(lambda - 600) / 25)); };
  Spectrum spectrum{wavelengths, {}};
  for (double l : wavelengths) spectrum.values.push_back(double(float(reflectance(l))));
  const Rgb expectedColour = reflectanceRgb(spectrum);

  const auto luminanceOf = [&](const Vec3d& wi, const Vec3d& wo) {
    const Rgb f = model->eval(wi, wo) * wo.z;
    return 0.2126 * f.x + 0.7152 * f.y + 0.0722 * f.z;
  };
  for (const bool flat : {false, true}) {
    RglChannelValues channels{[&](const Vec3d& wi, const Vec3d& wo, std::span<double> out) {
                                const double y = luminanceOf(wi, wo);
                                for (size_t l = 0; l < out.size(); ++l)
                                  out[l] = y * (flat ? 0.5 : spectrum.values[l]);
                              },
                              [](std::span<const double> c) { return c[c.size() / 2]; }};
    RglSynthesisOptions options;
    options.wavelengths = wavelengths;
    const TensorFile file = synthesizeRglFile(channels, options);
    const RglBrdf brdf = read(file);
    EXPECT_TRUE(brdf.spectral());
    EXPECT_EQ(brdf.wavelengthCount(), 48u);
    const Rgb colour = flat ? Rgb(0.5) : expectedColour;
    expectNodesReproduced(
        file, brdf, [&](const Vec3d& wi, const Vec3d& wo) { return colour * luminanceOf(wi, wo); }, 2);
  }
  // Reddish: red above green above blue, all inside (0, 1).
  EXPECT_GT(expectedColour.x, expectedColour.y);
  EXPECT_GT(expectedColour.y, expectedColour.z);
  EXPECT_GT(expectedColour.z, 0.0);
}

// Without the jacobian flag the stored colour is the value itself (Mitsuba 3's reading).
TEST(RglSynthesised, JacobianFlagOffStoresTheValueItself) {
  const auto model = makeBsdf({{"type", "conductor"}, {"metal", "Cu"}, {"alpha", 0.3}});
  RglSynthesisOptions options;
  options.jacobian = false;
  const TensorFile file = synthesizeRglFile(modelChannels(*model), options);
  const RglBrdf brdf = read(file);
  EXPECT_FALSE(brdf.jacobian());
  expectNodesReproduced(
      file, brdf, [&](const Vec3d& wi, const Vec3d& wo) { return model->eval(wi, wo) * wo.z; }, 2);
}

// float16 and float64 arrays read as float32 ones do (the reference readers take float32 only).
TEST(RglSynthesised, OtherFloatingPointDtypesReadAlike) {
  const auto model = makeBsdf({{"type", "conductor"}, {"metal", "Cu"}, {"alpha", 0.3}});
  const TensorFile file = synthesizeRglFile(modelChannels(*model), {});
  TensorFile wide = file;
  for (const TensorField& field : file.fields())
    if (field.dtype == TensorDtype::Float32)
      wide.set(TensorField::fromValues(field.name, TensorDtype::Float64, field.shape, field.values()));
  const RglBrdf a = read(file), b = read(wide);
  const Vec3d wi = directionFromDegrees(35, 10), wo = directionFromDegrees(30, 200);
  EXPECT_EQ(a.eval(wi, wo), b.eval(wi, wo));
  EXPECT_EQ(a.pdf(wi, wo), b.pdf(wi, wo));
}

}  // namespace rgl_synthesised_test
}  // namespace scatterlab
