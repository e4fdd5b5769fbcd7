// A tiny embedded bitmap font for labels on contact sheets: 5 x 7 pixel glyphs in a 6 x 8
// cell, drawn in the style of the classic HD44780 LCD character set (the glyphs are written
// out in bitmap_font.cpp as rows of '#' and '.'). It covers digits, the Latin capitals and the
// punctuation material names use; lower-case letters are drawn as capitals, and any other
// character as a hollow box, so a label never loses its length.
#pragma once

#include <string_view>

#include "integrator/image.h"

namespace scatterlab {

inline constexpr int GlyphWidth = 5, GlyphHeight = 7;
inline constexpr int GlyphAdvance = GlyphWidth + 1;  // one column of spacing

// Width in pixels of `text` drawn at integer `scale`.
int textWidth(std::string_view text, int scale = 1);

// Draws `text` with its top-left corner at (x, y), each font pixel a scale x scale block of
// `colour`; whatever falls outside the image is clipped.
void drawText(Image& image, int x, int y, std::string_view text, const Rgb& colour, int scale = 1);

// Whether the font has a glyph of its own for c (lower case counts, as its capital).
bool hasGlyph(char c);

}  // namespace scatterlab
