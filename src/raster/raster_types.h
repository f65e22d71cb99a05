// Fixed-point constants, limits and render state shared by clipping, setup and rasterization.
// Conventions follow D3D11/Vulkan: 16.8 fixed point, pixel centres at +0.5, depth in [0, 1].
#pragma once
#include <cstdint>

namespace ontile {

// 8 subpixel bits (D3D11 functional spec 3.2.4.1: 16.8 fixed point vertex positions). Edge
// functions and sample positions always work in these 1/256 px units; a coarser snapping
// precision (TilerConfig::subpixel_bits) only moves vertices onto a coarser grid of them.
constexpr int kSubpixelBits = 8;
constexpr int64_t kSubpixelScale = int64_t{1} << kSubpixelBits;
// Vulkan requires subPixelPrecisionBits >= 4 (Vulkan 1.3, table "Required Limits").
constexpr int kMinSubpixelBits = 4;
// Snapped positions must lie in [-kGuardBandPx, kGuardBandPx]: then |x| < 2^23 subpixels, edge
// function products stay below 2^49 and fit int64 comfortably. Triangles reaching beyond are
// clipped against these guard-band planes; everything inside is rasterized without clipping.
constexpr int kGuardBandPx = 32768;
// Render targets are at most this big so that the viewport lies well inside the guard band.
constexpr int kMaxTargetSizePx = 16384;

constexpr int kMaxVaryings = 32;      // floats per vertex passed to the fragment shader
constexpr int kMaxColorTargets = 8;   // Vulkan's guaranteed maxColorAttachments
constexpr int kMaxSamples = 8;

enum class CullMode { None, Back, Front };
enum class FrontFace { CounterClockwise, Clockwise };  // as seen in NDC with +Y up (glTF/GL)
enum class CompareOp { Never, Less, LessEqual, Equal, Greater, GreaterEqual, NotEqual, Always };

struct RasterState {
  CullMode cull = CullMode::Back;
  FrontFace front_face = FrontFace::CounterClockwise;
  bool depth_test = true;
  bool depth_write = true;
  CompareOp depth_compare = CompareOp::Less;
};

inline bool depth_compare_passes(CompareOp op, float incoming, float stored) {
  switch (op) {
    case CompareOp::Never: return false;
    case CompareOp::Less: return incoming < stored;
    case CompareOp::LessEqual: return incoming <= stored;
    case CompareOp::Equal: return incoming == stored;
    case CompareOp::Greater: return incoming > stored;
    case CompareOp::GreaterEqual: return incoming >= stored;
    case CompareOp::NotEqual: return incoming != stored;
    case CompareOp::Always: return true;
  }
  return false;
}

}  // namespace ontile
