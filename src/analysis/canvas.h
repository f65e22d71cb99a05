// An RGBA8 pixel canvas with the few drawing operations a plot needs: filled rectangles, lines,
// discs, rings and text in the built-in 5x7 font. Drawing outside the canvas is clipped.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace ontile {

struct Rgba8 {
  uint8_t r = 0, g = 0, b = 0, a = 255;
};

class Canvas {
 public:
  // Throws ontile::Error for sizes outside 1..16384.
  Canvas(int width_px, int height_px, Rgba8 background);
  int width() const { return width_; }
  int height() const { return height_; }
  const std::vector<uint8_t>& rgba() const { return rgba_; }  // row-major, top row first
  Rgba8 at(int x, int y) const;

  void set(int x, int y, Rgba8 color);
  void fill_rect(int x0, int y0, int x1, int y1, Rgba8 color);  // inclusive corners
  void line(int x0, int y0, int x1, int y1, Rgba8 color, int thickness_px = 1);
  void disc(int cx, int cy, int radius_px, Rgba8 color);
  void ring(int cx, int cy, int radius_px, int thickness_px, Rgba8 color);
  // Text with its top-left corner at (x, y), each font pixel scale x scale canvas pixels;
  // vertical text runs upwards (rotated 90 degrees counter-clockwise) from (x, y) as its
  // bottom-left corner.
  void text(int x, int y, const std::string& text, Rgba8 color, int scale = 1);
  void text_vertical(int x, int y, const std::string& text, Rgba8 color, int scale = 1);
  static int text_width_px(const std::string& text, int scale = 1);

 private:
  int width_, height_;
  std::vector<uint8_t> rgba_;
};

}  // namespace ontile
