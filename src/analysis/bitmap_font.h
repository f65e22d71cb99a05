// A tiny built-in 5x7 bitmap font (digits, capital letters, common punctuation) for labelling
// plots without a font dependency. Lower-case letters are drawn as capitals.
#pragma once
#include <array>
#include <cstdint>

namespace ontile {

constexpr int kGlyphWidthPx = 5, kGlyphHeightPx = 7;
constexpr int kGlyphAdvancePx = 6;  // one blank column between characters

// Seven rows, top first; bit 4 of each row is the leftmost pixel. Characters the font lacks
// give the '?' glyph.
const std::array<uint8_t, kGlyphHeightPx>& glyph_rows(char c);

}  // namespace ontile
