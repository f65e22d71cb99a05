// The write-back of whole shaded quads on SIMD lanes: a batch's structure-of-arrays outputs
// interleaved into a tile plane of RGBA values, two pixels of a quad row per store, or its
// packed 8-bit codes into a code plane (tile_memory.h); the inverse reads (framebuffer fetch of
// a batch); and the fills of cleared tile planes.
#pragma once
#include <cstddef>
#include <cstdint>

#include <glm/glm.hpp>

namespace ontile {

// For each quad i < quad_count: fragments first_fragment[i] .. first_fragment[i] + 3 (quad
// lanes (0,0), (1,0), (0,1), (1,1)) go to plane pixels pixel[i], pixel[i] + 1,
// pixel[i] + row_pixels and pixel[i] + row_pixels + 1; channels[c][f] is channel c of fragment
// f. A copy: the plane receives exactly the output values.
void store_full_quads(const float* const channels[4], const int32_t* first_fragment,
                      const uint32_t* pixel, int quad_count, int row_pixels, glm::vec4* plane);

// store_full_quads for quads whose lanes are not all written: pixel `lane` of quad i is stored
// only where bit lane of lanes[i] is set.
void store_quads(const float* const channels[4], const int32_t* first_fragment, const uint32_t* pixel,
                 const uint8_t* lanes, int quad_count, int row_pixels, glm::vec4* plane);

// The inverse: channels[c][4 i + lane] = channel c of plane pixel pixel[i] (+ 1, + row_pixels,
// + row_pixels + 1 for lanes 1, 2, 3), for quads i < quad_count.
void load_full_quads(const glm::vec4* plane, const uint32_t* pixel, int quad_count, int row_pixels,
                     float* const channels[4]);

// The same on code planes (tile_memory.h: 8-bit RGBA pixels as their four bytes): codes[f] is
// fragment f's packed code. Copies of whole quad rows (two adjacent pixels) for full quads.
void store_full_quad_codes(const uint32_t* codes, const int32_t* first_fragment,
                           const uint32_t* pixel, int quad_count, int row_pixels, uint32_t* plane);
// store_full_quad_codes of a whole-tile batch's row segments: segment s is quads[s] quads side
// by side from plane pixel top[s] on, fragments 4 first[s] on in order.
void store_quad_rows_codes(const uint32_t* codes, const int32_t* first, const int32_t* quads,
                           const uint32_t* top, int segments, int row_pixels, uint32_t* plane);
// store_full_quad_codes of the lanes set in lanes[i] only (the others keep their codes); the
// quads in order, so a later quad's pixels overwrite an earlier one's.
void store_quad_codes(const uint32_t* codes, const int32_t* first_fragment, const uint32_t* pixel,
                      const uint8_t* lanes, int quad_count, int row_pixels, uint32_t* plane);
// load_full_quads of a code plane, decoded as decode_pixel does (sRGB or UNORM colour, UNORM
// alpha: table reads, so every target gives the same bits).
void load_full_quad_codes(const uint32_t* plane, const uint32_t* pixel, int quad_count,
                          int row_pixels, bool srgb, float* const channels[4]);

// Clears as fills: plane[0 .. count) = value, and depth[0 .. count) = value.
void fill_plane(glm::vec4* plane, size_t count, glm::vec4 value);
void fill_depth(float* depth, size_t count, float value);
void fill_codes(uint32_t* plane, size_t count, uint32_t code);

}  // namespace ontile
