// Contact sheets and their labels: the grid's size, every image copied in place, the label
// drawn in the strip beneath its cell (ink where the font has it, centred), long labels cut,
// and the bitmap font's coverage.
#include <gtest/gtest.h>

#include "integrator/bitmap_font.h"
#include "integrator/contact_sheet.h"

namespace scatterlab {
namespace contact_sheet_test {

// The number of pixels of the sheet's rectangle [x0, x1) x [y0, y1) drawn in ink.
int inkIn(const Image& image, int x0, int y0, int x1, int y1) {
  int ink = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) ink += image.rgb(x, y) == Rgb(ContactSheetInk);
  return ink;
}

TEST(BitmapFont, CoversLettersDigitsAndMaterialPunctuation) {
  for (char c = 'A'; c <= 'Z'; ++c) EXPECT_TRUE(hasGlyph(c)) << c;
  for (char c = 'a'; c <= 'z'; ++c) EXPECT_TRUE(hasGlyph(c)) << c;
  for (char c = '0'; c <= '9'; ++c) EXPECT_TRUE(hasGlyph(c)) << c;
  for (const char c : std::string(" -_.,:/()[]+=%#'\"!?*<>@&;")) EXPECT_TRUE(hasGlyph(c)) << c;
  EXPECT_FALSE(hasGlyph('~'));
  EXPECT_EQ(textWidth("ab", 2), (2 * GlyphAdvance - 1) * 2);
}

TEST(BitmapFont, DrawsDistinctGlyphs) {
  // Every pair of glyphs differs somewhere (no copy-paste slip in the table).
  const std::string chars = "ABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789-_.,:/()[]+=%#'\"!?*<>@&;";
  std::vector<std::vector<float>> drawn;
  for (const char c : chars) {
    Image image(GlyphWidth, GlyphHeight);
    drawText(image, 0, 0, std::string(1, c), Rgb(1.0));
    drawn.push_back(image.data());
    EXPECT_GT(inkIn(image, 0, 0, GlyphWidth, GlyphHeight), 0) << c;
  }
  for (size_t i = 0; i < drawn.size(); ++i)
    for (size_t j = i + 1; j < drawn.size(); ++j)
      EXPECT_NE(drawn[i], drawn[j]) << chars[i] << " and " << chars[j];
}

TEST(ContactSheet, PlacesImagesAndLabels) {
  std::vector<Image> images;
  for (int i = 0; i < 5; ++i) images.emplace_back(40, 30, 3, 0.1f * float(i + 1));
  std::vector<ContactSheetEntry> entries;
  for (int i = 0; i < 5; ++i) entries.push_back({&images[i], "mat " + std::to_string(i)});
  ContactSheetLayout layout;
  layout.columns = 3;
  const Image sheet = composeContactSheet(entries, layout);
  const int strip = labelStripHeight(1), gap = layout.gap;
  EXPECT_EQ(sheet.width(), gap + 3 * (40 + gap));
  EXPECT_EQ(sheet.height(), gap + 2 * (30 + strip + gap));
  for (int i = 0; i < 5; ++i) {
    const int left = gap + (i % 3) * (40 + gap), top = gap + (i / 3) * (30 + strip + gap);
    EXPECT_FLOAT_EQ(sheet.pixel(left + 7, top + 11)[0], 0.1f * float(i + 1)) << "cell " << i;
    // The label's ink lies in the strip, centred: as much on the left half as text allows.
    const int ink = inkIn(sheet, left, top + 30, left + 40, top + 30 + strip);
    EXPECT_GT(ink, 20) << "cell " << i;
    EXPECT_EQ(inkIn(sheet, left, top, left + 40, top + 30), 0) << "cell " << i;
  }
  // The sixth cell of the grid is empty paper.
  EXPECT_EQ(inkIn(sheet, gap + 2 * (40 + gap), gap + 30 + strip + gap, sheet.width(), sheet.height()), 0);
}

TEST(ContactSheet, CutsLongLabels) {
  const Image image(30, 20);
  const Image sheet = composeContactSheet({{&image, "a-very-long-material-name"}});
  // 30 pixels hold 5 glyphs: "a-v" and "..": the last ink column is inside the cell.
  const int gap = ContactSheetLayout{}.gap;
  EXPECT_EQ(inkIn(sheet, gap + 30, 0, sheet.width(), sheet.height()), 0);
  EXPECT_GT(inkIn(sheet, gap, gap + 20, gap + 30, sheet.height()), 0);
}

TEST(ContactSheet, RejectsMixedSizes) {
  const Image a(10, 10), b(12, 10);
  EXPECT_THROW(composeContactSheet({{&a, "a"}, {&b, "b"}}), std::invalid_argument);
  EXPECT_THROW(composeContactSheet({}), std::invalid_argument);
}

}  // namespace contact_sheet_test
}  // namespace scatterlab
