// What the tiler executes: one render pass with its attachments (load/store actions, bound
// surface or transient), its subpasses, and the draw calls recorded into each subpass.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "raster/blend.h"
#include "raster/pixel_format.h"
#include "raster/raster_types.h"
#include "raster/shader_interface.h"
#include "tiler/surface.h"

namespace ontile {

// Vulkan VkAttachmentLoadOp / VkAttachmentStoreOp semantics.
enum class LoadAction { Load, Clear, DontCare };
enum class StoreAction { Store, DontCare, Resolve, StoreAndResolve };

struct AttachmentDesc {
  std::string name;
  PixelFormat format = PixelFormat::RGBA8_UNORM;
  LoadAction load = LoadAction::Clear;
  StoreAction store = StoreAction::Store;
  glm::vec4 clear_value{0.0f};          // depth attachments use clear_value.x
  Surface* surface = nullptr;           // null: transient, never backed by external memory
  Surface* resolve_surface = nullptr;   // single-sample target of Resolve/StoreAndResolve
};

// A triangle-list draw. The vertex shader knows the vertex data; the tiler only needs counts.
struct DrawCall {
  const VertexShader* vertex_shader = nullptr;
  const FragmentShader* fragment_shader = nullptr;  // null: depth-only draw
  uint32_t vertex_count = 0;
  const uint32_t* indices = nullptr;  // index_count / 3 triangles
  uint32_t index_count = 0;
  RasterState raster;
  BlendState blend;
  uint32_t primitive_id_base = 0;     // primitive_id = base + triangle index within the draw
  uint32_t input_vertex_bytes = 0;    // bytes fetched per unique vertex (geometry traffic)
  uint32_t index_bytes = 4;           // bytes per index fetched
};

struct SubpassDesc {
  std::vector<int> color_outputs;  // attachment indices; fragment output k writes color_outputs[k]
  std::vector<int> inputs;         // attachment indices readable by framebuffer fetch
  bool depth_read_only = false;
  std::vector<DrawCall> draws;
};

struct RenderPassDesc {
  std::string name;
  int width_px = 0, height_px = 0;
  int samples = 1;
  std::vector<AttachmentDesc> attachments;
  int depth_index = -1;  // attachment index of the depth buffer, -1 = none
  std::vector<SubpassDesc> subpasses;
  // For inspection tools only (the HTML report): empty, or one entry per attachment; a non-null
  // surface (the pass's size and samples, the attachment's format) receives what the tiles held
  // at the end of the pass, transient attachments included. Not external memory: no traffic is
  // counted and nothing else changes.
  std::vector<Surface*> capture_surfaces;
};

}  // namespace ontile
