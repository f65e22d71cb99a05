// Hash-based procedural textures for the generated scenes (see procedural_textures.h).
#include "scene/gen/procedural_textures.h"

#include <algorithm>
#include <cmath>
#include <functional>

#include "util/error.h"

namespace ontile::gen {
namespace {

constexpr double kPi = 3.14159265358979323846;

uint32_t fmix32(uint32_t h) {
  h ^= h >> 16;
  h *= 0x85EBCA6Bu;
  h ^= h >> 13;
  h *= 0xC2B2AE35u;
  h ^= h >> 16;
  return h;
}

uint8_t to_byte(float value) {
  return static_cast<uint8_t>(std::lround(std::clamp(value, 0.0f, 1.0f) * 255.0f));
}

// Evaluates texel(x, y) -> sRGB colour for every texel of a size_px x size_px image.
RgbImage render_texture(int size_px, const std::function<glm::vec3(int x, int y)>& texel) {
  if (size_px < 8 || size_px > 4096) {
    throw Error("scene generator: texture size " + std::to_string(size_px) +
                " px outside 8..4096");
  }
  RgbImage image;
  image.width_px = size_px;
  image.height_px = size_px;
  image.rgb.resize(static_cast<size_t>(size_px) * size_px * 3);
  size_t offset = 0;
  for (int y = 0; y < size_px; ++y) {
    for (int x = 0; x < size_px; ++x) {
      const glm::vec3 c = texel(x, y);
      image.rgb[offset++] = to_byte(c.x);
      image.rgb[offset++] = to_byte(c.y);
      image.rgb[offset++] = to_byte(c.z);
    }
  }
  return image;
}

// Texel centre in noise-lattice units when period_cells cells span the whole texture.
float lattice(int texel, int size_px, int period_cells) {
  return (static_cast<float>(texel) + 0.5f) * static_cast<float>(period_cells) /
         static_cast<float>(size_px);
}

int wrap(int value, int period) { return ((value % period) + period) % period; }

}  // namespace

uint32_t hash_lattice(uint32_t x, uint32_t y, uint32_t seed) {
  uint32_t h = fmix32(seed ^ 0x9E3779B9u);
  h = fmix32(h ^ x);
  return fmix32(h ^ (y * 0x27D4EB2Fu));
}

float hash_unit(uint32_t x, uint32_t y, uint32_t seed) {
  return static_cast<float>(hash_lattice(x, y, seed) >> 8) * (1.0f / 16777216.0f);
}

float periodic_value_noise(float x, float y, int period_cells, uint32_t seed) {
  const float fx = std::floor(x), fy = std::floor(y);
  const int ix = static_cast<int>(fx), iy = static_cast<int>(fy);
  const float tx = x - fx, ty = y - fy;
  const float sx = tx * tx * (3.0f - 2.0f * tx), sy = ty * ty * (3.0f - 2.0f * ty);
  const auto corner = [&](int dx, int dy) {
    return hash_unit(static_cast<uint32_t>(wrap(ix + dx, period_cells)),
                     static_cast<uint32_t>(wrap(iy + dy, period_cells)), seed);
  };
  const float bottom = corner(0, 0) + (corner(1, 0) - corner(0, 0)) * sx;
  const float top = corner(0, 1) + (corner(1, 1) - corner(0, 1)) * sx;
  return bottom + (top - bottom) * sy;
}

float periodic_fbm(float x, float y, int period_cells, int octaves, uint32_t seed) {
  float sum = 0.0f, amplitude = 1.0f, total = 0.0f, scale = 1.0f;
  for (int octave = 0; octave < octaves; ++octave) {
    sum += amplitude * periodic_value_noise(x * scale, y * scale, period_cells << octave,
                                            seed + static_cast<uint32_t>(octave) * 101u);
    total += amplitude;
    amplitude *= 0.5f;
    scale *= 2.0f;
  }
  return sum / total;
}

RgbImage make_checker_texture(int size_px, int checks_per_side, const glm::vec3& colour_a,
                              const glm::vec3& colour_b) {
  return render_texture(size_px, [&](int x, int y) {
    const int cx = x * checks_per_side / size_px, cy = y * checks_per_side / size_px;
    return ((cx + cy) % 2 == 0) ? colour_a : colour_b;
  });
}

RgbImage make_brick_texture(int size_px, uint32_t seed) {
  constexpr int kCourses = 16, kBricksPerCourse = 8;
  const int brick_h = size_px / kCourses, brick_w = size_px / kBricksPerCourse;
  const int mortar_px = std::max(1, size_px / 170);
  return render_texture(size_px, [&](int x, int y) {
    const int course = y / brick_h;
    const int shifted_x = (x + (course % 2) * brick_w / 2) % size_px;  // running bond
    const int brick = shifted_x / brick_w;
    const int local_x = shifted_x % brick_w, local_y = y % brick_h;
    const float grain = periodic_fbm(lattice(x, size_px, 32), lattice(y, size_px, 32), 32, 4, seed);
    if (local_x < mortar_px || local_y < mortar_px) {
      return glm::vec3(0.70f, 0.66f, 0.59f) * (0.85f + 0.2f * grain);
    }
    const float tone = hash_unit(static_cast<uint32_t>(brick), static_cast<uint32_t>(course), seed);
    const float hue = hash_unit(static_cast<uint32_t>(brick), static_cast<uint32_t>(course), seed + 7);
    const glm::vec3 base = glm::mix(glm::vec3(0.60f, 0.29f, 0.19f), glm::vec3(0.52f, 0.34f, 0.24f), hue);
    // Edges of each brick a little darker (worn arrises).
    const int edge_px = std::min({local_x - mortar_px, brick_w - 1 - local_x, local_y - mortar_px,
                                  brick_h - 1 - local_y});
    const float edge = edge_px < 2 ? 0.88f : 1.0f;
    const float speckle = hash_unit(static_cast<uint32_t>(x), static_cast<uint32_t>(y), seed + 3);
    return base * (0.78f + 0.32f * tone) * (0.85f + 0.3f * grain) * edge *
           (0.95f + 0.1f * speckle);
  });
}

RgbImage make_floor_tile_texture(int size_px, uint32_t seed) {
  constexpr int kTiles = 4;
  const int tile_px = size_px / kTiles;
  const int grout_px = std::max(1, size_px / 170);
  return render_texture(size_px, [&](int x, int y) {
    const int tx = x / tile_px, ty = y / tile_px;
    const int local_x = x % tile_px, local_y = y % tile_px;
    const float mottling =
        periodic_fbm(lattice(x, size_px, 16), lattice(y, size_px, 16), 16, 5, seed);
    if (local_x < grout_px || local_y < grout_px) {
      return glm::vec3(0.42f, 0.40f, 0.36f) * (0.9f + 0.2f * mottling);
    }
    const bool light = (tx + ty) % 2 == 0;
    const glm::vec3 base = light ? glm::vec3(0.82f, 0.77f, 0.66f) : glm::vec3(0.58f, 0.50f, 0.42f);
    const float tone = hash_unit(static_cast<uint32_t>(tx), static_cast<uint32_t>(ty), seed + 5);
    const float phase = static_cast<float>(2.0 * kPi * 2.0 * (x + 2 * y) / size_px);
    const float vein = std::pow(1.0f - std::abs(std::sin(phase + 5.0f * mottling)), 12.0f);
    return base * (0.9f + 0.12f * tone) * (0.82f + 0.3f * mottling) * (1.0f - 0.25f * vein);
  });
}

RgbImage make_ashlar_texture(int size_px, uint32_t seed) {
  constexpr int kCourses = 8, kBlocksPerCourse = 4;
  const int block_h = size_px / kCourses, block_w = size_px / kBlocksPerCourse;
  const int joint_px = std::max(1, size_px / 256);
  return render_texture(size_px, [&](int x, int y) {
    const int course = y / block_h;
    const int shifted_x = (x + (course % 2) * block_w / 2) % size_px;
    const int block = shifted_x / block_w;
    const int local_x = shifted_x % block_w, local_y = y % block_h;
    const float grain = periodic_fbm(lattice(x, size_px, 16), lattice(y, size_px, 16), 16, 5, seed);
    if (local_x < joint_px || local_y < joint_px) {
      return glm::vec3(0.55f, 0.50f, 0.42f) * (0.9f + 0.15f * grain);
    }
    const float tone = hash_unit(static_cast<uint32_t>(block), static_cast<uint32_t>(course), seed);
    // Bedding strata: an integer number of periods per texture keeps it tileable.
    const float strata = static_cast<float>(std::sin(2.0 * kPi * 20.0 * y / size_px + 6.0 * grain));
    const float speckle = hash_unit(static_cast<uint32_t>(x), static_cast<uint32_t>(y), seed + 9);
    return glm::vec3(0.80f, 0.72f, 0.58f) * (0.88f + 0.14f * tone) * (0.86f + 0.24f * grain) *
           (1.0f + 0.03f * strata) * (0.96f + 0.08f * speckle);
  });
}

RgbImage make_marble_texture(int size_px, uint32_t seed) {
  return render_texture(size_px, [&](int x, int y) {
    const float turbulence =
        periodic_fbm(lattice(x, size_px, 8), lattice(y, size_px, 8), 8, 6, seed);
    // An integer number of vein periods across the texture keeps it tileable.
    const float phase = static_cast<float>(2.0 * kPi * 3.0 * (x + y) / size_px);
    const float vein = std::pow(1.0f - std::abs(std::sin(phase + 7.0f * turbulence)), 10.0f);
    const float grain = hash_unit(static_cast<uint32_t>(x), static_cast<uint32_t>(y), seed + 11);
    const glm::vec3 stone(0.92f, 0.90f, 0.85f), vein_colour(0.50f, 0.50f, 0.54f);
    return glm::mix(stone * (0.93f + 0.07f * turbulence), vein_colour, 0.7f * vein) *
           (0.98f + 0.04f * grain);
  });
}

RgbImage make_fabric_texture(int size_px, const std::vector<glm::vec3>& stripe_colours,
                             uint32_t seed) {
  if (stripe_colours.empty()) throw Error("scene generator: fabric texture needs a colour");
  // Stripe layout per half texture, in 1/32 of the half width: ground, accent, ground, accent.
  const int half_px = size_px / 2;
  return render_texture(size_px, [&](int x, int y) {
    const int slot = (x % half_px) * 32 / half_px;
    size_t colour_index = 0;
    if (slot >= 20 && slot < 22) colour_index = 1;
    if (slot >= 24 && slot < 29) colour_index = 2;
    if (slot >= 31) colour_index = 1;
    const glm::vec3 colour = stripe_colours[std::min(colour_index, stripe_colours.size() - 1)];
    // 2/2 twill: diagonal ribs from alternating warp and weft floats.
    const float twill = ((x / 2 + y / 2) % 2 == 0) ? 1.0f : 0.9f;
    const float thread = hash_unit(static_cast<uint32_t>(x), static_cast<uint32_t>(y), seed);
    const float dirt = periodic_fbm(lattice(x, size_px, 4), lattice(y, size_px, 4), 4, 4, seed + 1);
    return colour * twill * (0.96f + 0.06f * thread) * (0.88f + 0.16f * dirt);
  });
}

RgbImage make_terracotta_texture(int size_px, uint32_t seed) {
  return render_texture(size_px, [&](int x, int y) {
    const float mottling =
        periodic_fbm(lattice(x, size_px, 8), lattice(y, size_px, 8), 8, 5, seed);
    const float rings = static_cast<float>(std::sin(2.0 * kPi * 24.0 * y / size_px));
    const float speckle = hash_unit(static_cast<uint32_t>(x), static_cast<uint32_t>(y), seed + 2);
    const glm::vec3 clay(0.74f, 0.40f, 0.24f);
    return clay * (0.8f + 0.3f * mottling) * (1.0f + 0.04f * rings) *
           (speckle > 0.97f ? 0.75f : 1.0f);
  });
}

}  // namespace ontile::gen
