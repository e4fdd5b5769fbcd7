#include "materials/measured/measured_file.h"

#include <string>

#include "materials/measured/merl_io.h"
#include "materials/measured/rgl_brdf.h"
#include "materials/measured/tabulated_brdf.h"
#include "materials/registry/material_model.h"

namespace scatterlab {

namespace {

std::unique_ptr<BsdfModel> buildMeasured(const MaterialParameters& p) {
  return readMeasuredFile(p.path("file"));
}

}  // namespace

std::optional<MeasuredFormat> measuredFormatOf(const std::filesystem::path& path) {
  if (isTensorFile(path)) return MeasuredFormat::Rgl;
  if (isMerlFile(path)) return MeasuredFormat::Merl;
  return std::nullopt;
}

std::string notMeasuredReason(const std::filesystem::path& path) {
  try {
    readMerl(path);
  } catch (const MerlError& error) {
    return error.what();
  }
  return "MERL file \"" + path.string() + "\": readable after all";
}

std::string measuredFileProblem(const std::string& readerMessage) {
  return "material key \"file\": " + readerMessage +
         "; allowed: a MERL BRDF file (90 x 90 x 180 cells, 34992012 bytes) or an RGL .bsdf tensor file";
}

std::unique_ptr<BsdfModel> readMeasuredFile(const std::filesystem::path& path) {
  try {
    if (isTensorFile(path)) return readRglBrdf(path);
    return std::make_unique<TabulatedBrdf>(readMerl(path));
  } catch (const TensorFileError& error) {
    throw MaterialError(measuredFileProblem(error.what()));
  } catch (const MerlError& error) {
    throw MaterialError(measuredFileProblem(error.what()));
  }
}

MaterialModel measuredModel() {
  return {
      .type = "measured",
      .description =
          "Measured BRDF read from a file, its format told by content: a MERL table (isotropic, "
          "interpolated in half/diff angles, sampled from tabulated half-vector distributions) or an RGL "
          "tensor file (isotropic or anisotropic, RGB or spectral, sampled through its own warps); exact pdf",
      .citation =
          "Matusik et al. 2003, A Data-Driven Reflectance Model; Rusinkiewicz 1998, A New Change of "
          "Variables for Efficient BRDF Representation; Dupuy & Jakob 2018, An Adaptive Parameterization "
          "for Efficient Material Acquisition and Rendering",
      .parameters = {{.name = "file",
                      .kind = ParameterKind::Path,
                      .description =
                          "MERL .binary file (`scatterlab synth` makes them; missing cells, negative, take "
                          "the nearest measured value along theta_d) or RGL .bsdf file (the RGL material "
                          "database's tensor files)",
                      .required = true}},
      .alternatives = {},
      .build = buildMeasured,
  };
}

}  // namespace scatterlab
