// A contact sheet: several renders of one size in a grid, each with a label strip beneath it
// (text in the embedded bitmap font, bitmap_font.h), as one float image that can be written as
// EXR or PNG like any render.
#pragma once

#include <string>
#include <vector>

#include "integrator/image.h"

namespace scatterlab {

struct ContactSheetEntry {
  const Image* image = nullptr;  // 3 channels, every entry the same size
  std::string label;
};

struct ContactSheetLayout {
  int columns = 0;     // 0: ceil(sqrt(entries))
  int gap = 4;         // pixels between cells and around the sheet
  int labelScale = 0;  // font pixel size; 0: 1 for cells narrower than 192 pixels, else 2
};

// The labels' colour and the background's, in linear RGB.
inline constexpr double ContactSheetInk = 1.0;
inline constexpr double ContactSheetPaper = 0.02;

// A label too long for its cell is cut and ends in "..". std::invalid_argument for no
// entries, a missing image or images of different sizes.
Image composeContactSheet(const std::vector<ContactSheetEntry>& entries,
                          const ContactSheetLayout& layout = {});

// Height of the label strip under each cell at `scale`.
int labelStripHeight(int scale);

}  // namespace scatterlab
