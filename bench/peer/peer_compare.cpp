// Output comparisons for the peer benchmark (see peer_compare.h).
#include "peer_compare.h"

#include <algorithm>
#include <cstdlib>
#include <vector>

#include "io/image_io.h"
#include "util/error.h"

namespace ontile::peer {
namespace {

void check_size(const std::filesystem::path& file, int w, int h, const Surface& s) {
  if (w != s.width() || h != s.height()) {
    throw Error(file.string() + ": " + std::to_string(w) + "x" + std::to_string(h) + ", expected " +
                std::to_string(s.width()) + "x" + std::to_string(s.height()));
  }
}

}  // namespace

IdAgreement compare_primitive_ids(const Surface& ontile_ids, const std::filesystem::path& llvmpipe_exr) {
  const ImageRGBA32F theirs = read_image(llvmpipe_exr);
  check_size(llvmpipe_exr, theirs.width, theirs.height, ontile_ids);
  const int w = theirs.width, h = theirs.height;
  std::vector<float> mine(static_cast<size_t>(w) * h), other(mine.size());
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const size_t i = static_cast<size_t>(y) * w + x;
      mine[i] = ontile_ids.read(x, y).x;
      other[i] = theirs.pixels[i * 4];
    }
  }
  // True when `id` is in `image` at (x, y) or one of its 8 neighbours.
  auto nearby = [&](const std::vector<float>& image, int x, int y, float id) {
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        const int nx = x + dx, ny = y + dy;
        if (nx >= 0 && ny >= 0 && nx < w && ny < h && image[static_cast<size_t>(ny) * w + nx] == id) return true;
      }
    }
    return false;
  };
  IdAgreement a;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const size_t i = static_cast<size_t>(y) * w + x;
      ++a.pixels;
      if (mine[i] == other[i]) {
        ++a.equal;
        continue;
      }
      ++(mine[i] < 0.0f || other[i] < 0.0f ? a.coverage_differs : a.id_differs);
      if (nearby(other, x, y, mine[i]) && nearby(mine, x, y, other[i])) ++a.boundary_shifts;
    }
  }
  return a;
}

EdgeAgreement compare_edge_masks(const std::vector<uint8_t>& ontile_mask, int width, int height,
                                 const std::filesystem::path& llvmpipe_png) {
  int w = 0, h = 0;
  const std::vector<uint8_t> png = read_png_rgba8(llvmpipe_png, w, h);
  if (w != width || h != height || ontile_mask.size() != static_cast<size_t>(w) * h) {
    throw Error(llvmpipe_png.string() + ": " + std::to_string(w) + "x" + std::to_string(h) + ", expected " +
                std::to_string(width) + "x" + std::to_string(height));
  }
  std::vector<uint8_t> mine(ontile_mask.size()), theirs(ontile_mask.size());
  for (size_t i = 0; i < mine.size(); ++i) {
    mine[i] = ontile_mask[i] != 0;
    theirs[i] = png[i * 4] >= 128;
  }
  auto edge_nearby = [&](const std::vector<uint8_t>& mask, int x, int y) {
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        const int nx = x + dx, ny = y + dy;
        if (nx >= 0 && ny >= 0 && nx < w && ny < h && mask[static_cast<size_t>(ny) * w + nx]) return true;
      }
    }
    return false;
  };
  EdgeAgreement a;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const size_t i = static_cast<size_t>(y) * w + x;
      ++a.pixels;
      a.ontile_edges += mine[i];
      a.llvmpipe_edges += theirs[i];
      if (mine[i] == theirs[i]) {
        ++a.equal;
        continue;
      }
      ++(mine[i] ? a.only_ontile : a.only_llvmpipe);
      if (edge_nearby(mine[i] ? theirs : mine, x, y)) ++a.shifted;
    }
  }
  return a;
}

ColorAgreement compare_colors(const Surface& ontile_color, const std::filesystem::path& llvmpipe_png) {
  if (ontile_color.format() != PixelFormat::RGBA8_SRGB || ontile_color.samples() != 1) {
    throw Error("colour comparison: ontile's target is " + std::string(format_name(ontile_color.format())) +
                ", expected single-sample rgba8_srgb");
  }
  int w = 0, h = 0;
  const std::vector<uint8_t> theirs = read_png_rgba8(llvmpipe_png, w, h);
  check_size(llvmpipe_png, w, h, ontile_color);
  const std::vector<uint8_t>& ours = ontile_color.bytes();
  ColorAgreement a;
  uint64_t abs_sum = 0;
  for (size_t p = 0; p < static_cast<size_t>(w) * h; ++p) {
    int worst = 0;
    for (size_t c = 0; c < 3; ++c) {
      const int d = std::abs(int(ours[p * 4 + c]) - int(theirs[p * 4 + c]));
      abs_sum += static_cast<uint64_t>(d);
      worst = std::max(worst, d);
    }
    ++a.pixels;
    if (worst <= kColorTolerance) ++a.close;
  }
  a.mean_abs_diff = a.pixels ? double(abs_sum) / double(a.pixels * 3) : 0.0;
  return a;
}

}  // namespace ontile::peer
