// What draw_renderers draws and in which order: the LightMode tags of the passes to use, the
// sort (Unity's SortingCriteria), and the filter (render-queue range and layer masks).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace ontile {

enum class SortingCriteria {
  None,               // renderer order
  CommonOpaque,       // render queue, then quantised front to back, then material (batching)
  CommonTransparent,  // render queue, then back to front
};

// Data the context hands each draw beyond its transforms (Unity's PerObjectData).
enum PerObjectData : uint32_t { kPerObjectNone = 0, kPerObjectLightData = 1 };

struct DrawingSettings {
  std::vector<std::string> light_modes;  // each renderer draws every matching pass, in this order
  SortingCriteria sorting = SortingCriteria::CommonOpaque;
  uint32_t per_object_data = kPerObjectNone;
};

struct RenderQueueRange {
  int lower = 0, upper = 5000;  // inclusive
  static RenderQueueRange opaque() { return {0, 2500}; }        // as Unity's RenderQueueRange
  static RenderQueueRange transparent() { return {2501, 5000}; }
  static RenderQueueRange all() { return {0, 5000}; }
};

struct FilteringSettings {
  RenderQueueRange render_queue_range = RenderQueueRange::all();
  uint32_t layer_mask = ~0u;
  uint32_t rendering_layer_mask = ~0u;
};

}  // namespace ontile
