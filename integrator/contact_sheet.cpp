#include "integrator/contact_sheet.h"

#include <cmath>
#include <stdexcept>

#include "integrator/bitmap_font.h"

namespace scatterlab {

int labelStripHeight(int scale) { return (GlyphHeight + 4) * scale; }

namespace {

// The longest prefix of `label` (plus "..") that fits in `width` pixels at `scale`.
std::string fitLabel(const std::string& label, int width, int scale) {
  if (textWidth(label, scale) <= width) return label;
  const int fits = (width / scale + 1) / GlyphAdvance;  // characters that fit
  if (fits <= 2) return label.substr(0, std::max(fits, 0));
  return label.substr(0, size_t(fits - 2)) + "..";
}

}  // namespace

Image composeContactSheet(const std::vector<ContactSheetEntry>& entries, const ContactSheetLayout& layout) {
  if (entries.empty()) throw std::invalid_argument("composeContactSheet: no entries");
  for (const ContactSheetEntry& entry : entries)
    if (!entry.image || entry.image->channels() != 3 ||
        entry.image->width() != entries.front().image->width() ||
        entry.image->height() != entries.front().image->height())
      throw std::invalid_argument("composeContactSheet: every entry needs a 3-channel image of one size");
  const int count = int(entries.size());
  const int columns =
      layout.columns > 0 ? std::min(layout.columns, count) : int(std::ceil(std::sqrt(double(count))));
  const int rows = (count + columns - 1) / columns;
  const int cellWidth = entries.front().image->width(), cellHeight = entries.front().image->height();
  const int scale = layout.labelScale > 0 ? layout.labelScale : (cellWidth < 192 ? 1 : 2);
  const int strip = labelStripHeight(scale), gap = layout.gap;
  const int width = gap + columns * (cellWidth + gap), height = gap + rows * (cellHeight + strip + gap);
  Image sheet(width, height, 3, float(ContactSheetPaper));
  for (int i = 0; i < count; ++i) {
    const int left = gap + (i % columns) * (cellWidth + gap),
              top = gap + (i / columns) * (cellHeight + strip + gap);
    const Image& image = *entries[i].image;
    for (int y = 0; y < cellHeight; ++y)
      for (int x = 0; x < cellWidth; ++x) sheet.setRgb(left + x, top + y, image.rgb(x, y));
    const std::string label = fitLabel(entries[i].label, cellWidth, scale);
    const int textLeft = left + (cellWidth - textWidth(label, scale)) / 2;
    drawText(sheet, textLeft, top + cellHeight + 2 * scale, label, Rgb(ContactSheetInk), scale);
  }
  return sheet;
}

}  // namespace scatterlab
