// How pipelines name render targets: a surface the context owns (persistent) or a temporary
// render target id from CommandBuffer::get_temporary_rt, resolved when the commands execute.
#pragma once
#include <string>

#include <glm/glm.hpp>

#include "raster/pixel_format.h"
#include "tiler/render_pass.h"

namespace ontile {

struct RenderTargetDesc {
  int width_px = 0, height_px = 0;
  PixelFormat format = PixelFormat::RGBA8_UNORM;
  int samples = 1;
  bool operator==(const RenderTargetDesc&) const = default;
};

struct RenderTargetRef {
  Surface* surface = nullptr;  // a persistent target
  int temporary_id = -1;       // or a temporary one
  static RenderTargetRef of(Surface* s) { return {s, -1}; }
  static RenderTargetRef temporary(int id) { return {nullptr, id}; }
  bool valid() const { return surface != nullptr || temporary_id >= 0; }
};

// One colour or depth target of CommandBuffer::set_render_target.
struct TargetBinding {
  RenderTargetRef target;
  LoadAction load = LoadAction::Load;
  StoreAction store = StoreAction::Store;
};

}  // namespace ontile
