// Test harness: draws clip-space triangles through the real context and tiler with culling off
// and additive blending into an RGBA32F target, counting front-facing coverage in R and
// back-facing coverage in G, so closed meshes can be checked pixel by pixel.
#pragma once
#include <vector>

#include <glm/glm.hpp>

#include "support/raster_harness.h"

namespace ontile::test {

// R += 1 for a front-facing triangle, G += 1 for a back-facing one.
class FaceCountShader final : public FragmentShader {
 public:
  void shade(const QuadFragment& q, QuadOutput& out) const override {
    const glm::vec4 value = q.front_facing ? glm::vec4(1, 0, 0, 0) : glm::vec4(0, 1, 0, 0);
    for (int lane = 0; lane < kQuadLanes; ++lane) out.color[0][lane] = value;
  }
};

struct FaceCounts {
  int width = 0, height = 0;
  std::vector<float> front, back;  // per pixel
  FrameReport report;
  size_t index(int x, int y) const { return static_cast<size_t>(y) * width + x; }
};

inline FaceCounts draw_face_counts(const std::vector<glm::vec4>& positions,
                                   const std::vector<uint32_t>& indices, int width, int height,
                                   int threads = 2) {
  ContextConfig cfg;
  cfg.threads = threads;
  RenderContext ctx(cfg);
  Surface* target = ctx.create_surface("faces", PixelFormat::RGBA32_FLOAT, width, height);
  ClipSpaceVertexShader vs(positions, {}, 0);
  FaceCountShader fs;
  record_additive_pass(ctx, "faces", width, height, 1,
                       {"faces", PixelFormat::RGBA32_FLOAT, LoadAction::Clear, StoreAction::Store,
                        glm::vec4(0.0f), target, nullptr},
                       vs, fs, indices);
  FaceCounts r;
  r.report = ctx.submit();
  r.width = width;
  r.height = height;
  r.front.resize(static_cast<size_t>(width) * height);
  r.back.resize(r.front.size());
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const glm::vec4 v = target->read(x, y);
      r.front[r.index(x, y)] = v.x;
      r.back[r.index(x, y)] = v.y;
    }
  }
  return r;
}

}  // namespace ontile::test
