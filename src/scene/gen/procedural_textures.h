// Deterministic procedural textures for the generated scenes (checker, bricks, floor tiles,
// marble, striped fabric, terracotta), all seamlessly tileable. Randomness comes only from an
// integer hash, never std::rand or <random> distributions (their output differs between
// standard-library versions).
#pragma once
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace ontile::gen {

// 8-bit RGB texels, row-major, top row first; colours are sRGB-encoded.
struct RgbImage {
  int width_px = 0;
  int height_px = 0;
  std::vector<uint8_t> rgb;
};

// Integer hash of a lattice point (murmur3 finaliser chain).
uint32_t hash_lattice(uint32_t x, uint32_t y, uint32_t seed);
// hash_lattice mapped to [0, 1).
float hash_unit(uint32_t x, uint32_t y, uint32_t seed);
// Smooth value noise in [0, 1] on a lattice that repeats every period_cells cells in x and y.
float periodic_value_noise(float x, float y, int period_cells, uint32_t seed);
// Sum of octaves of periodic_value_noise (each octave doubles frequency and period), in [0, 1].
float periodic_fbm(float x, float y, int period_cells, int octaves, uint32_t seed);

// colour_a / colour_b squares, checks_per_side of them along each edge.
RgbImage make_checker_texture(int size_px, int checks_per_side, const glm::vec3& colour_a,
                              const glm::vec3& colour_b);
// Running-bond red bricks (16 courses x 8 bricks) with mortar joints.
RgbImage make_brick_texture(int size_px, uint32_t seed);
// 4 x 4 stone floor tiles in two alternating tones with grout lines.
RgbImage make_floor_tile_texture(int size_px, uint32_t seed);
// Sandstone ashlar: 8 courses of 4 blocks with thin joints, bedding strata and grain.
RgbImage make_ashlar_texture(int size_px, uint32_t seed);
// White marble with grey veins.
RgbImage make_marble_texture(int size_px, uint32_t seed);
// Woven cloth with vertical stripes: stripe_colours[0] is the ground colour, the others accents.
RgbImage make_fabric_texture(int size_px, const std::vector<glm::vec3>& stripe_colours,
                             uint32_t seed);
// Mottled fired clay with faint horizontal throwing rings, for vases.
RgbImage make_terracotta_texture(int size_px, uint32_t seed);

}  // namespace ontile::gen
