// The material registry's "measured" type: a BSDF read from a measured file whose format is
// told by its content, never by its name: an RGL tensor file (it starts with "tensor_file\0";
// rgl_brdf.h) or a MERL table (it starts with the int32 header 90, 90, 180; tabulated_brdf.h).
// `{"type": "measured", "file": PATH}` reads either, and so does a bare PATH given as a
// material on the command line (registry/material_file.h).
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "materials/bsdf/bsdf.h"

namespace scatterlab {

enum class MeasuredFormat { Merl, Rgl };

// The format of the file at `path` from its first bytes; nullopt when it is neither (or cannot
// be opened).
std::optional<MeasuredFormat> measuredFormatOf(const std::filesystem::path& path);

// For a file that measuredFormatOf does not recognise: what the MERL reader finds wrong with
// it, in its own words (naming the file: its size, or its header); an RGL file is recognised
// by its first 12 bytes alone, so they are not the tensor_file magic.
std::string notMeasuredReason(const std::filesystem::path& path);

// Reads the measured file at `path`: an RGL file when it starts with the tensor_file magic,
// else a MERL table (whose reader says what is wrong with anything else). Throws MaterialError
// "material key \"file\": ..." with the reader's message (naming the file and the field or
// header) and what is allowed.
std::unique_ptr<BsdfModel> readMeasuredFile(const std::filesystem::path& path);

// The message of a measured file that cannot be read: "material key \"file\": " + the
// reader's message + what is allowed (the registry's and the lab's words alike).
std::string measuredFileProblem(const std::string& readerMessage);

struct MaterialModel;

// The material registry's "measured" model (materials/registry/model_list.h).
MaterialModel measuredModel();

}  // namespace scatterlab
