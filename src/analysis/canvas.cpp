// Canvas drawing (see canvas.h): integer-only rasterisation, so plots are bit-identical.
#include "analysis/canvas.h"

#include <algorithm>
#include <cstdlib>

#include "analysis/bitmap_font.h"
#include "util/error.h"

namespace ontile {

Canvas::Canvas(int width_px, int height_px, Rgba8 background) : width_(width_px), height_(height_px) {
  if (width_px < 1 || height_px < 1 || width_px > 16384 || height_px > 16384) {
    throw Error("canvas size " + std::to_string(width_px) + "x" + std::to_string(height_px) +
                " outside 1..16384");
  }
  rgba_.resize(static_cast<size_t>(width_) * height_ * 4);
  for (size_t i = 0; i < rgba_.size(); i += 4) {
    rgba_[i] = background.r;
    rgba_[i + 1] = background.g;
    rgba_[i + 2] = background.b;
    rgba_[i + 3] = background.a;
  }
}

Rgba8 Canvas::at(int x, int y) const {
  const size_t i = (static_cast<size_t>(y) * width_ + x) * 4;
  return {rgba_[i], rgba_[i + 1], rgba_[i + 2], rgba_[i + 3]};
}

void Canvas::set(int x, int y, Rgba8 c) {
  if (x < 0 || y < 0 || x >= width_ || y >= height_) return;
  const size_t i = (static_cast<size_t>(y) * width_ + x) * 4;
  rgba_[i] = c.r;
  rgba_[i + 1] = c.g;
  rgba_[i + 2] = c.b;
  rgba_[i + 3] = c.a;
}

void Canvas::fill_rect(int x0, int y0, int x1, int y1, Rgba8 c) {
  for (int y = std::max(0, std::min(y0, y1)); y <= std::min(height_ - 1, std::max(y0, y1)); ++y) {
    for (int x = std::max(0, std::min(x0, x1)); x <= std::min(width_ - 1, std::max(x0, x1)); ++x) set(x, y, c);
  }
}

void Canvas::line(int x0, int y0, int x1, int y1, Rgba8 c, int thickness_px) {
  // Bresenham; a thick line stamps a square at every step.
  const int dx = std::abs(x1 - x0), dy = -std::abs(y1 - y0);
  const int sx = x0 < x1 ? 1 : -1, sy = y0 < y1 ? 1 : -1;
  const int lo = -(thickness_px - 1) / 2, hi = thickness_px / 2;
  int err = dx + dy;
  while (true) {
    fill_rect(x0 + lo, y0 + lo, x0 + hi, y0 + hi, c);
    if (x0 == x1 && y0 == y1) break;
    const int e2 = 2 * err;
    if (e2 >= dy) { err += dy; x0 += sx; }
    if (e2 <= dx) { err += dx; y0 += sy; }
  }
}

void Canvas::disc(int cx, int cy, int r, Rgba8 c) {
  for (int y = -r; y <= r; ++y) {
    for (int x = -r; x <= r; ++x) {
      if (x * x + y * y <= r * r + r) set(cx + x, cy + y, c);
    }
  }
}

void Canvas::ring(int cx, int cy, int r, int thickness_px, Rgba8 c) {
  const int inner = std::max(0, r - thickness_px);
  for (int y = -r; y <= r; ++y) {
    for (int x = -r; x <= r; ++x) {
      const int d2 = x * x + y * y;
      if (d2 <= r * r + r && d2 > inner * inner + inner) set(cx + x, cy + y, c);
    }
  }
}

int Canvas::text_width_px(const std::string& text, int scale) {
  return text.empty() ? 0 : (static_cast<int>(text.size()) * kGlyphAdvancePx - 1) * scale;
}

void Canvas::text(int x, int y, const std::string& text, Rgba8 c, int scale) {
  for (size_t k = 0; k < text.size(); ++k) {
    const auto& rows = glyph_rows(text[k]);
    const int gx = x + static_cast<int>(k) * kGlyphAdvancePx * scale;
    for (int row = 0; row < kGlyphHeightPx; ++row) {
      for (int col = 0; col < kGlyphWidthPx; ++col) {
        if ((rows[row] >> (kGlyphWidthPx - 1 - col)) & 1u) {
          fill_rect(gx + col * scale, y + row * scale, gx + col * scale + scale - 1, y + row * scale + scale - 1, c);
        }
      }
    }
  }
}

void Canvas::text_vertical(int x, int y, const std::string& text, Rgba8 c, int scale) {
  // Font column col of character k lands on canvas row y - (k * advance + col) * scale; font
  // row `row` on canvas column x + row * scale (top of the glyph to the left).
  for (size_t k = 0; k < text.size(); ++k) {
    const auto& rows = glyph_rows(text[k]);
    const int gy = y - static_cast<int>(k) * kGlyphAdvancePx * scale;
    for (int row = 0; row < kGlyphHeightPx; ++row) {
      for (int col = 0; col < kGlyphWidthPx; ++col) {
        if ((rows[row] >> (kGlyphWidthPx - 1 - col)) & 1u) {
          const int px = x + row * scale, py = gy - col * scale;
          fill_rect(px, py - scale + 1, px + scale - 1, py, c);
        }
      }
    }
  }
}

}  // namespace ontile
