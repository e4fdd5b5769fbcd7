// Bad RGL files: one message naming the file, the field and what is allowed, for each way a
// field can be wrong (docs/references.md, "RGL measured BRDFs"). The files are written by the
// synthesiser and then broken one field at a time.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>

#include "materials/measured/rgl_brdf.h"
#include "materials/measured/rgl_synthesis.h"
#include "materials/registry/spec_validation.h"
#include "measured_test_support.h"

namespace scatterlab {
namespace rgl_errors_test {

const TensorFile& validFile() {
  static const TensorFile file = [] {
    static const auto model = makeBsdf({{"type", "conductor"}, {"metal", "Cu"}, {"alpha", 0.3}});
    RglSynthesisOptions options;
    options.vndfResolution = 8;
    options.colourResolution = 6;
    options.thetaI = {0.0, 0.6, 1.2};
    return synthesizeRglFile(modelChannels(*model), options);
  }();
  return file;
}

std::string errorOf(const TensorFile& file) {
  try {
    RglBrdf brdf(file, "RGL BRDF file \"broken.bsdf\"");
  } catch (const TensorFileError& error) {
    return error.what();
  }
  return "";
}

void expectRejected(const TensorFile& file, const std::vector<std::string>& fragments) {
  const std::string message = errorOf(file);
  ASSERT_FALSE(message.empty()) << "no error";
  EXPECT_NE(message.find("broken.bsdf"), std::string::npos) << message;
  EXPECT_NE(message.find("allowed"), std::string::npos) << message;
  for (const std::string& fragment : fragments)
    EXPECT_NE(message.find(fragment), std::string::npos)
        << "\"" << fragment << "\" missing from: " << message;
}

// The field `name` with `values` in place of its own (same shape unless given).
TensorFile with(const std::string& name, std::vector<double> values, std::vector<uint64_t> shape = {},
                TensorDtype dtype = TensorDtype::Float32) {
  TensorFile file = validFile();
  const TensorField& old = *file.find(name);
  file.set(TensorField::fromValues(name, dtype, shape.empty() ? old.shape : shape, values));
  return file;
}

std::vector<double> valuesOf(const std::string& name) { return validFile().find(name)->values(); }

TEST(RglErrors, TheValidFileReads) { EXPECT_EQ(errorOf(validFile()), ""); }

TEST(RglErrors, MissingFields) {
  for (const char* name : {"theta_i", "phi_i", "ndf", "sigma", "vndf", "luminance", "jacobian"}) {
    TensorFile file = validFile();
    file.remove(name);
    expectRejected(file, {std::string("field \"") + name + "\"", "missing"});
  }
  TensorFile noColour = validFile();
  noColour.remove("rgb");
  expectRejected(noColour, {"field \"rgb\"", "missing", "\"spectra\" with \"wavelengths\""});
}

TEST(RglErrors, WrongDtype) {
  std::vector<double> integers(valuesOf("vndf").size(), 1.0);
  expectRejected(with("vndf", integers, {}, TensorDtype::Int32), {"field \"vndf\"", "int32", "float32"});
  expectRejected(with("jacobian", {1.0}, {}, TensorDtype::Float32),
                 {"field \"jacobian\"", "float32 (1)", "uint8"});
}

TEST(RglErrors, WrongShapes) {
  // luminance conditioned on a different number of elevations than theta_i
  std::vector<double> luminance = valuesOf("luminance");
  luminance.resize(luminance.size() / 3 * 2);
  expectRejected(with("luminance", luminance, {1, 2, 6, 6}),
                 {"field \"luminance\"", "(1, 2, 6, 6)", "(1, 3, "});
  // rgb with 4 channels
  std::vector<double> rgb = valuesOf("rgb");
  rgb.resize(rgb.size() / 3 * 4, 0.1);
  expectRejected(with("rgb", rgb, {1, 3, 4, 6, 6}), {"field \"rgb\"", "(1, 3, 4, 6, 6)", "(1, 3, 3, 6, 6)"});
  // rgb on another grid than the luminance
  std::vector<double> coarse(1 * 3 * 3 * 5 * 5, 0.1);
  expectRejected(with("rgb", coarse, {1, 3, 3, 5, 5}), {"field \"rgb\"", "(1, 3, 3, 5, 5)"});
  // ndf with one dimension
  expectRejected(with("ndf", valuesOf("ndf"), {valuesOf("ndf").size()}), {"field \"ndf\"", "2-D"});
  // a 1-row vndf: bilinear interpolation needs 2 x 2
  expectRejected(with("vndf", std::vector<double>(3 * 8, 1.0), {1, 3, 1, 8}),
                 {"field \"vndf\"", "(1, 3, 1, 8)"});
  // jacobian with two entries
  expectRejected(with("jacobian", {1.0, 1.0}, {2}, TensorDtype::UInt8), {"field \"jacobian\"", "uint8 (2)"});
}

TEST(RglErrors, WrongValues) {
  std::vector<double> sigma = valuesOf("sigma");
  sigma[5] = 0.0;
  expectRejected(with("sigma", sigma), {"field \"sigma\"", "flat index 5", "positive"});
  std::vector<double> ndf = valuesOf("ndf");
  ndf[2] = -1.0;
  expectRejected(with("ndf", ndf), {"field \"ndf\"", "flat index 2", "non-negative"});
  std::vector<double> vndf = valuesOf("vndf");
  vndf[7] = -0.5;
  expectRejected(with("vndf", vndf), {"field \"vndf\"", "negative"});
  std::vector<double> luminance(valuesOf("luminance").size(), 0.0);
  expectRejected(with("luminance", luminance), {"field \"luminance\"", "no positive integral"});
  expectRejected(with("theta_i", {0.0, 1.2, 0.6}), {"field \"theta_i\"", "does not increase at index 2"});
  expectRejected(with("theta_i", {0.0, 0.6, 2.0}),
                 {"field \"theta_i\"", "value 2 at index 2", "out of range"});
  expectRejected(with("jacobian", {2.0}, {}, TensorDtype::UInt8), {"field \"jacobian\"", "is 2", "0 or 1"});
}

// phi_i covering a third of the circle: a reduction scatterlab does not read.
TEST(RglErrors, UnsupportedReduction) {
  const auto model = makeBsdf({{"type", "conductor"}, {"metal", "Cu"}, {"alpha", {0.2, 0.3}}});
  RglSynthesisOptions options;
  options.vndfResolution = 8;
  options.colourResolution = 6;
  options.thetaI = {0.0, 0.6, 1.2};
  options.phiI = {-Pi, -Pi + Pi / 3, -Pi + 2 * Pi / 3};
  const TensorFile file = synthesizeRglFile(modelChannels(*model), options);
  expectRejected(file, {"field \"phi_i\"", "reduction 3", "does not read", "[-pi, 0] (reduction 2)"});
  // A half circle that does not start at -pi.
  options.phiI = {0.0, Pi / 2, Pi};
  expectRejected(synthesizeRglFile(modelChannels(*model), options),
                 {"field \"phi_i\"", "does not start at -pi"});
}

TEST(RglErrors, SpectralWithoutVisibleWavelengths) {
  TensorFile file = validFile();
  file.remove("rgb");
  const std::vector<double> rgb = valuesOf("rgb");
  file.set(TensorField::fromValues("spectra", TensorDtype::Float32, {1, 3, 3, 6, 6}, rgb));
  file.set(
      TensorField::fromValues("wavelengths", TensorDtype::Float32, {3}, std::vector<double>{900, 950, 1000}));
  expectRejected(file, {"field \"wavelengths\"", "visible range"});
  file.set(TensorField::fromValues("wavelengths", TensorDtype::Float32, {2}, std::vector<double>{500, 600}));
  expectRejected(file, {"field \"spectra\"", "(1, 3, 3, 6, 6)", "(1, 3, 2 (the wavelengths), 6, 6)"});
}

// The container's own errors reach the caller with the path: a file cut short.
TEST(RglErrors, TruncatedFileNamesThePath) {
  const auto path = measured_test::scratchPath("truncated") += ".bsdf";
  std::vector<std::byte> bytes = serializeTensorFile(validFile());
  bytes.resize(bytes.size() - 100);
  std::ofstream(path, std::ios::binary)
      .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
  try {
    readRglBrdf(path);
    FAIL() << "no error";
  } catch (const TensorFileError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find(path.string()), std::string::npos) << message;
    EXPECT_NE(message.find("runs past the end"), std::string::npos) << message;
  }
}

}  // namespace rgl_errors_test
}  // namespace scatterlab
