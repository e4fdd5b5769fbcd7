// What a chi-square test leaves behind for a person to look at (docs/validation.md section 1, "On
// failure"): the observed, expected and (O - E) / sqrt(E) tables as PNG heatmaps, plus the raw
// tables as JSON; for any binning laid out as a Table2D (the sphere's cos(theta) x phi, the
// radius bins, the probe's rings x sectors), described in words by `layout`.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "validation/chi_square.h"

namespace scatterlab {

// A label as a file-name stem: letters, digits, '-', '_' and '.' kept, the rest '_', at most
// 80 characters.
std::string safeFileStem(const std::string& label);

// Writes STEM_observed.png, STEM_expected.png, STEM_residual.png and STEM_tables.json into
// `dir` (created if missing; files written atomically). With `consistencyMaxError`, also
// STEM_consistency.png (scaled so that `consistencyTolerance` sits a tenth of the way up) and
// its table.
// The endings of the names writeChiSquareImages gives its files ("_observed.png", ...).
std::vector<std::string> chiSquareImageSuffixes();

void writeChiSquareImages(const std::filesystem::path& dir, const std::string& stem,
                          const ChiSquareResult& chi, const std::string& layout,
                          const Table2D* consistencyMaxError = nullptr, double consistencyTolerance = 0.0);

}  // namespace scatterlab
